// The messages of the pockets (M4, M2D, CP): their codes (tool use, wall
// finish, pilot hole) and corner radius. Sentences of input processing that
// only these modules say (check/messages.h quotes lengths and tools for them).
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

// A tool-use code U that is not one (2 to 5 are reserved by the spec's
// table, the others do not exist).
std::string toolUseUnknown(int code);
std::string wallFinishUnknown(int code);
std::string pilotHoleUnknown(int code);
std::string radiusNegative(Len r1);
std::string toolUseNotForContours(int code);

}  // namespace taiwa::msg
