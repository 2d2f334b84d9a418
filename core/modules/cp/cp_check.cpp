// Input checks of one CP unit (contour pocket): the named contours (known,
// closed, not crossing themselves, islands inside the outline and apart, no
// sharp inside corner), the codes, the depth, and the room for the tools in
// the contour's narrowest place.
#include "modules/cp/cp.h"

#include "check/messages.h"
#include "model/clipper_scale.h"
#include "model/codes.h"

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;

constexpr double kChord = 1e-3;  // mm

ClipperLib::Path polygon(const Contour& c)
{
    auto p = toClipper(flatten(c, kChord));
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    return p;
}

bool crossesItself(const Contour& c)
{
    const ClipperLib::Path p = polygon(c);
    ClipperLib::Paths simple;
    ClipperLib::SimplifyPolygon(p, simple, ClipperLib::pftNonZero);
    if (simple.size() != 1) return true;
    return std::abs(ClipperLib::Area(simple[0]) - ClipperLib::Area(p)) > 1e-6 * std::abs(ClipperLib::Area(p)) + 100.0;
}

double commonArea(const ClipperLib::Path& a, const ClipperLib::Path& b, ClipperLib::ClipType type)
{
    ClipperLib::Clipper c;
    c.AddPath(a, ClipperLib::ptSubject, true);
    c.AddPath(b, ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    c.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0.0;
    for (const auto& p : out) area += clipperAreaMm2(p);
    return area;
}

// Where a contour, run with the pocket on its left, turns left at a sharp
// corner: the cutter cannot reach into it.
std::optional<Point2> sharpInsideCorner(const Contour& c)
{
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
        const ContourSegment& a = c.segments[i];
        const ContourSegment& b = c.segments[(i + 1) % c.segments.size()];
        const Point2 d0 = a.endDirection(), d1 = b.startDirection();
        if (cross(d0, d1) > 1e-9 || (dot(d0, d1) < 0.0 && std::abs(cross(d0, d1)) <= 1e-9)) return a.end;
    }
    return std::nullopt;
}

bool checkContours(const ContourPocket& p, Reporter& r)
{
    if (p.outline.empty()) {
        r.unit("outline", msg::contourNotNamed("outline"));
        return false;
    }
    if (!p.resolved) return false;  // no figure evaluated (a unit checked on its own)
    bool ok = true;
    for (const auto& name : p.unknown) {
        r.unit(name == p.outline ? "outline" : "islands", msg::contourUnknown(name, p.figureContours));
        ok = false;
    }
    if (!ok || !p.region) return false;
    const Region region = normalised(*p.region);
    std::vector<std::pair<std::string, const Contour*>> all{{p.outline, &region.outer}};
    for (std::size_t i = 0; i < region.islands.size() && i < p.islands.size(); ++i)
        all.push_back({p.islands[i], &region.islands[i]});
    for (std::size_t k = 0; k < all.size(); ++k) {
        const char* field = k == 0 ? "outline" : "islands";
        if (k < p.closedContours.size() && !p.closedContours[k]) {
            r.unit(field, msg::contourOpen(all[k].first, k == 0 ? "outline" : "island"));
            ok = false;
        } else if (crossesItself(*all[k].second)) {
            r.unit(field, msg::contourCrossesItself(all[k].first));
            ok = false;
        }
    }
    if (!ok) return false;
    if (const Stock* st = r.ctx.stock) {
        const Box2 b = bounds(region.outer);
        constexpr double e = 1e-9;
        if (b.min.x < st->x - e || b.min.y < st->y - e || b.max.x > st->x + st->width + e || b.max.y > st->y + st->length + e) {
            r.unit("outline", msg::outsideStock("pocket's outline " + p.outline));
            ok = false;
        }
    }
    const auto outer = polygon(region.outer);
    std::vector<ClipperLib::Path> islands;
    for (std::size_t k = 1; k < all.size(); ++k) {
        islands.push_back(polygon(*all[k].second));
        if (commonArea(islands.back(), outer, ClipperLib::ctDifference) > 1e-6) {
            r.unit("islands", msg::islandOutside(all[k].first, p.outline));
            ok = false;
        }
        for (std::size_t j = 0; j + 1 < islands.size(); ++j)
            if (commonArea(islands[j], islands.back(), ClipperLib::ctIntersection) > 1e-6) {
                r.unit("islands", msg::islandsOverlap(all[j + 1].first, all[k].first));
                ok = false;
            }
    }
    for (std::size_t k = 0; ok && k < all.size(); ++k)
        if (const auto corner = sharpInsideCorner(*all[k].second)) {
            r.unit(k == 0 ? "outline" : "islands", msg::sharpInsideCorner(all[k].first, r.len(corner->x), r.len(corner->y)));
            ok = false;
        }
    return ok;
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
    q.label = twoStage ? "the contour's narrowest reach − α3" : "the contour's narrowest reach";
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
    const bool depth = check::checkLength(p.depth, "depth", "the depth", r) && check::checkDepth(p.depth, r);
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
