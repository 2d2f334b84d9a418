// Input checks the modules share on their own fields: the pockets' codes
// (tool use U, wall finish F, pilot hole H of M4, M2D, CP), each refused in
// the words of pocket_messages.h, the depth T (CP, AREA, SIDE): a length
// within reach and no deeper than the stock, and the checks M4's and M2D's
// open with. Called from the modules' *_check.cpp.
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

// What a pocket's opening checks found: its codes defined, its depth T
// positive and within the stock.
struct PocketOpening {
    bool codes = false;
    bool depth = false;
};
// The checks M4 and M2D open with: the pocket's codes (`codes`, the
// module's own), its numbers finite (`finite`), then the depth T
// (check::checkDepth) and the step-over. Nothing when a number is not
// finite: the pocket's other checks are not run.
template <class Pocket>
std::optional<PocketOpening> openPocketCheck(const Pocket& p, check::Reporter& r,
                                             bool (*codes)(const Pocket&, check::Reporter&),
                                             bool (*finite)(const Pocket&, check::Reporter&))
{
    const bool codesOk = codes(p, r);
    if (!finite(p, r)) return std::nullopt;
    const bool depthOk = check::checkDepth(p.depth, r);
    check::checkStepOver(p.stepOver, r);
    return PocketOpening{codesOk, depthOk};
}

}  // namespace taiwa
