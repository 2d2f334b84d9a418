// Input checks of one CP unit (contour pocket): the named contours (known,
// closed, not crossing themselves, islands inside the outline and apart, no
// sharp inside corner), the codes, the depth, and the room for the tools in
// the contour's narrowest place.
#include "model/translate_noop.h"
#include "modules/cp/cp.h"

#include "check/messages.h"
#include "modules/named_region.h"
#include "model/codes.h"

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;

bool checkContours(const ContourPocket& p, Reporter& r)
{
    NamedRegion n;
    n.outline = p.outline;
    n.islands = p.islands;
    n.region = p.region;
    n.unknown = p.unknown;
    n.figureContours = p.figureContours;
    n.closedContours = p.closedContours;
    n.resolved = p.resolved;
    return checkNamedRegion(n, r, TAIWA_TRANSLATE_NOOP("taiwa::msg", "pocket"), true);
}

bool checkCodes(const ContourPocket& p, Reporter& r)
{
    bool ok = true;
    const auto use = toolUseFromCode(p.toolUse);
    if (!use) {
        r.unit("U", p.toolUse >= 2 && p.toolUse <= 5 ? msg::toolUseUndefined(p.toolUse) : msg::toolUseUnknown(p.toolUse));
        ok = false;
    } else if (*use == ToolUse::Cored) {
        r.unit("U", msg::toolUseNotForContours(p.toolUse));
        ok = false;
    }
    if (!wallFinishFromCode(p.wallFinish)) {
        r.unit("F", msg::wallFinishUnknown(p.wallFinish));
        ok = false;
    }
    return ok;
}

void checkRooms(const ContourPocket& p, double reach, Reporter& r)
{
    const TechnologyData& tech = *r.ctx.tech;
    const ToolUse use = *toolUseFromCode(p.toolUse);
    if (hasRoughing(use) || hasFloorFinishing(use)) {
        check::RoomQuery q;
        if (hasRoughing(use)) q.stepKeys.push_back("roughing");
        if (hasFloorFinishing(use)) q.stepKeys.push_back("floor");
        q.label = "the contour's narrowest reach (half its narrowest channel or its smallest inside radius) − α2";
        q.available = reach - tech.alpha2;
        q.cornerRadius = reach;
        check::checkRoom(q, p.tools, r.unitNo, ContourPocket::kName, r.ctx, r.out);
    }
    if (!hasWallFinishing(use)) return;
    const bool twoStage = *wallFinishFromCode(p.wallFinish) == WallFinish::TwoStage;
    check::RoomQuery q;
    q.stepKeys = {"wall"};
    q.label = twoStage ? "the contour's narrowest reach − α3"
                       : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the contour's narrowest reach");
    q.available = reach - (twoStage ? tech.alpha3 : 0.0);
    q.cornerRadius = reach;
    check::checkRoom(q, p.tools, r.unitNo, ContourPocket::kName, r.ctx, r.out);
}

}  // namespace

check::UnitReport checkContourPocket(const ContourPocket& p, int unitNo, const check::Context& ctx)
{
    check::UnitReport report;
    Reporter r{unitNo, ContourPocket::kName, ctx, report.diagnostics};
    check::checkPins(p.tools, unitNo, ContourPocket::kName, ctx, report.diagnostics);
    const bool codes = checkCodes(p, r);
    const bool depth = check::checkLength(p.depth, "depth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"), r) &&
                       check::checkDepth(p.depth, r);
    check::checkStepOver(p.stepOver, r);
    const bool contours = checkContours(p, r);
    report.figureValid = contours;
    if (!codes || !depth || !contours || !ctx.tech) return report;
    const ToolUse use = *toolUseFromCode(p.toolUse);
    if (!check::checkDepthAllowances(p.depth, *ctx.tech, false, hasRoughing(use) || hasFloorFinishing(use), r))
        return report;
    checkRooms(p, p.reach, r);
    return report;
}

}  // namespace taiwa
