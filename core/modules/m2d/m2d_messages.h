// The messages of M2D, the pocket with inclined faces: its radius, face
// angles, floor, scallop and tool use: the sentences of input processing
// (check/messages.h quotes lengths and tools for them) that only this module
// says, kept in its folder.
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

std::string scallopTooSmall(Len scallop, Len smallest);
std::string radiusOverHalfL2(Len r1, Len l2);
std::string thetaOutOfRange(const std::string& name, double theta);
std::string floorVanishes(Len floorWidth, Len needed, Len shortBy);
std::string scallopNotPositive(Len scallop);
std::string toolUseNotForM2D(int code);

}  // namespace taiwa::msg
