// Input checks the modules share on their own fields: the pockets' codes
// (tool use U, wall finish F, pilot hole H of M4, M2D, CP), each refused in
// the words of pocket_messages.h, and the depth T (CP, AREA, SIDE): a length
// within reach and no deeper than the stock. Called from the modules'
// *_check.cpp.
#pragma once

#include "check/unit_checks.h"
#include "model/codes.h"

#include <optional>

namespace taiwa {

// The tool use of code U; an unknown code or a reserved one (2 to 5) is
// refused on "U" and gives nothing.
std::optional<ToolUse> checkToolUseCode(int code, check::Reporter& r);
// The wall finish F and the pilot hole H: false, refused on their field,
// when the code is unknown.
bool checkWallFinishCode(int code, check::Reporter& r);
bool checkPilotHoleCode(int code, check::Reporter& r);
// The depth T on field "depth": a length (check::checkLength) and then
// positive and within the stock (check::checkDepth); false when either is not.
bool checkDepthField(double depth, check::Reporter& r);

}  // namespace taiwa
