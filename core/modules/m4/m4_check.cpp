// Input checks of one M4 unit (2.5-D pocket): numbers, codes, the outline's
// geometry, depth against stock and technology data, and tool room.
#include "check/check_unit.h"
#include "check/messages.h"
#include "model/codes.h"
#include "model/translate_noop.h"
#include "modules/m4/m4_kind.h"
#include "modules/m4/m4_messages.h"
#include "modules/pocket_checks.h"
#include "modules/pocket_messages.h"
#include "modules/region_messages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::check {

namespace {

constexpr double kSamePoint = 1e-6;  // mm: closer corners are the same point
constexpr double kTolerance = 1e-9;  // mm



bool allFinite(const M4Pocket& p, Reporter& r)
{
    bool ok = true;
    for (std::size_t i = 0; i < 4; ++i) {
        const std::string field = "corners[" + std::to_string(i) + "]", point = "P" + std::to_string(i + 1);
        ok &= checkLength(p.corners[i].x, field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the coordinate X of {}"), point), r) &&
              checkLength(p.corners[i].y, field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the coordinate Y of {}"), point), r);
    }
    ok &= checkLength(p.cornerRadius, "cornerRadius", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the cornerRadius"), r);
    ok &= checkLength(p.depth, "depth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"), r);
    if (!std::isfinite(p.taper)) {
        r.unit("taper", msg::notFinite(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the taper")));
        ok = false;
    }
    return ok;
}

bool codesDefined(const M4Pocket& p, Reporter& r)
{
    const bool use = checkToolUseCode(p.toolUse, r).has_value();
    const bool finish = checkWallFinishCode(p.wallFinish, r);
    return checkPilotHoleCode(p.pilotHole, r) && use && finish;
}

// Four distinct corners forming a convex outline whose corner radius fits.
bool outlineValid(const M4Pocket& p, Reporter& r)
{
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            if (distance(p.corners[i], p.corners[j]) < kSamePoint) {
                r.unit("corners[" + std::to_string(j) + "]",
                       msg::duplicateCorner(static_cast<int>(i + 1), static_cast<int>(j + 1), r.len(p.corners[j].x),
                                            r.len(p.corners[j].y)));
                return false;
            }
    if (isSelfIntersecting(p.corners)) {
        r.unit("corners", msg::selfIntersecting());
        return false;
    }
    if (!isStrictlyConvex(p.corners)) {
        r.unit("corners", msg::notConvex());
        return false;
    }
    if (p.cornerRadius < 0.0) {
        r.unit("cornerRadius", msg::radiusNegative(r.len(p.cornerRadius)));
        return false;
    }
    const double side = shortestSide(p.corners);
    if (p.cornerRadius > side / 2.0 + kTolerance) {
        r.unit("cornerRadius", msg::radiusOverHalfSide(r.len(p.cornerRadius), r.len(side)));
        return false;
    }
    const double inscribed = inscribedRadius(p.corners);
    if (p.cornerRadius > inscribed + 1e-6) {
        r.unit("cornerRadius", msg::radiusOverInscribed(r.len(p.cornerRadius), r.len(inscribed)));
        return false;
    }
    return true;
}

bool insideStock(const std::array<Point2, 4>& corners, const Stock& s)
{
    for (const auto& c : corners)
        if (c.x < s.x - kTolerance || c.x > s.x + s.width + kTolerance || c.y < s.y - kTolerance ||
            c.y > s.y + s.length + kTolerance)
            return false;
    return true;
}

// Tool room of every step that the codes ask for.
void checkToolRoom(const M4Pocket& p, const TechnologyData& tech, Reporter& r)
{
    const ToolUse use = *toolUseFromCode(p.toolUse);
    const double t = tanDeg(p.taper);
    const double r1 = p.cornerRadius;
    if (hasRoughing(use) || hasFloorFinishing(use)) {
        RoomQuery q;
        if (hasRoughing(use)) q.stepKeys.push_back("roughing");
        if (hasFloorFinishing(use)) q.stepKeys.push_back("floor");
        q.label = p.taper > 0.0 ? "the roughing corner radius (r1 less the taper down to the roughing depth, less α2)"
                                : "r1 − α2";
        q.available = std::max(r1 - (p.depth - tech.beta2) * t, 0.0) - tech.alpha2;
        q.cornerRadius = r1;
        checkRoom(q, p.tools, r.unitNo, "M4", r.ctx, r.out);
    }
    if (!hasWallFinishing(use)) return;
    const bool twoStage = *wallFinishFromCode(p.wallFinish) == WallFinish::TwoStage;
    RoomQuery q;
    q.stepKeys = {"wall"};
    q.cornerRadius = r1;
    if (p.taper > 0.0) {
        q.type = ToolType::TaperEndMill;
        q.taper = p.taper;
        q.label = twoStage ? "the semi-finish corner radius at the floor (r1 − T·tan S − α3)"
                           : "the corner radius at the floor (r1 − T·tan S)";
        q.available = r1 - p.depth * t - (twoStage ? tech.alpha3 : 0.0);
    } else {
        q.label = twoStage ? "r1 − α3" : "r1";
        q.available = r1 - (twoStage ? tech.alpha3 : 0.0);
    }
    checkRoom(q, p.tools, r.unitNo, "M4", r.ctx, r.out);
}

}  // namespace

UnitReport checkM4(const M4Pocket& p, int unitNo, const Context& ctx)
{
    return checkUnit(unitNo, "M4", ctx, [&](Reporter& r, UnitReport& report) {
        const auto opening = openPocketCheck(p, r, codesDefined, allFinite);
        if (!opening) return;

        const bool taperOk = p.taper >= 0.0 && p.taper <= 30.0;
        if (!taperOk) r.unit("taper", msg::taperOutOfRange(p.taper));

        const bool outlineOk = outlineValid(p, r);
        report.figureValid = outlineOk;
        if (outlineOk && ctx.stock && !insideStock(p.corners, *ctx.stock))
            r.unit("corners", msg::outsideStock(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pocket")));

        bool taperFits = true;
        if (outlineOk && opening->depth && taperOk && p.taper > 0.0) {
            const double meet = inscribedRadius(p.corners) / tanDeg(p.taper);
            taperFits = meet > p.depth;
            if (!taperFits) r.unit("taper", msg::taperClosesPocket(p.taper, r.len(meet)));
        }

        if (!ctx.tech || !opening->codes || !opening->depth) return;
        const TechnologyData& tech = *ctx.tech;
        const ToolUse use = *toolUseFromCode(p.toolUse);
        const bool depthsOk = checkDepthAllowances(p.depth, tech, *pilotHoleFromCode(p.pilotHole) == PilotHole::Drill,
                                                   hasRoughing(use) || hasFloorFinishing(use), r);
        // α3 is used only by a two-stage wall finish (F = 3): checked where it is used.
        const bool twoStage = hasWallFinishing(use) && *wallFinishFromCode(p.wallFinish) == WallFinish::TwoStage;
        if (twoStage && tech.alpha3 >= tech.alpha2)
            r.job("technology.alpha3", msg::alpha3NotBelowAlpha2(r.len(tech.alpha3), r.len(tech.alpha2)));
        if (outlineOk && taperOk && taperFits && depthsOk && !(twoStage && tech.alpha3 >= tech.alpha2)) checkToolRoom(p, tech, r);
    });
}

}  // namespace taiwa::check
