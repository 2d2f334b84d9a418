// The messages of AREA, area clearing by drawn passes: its points, passes, end
// mill and the area left unswept: the sentences of input processing
// (check/messages.h quotes lengths and tools for them) that only this module
// says, kept in its folder.
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

std::string pointsUnreadable(const std::string& typed);
std::string tooFewPoints(std::size_t count);
std::string pointOutsideStock(std::size_t index, Len x, Len y);
std::string passSamePoint(int pass);
std::string passLeavesArea(int pass, Len x, Len y, Len by, const std::string& outline);  // pass 0: the start point
std::string diameterNotPositive(Len d);
std::string noToolOfDiameter(Len d, const std::vector<double>& diametersMm, LengthUnit unit);
std::string pinnedDiameterDiffers(const Tool& pinned, Len d);
std::string unswept(double areaMm2, int pieces, double largestMm2, Len x, Len y, LengthUnit unit);

}  // namespace taiwa::msg
