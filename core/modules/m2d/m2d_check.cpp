// Input checks of one M2D unit (geometric 3-D pocket): numbers, codes, the
// opening and its inclined walls, the floor they leave, depth against stock
// and technology data, and tool room.
#include "check/check_unit.h"
#include "check/messages.h"
#include "model/codes.h"
#include "model/translate_noop.h"
#include "modules/m2d/m2d_kind.h"
#include "modules/m2d/m2d_messages.h"
#include "modules/pocket_checks.h"
#include "modules/pocket_messages.h"
#include "modules/region_messages.h"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace taiwa::check {

namespace {

constexpr double kTolerance = 1e-9;  // mm



bool allFinite(const M2DPocket& p, Reporter& r)
{
    bool ok = true;
    auto length = [&](const char* field, double v, const std::string& what) { ok &= checkLength(v, field, what, r); };
    auto angle = [&](const char* field, double v, const std::string& what) {
        if (std::isfinite(v)) return;
        r.unit(field, msg::notFinite(what));
        ok = false;
    };
    length("corner", p.corner.x, "X1 of the reference corner");
    length("corner", p.corner.y, "Y1 of the reference corner");
    length("L1", p.lengthX, "L1");
    length("L2", p.lengthY, "L2");
    length("depth", p.depth, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"));
    angle("theta1", p.theta1, "θ1");
    if (p.theta2) angle("theta2", *p.theta2, "θ2");
    length("cornerRadius", p.cornerRadius, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius"));
    length("scallop", p.scallop, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the scallop height"));
    return ok;
}

bool codesDefined(const M2DPocket& p, Reporter& r)
{
    // U 1 or 9 only: another known tool use is refused as not M2D's.
    const bool use = p.toolUse == 1 || p.toolUse == 9;
    if (!use && checkToolUseCode(p.toolUse, r)) r.unit("U", msg::toolUseNotForM2D(p.toolUse));
    return checkPilotHoleCode(p.pilotHole, r) && use;
}

bool anglesValid(const M2DPocket& p, Reporter& r)
{
    bool ok = true;
    auto angle = [&](const char* field, const char* name, double v) {
        if (v >= 0.0 && v < 60.0) return;
        r.unit(field, msg::thetaOutOfRange(name, v));
        ok = false;
    };
    angle("theta1", "θ1", p.theta1);
    if (p.theta2) angle("theta2", "θ2", *p.theta2);
    return ok;
}

// Opening and floor: lengths positive, r1 fits L2 and the floor the inclined walls leave.
bool figureValid(const M2DPocket& p, bool depthOk, bool anglesOk, Reporter& r)
{
    bool ok = true;
    if (p.lengthX <= 0.0) r.unit("L1", msg::lengthNotPositive("L1", r.len(p.lengthX))), ok = false;
    if (p.lengthY <= 0.0) r.unit("L2", msg::lengthNotPositive("L2", r.len(p.lengthY))), ok = false;
    if (p.cornerRadius < 0.0) r.unit("cornerRadius", msg::radiusNegative(r.len(p.cornerRadius))), ok = false;
    if (!ok) return false;
    if (p.cornerRadius > p.lengthY / 2.0 + kTolerance) {
        r.unit("cornerRadius", msg::radiusOverHalfL2(r.len(p.cornerRadius), r.len(p.lengthY)));
        return false;
    }
    if (!depthOk || !anglesOk) return true;  // the opening alone is still a valid figure
    const double floorWidth = p.lengthX - p.depth * (tanDeg(p.theta1) + tanDeg(p.rightAngle()));
    const double needed = 2.0 * p.cornerRadius;
    if (floorWidth <= needed) {
        const bool blameTheta2 = p.theta2 && *p.theta2 > p.theta1;
        r.unit(blameTheta2 ? "theta2" : "theta1",
               msg::floorVanishes(r.len(floorWidth), r.len(needed), r.len(needed - floorWidth)));
    }
    return true;
}

bool insideStock(const M2DPocket& p, const Stock& s)
{
    return p.corner.x >= s.x - kTolerance && p.corner.y >= s.y - kTolerance &&
           p.corner.x + p.lengthX <= s.x + s.width + kTolerance && p.corner.y + p.lengthY <= s.y + s.length + kTolerance;
}

// Tool room of the steps the codes ask for: roughing (with U 1 the floor
// too) within r1 − α2, and with U 1 the wall within r1.
void checkToolRoom(const M2DPocket& p, const TechnologyData& tech, Reporter& r)
{
    const auto room = [&](std::vector<std::string> stepKeys, const char* label, double available) {
        const RoomQuery q{.stepKeys = std::move(stepKeys), .label = label, .available = available,
                          .cornerRadius = p.cornerRadius};
        checkRoom(q, p.tools, r.unitNo, "M2D", r.ctx, r.out);
    };
    const bool finishes = p.toolUse == 1;
    room(finishes ? std::vector<std::string>{"roughing", "floor"} : std::vector<std::string>{"roughing"}, "r1 − α2",
         p.cornerRadius - tech.alpha2);
    if (finishes) room({"wall"}, "r1", p.cornerRadius);
}

}  // namespace

UnitReport checkM2D(const M2DPocket& p, int unitNo, const Context& ctx)
{
    return checkUnit(unitNo, "M2D", ctx, [&](Reporter& r, UnitReport& report) {
        const auto opening = openPocketCheck(p, r, codesDefined, allFinite);
        if (!opening) return;
        // The smallest scallop height keeps the inclined faces' passes bounded (R / 1 µm at most).
        constexpr double kSmallestScallop = 0.001;  // mm
        if (p.scallop <= 0.0) r.unit("scallop", msg::scallopNotPositive(r.len(p.scallop)));
        else if (p.scallop < kSmallestScallop) r.unit("scallop", msg::scallopTooSmall(r.len(p.scallop), r.len(kSmallestScallop)));

        const bool anglesOk = anglesValid(p, r);
        const std::size_t before = report.diagnostics.size();
        report.figureValid = figureValid(p, opening->depth, anglesOk, r);
        const bool floorOk = report.diagnostics.size() == before;
        if (report.figureValid && ctx.stock && !insideStock(p, *ctx.stock))
            r.unit("corner", msg::outsideStock(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pocket opening")));

        if (!ctx.tech || !opening->codes || !opening->depth) return;
        const TechnologyData& tech = *ctx.tech;
        const bool depthsOk =
            checkDepthAllowances(p.depth, tech, *pilotHoleFromCode(p.pilotHole) == PilotHole::Drill, true, r);
        if (report.figureValid && floorOk && anglesOk && depthsOk) checkToolRoom(p, tech, r);
    });
}

}  // namespace taiwa::check
