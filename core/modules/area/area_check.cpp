// Input checks of one AREA unit (area clearing by drawn passes): the area's
// contours, the drawn points (readable, at least one pass, on the stock, no
// empty pass), every strip inside the area, the depth, the diameter and a
// tool of it; and, as a warning, what the strips leave unswept.
#include "model/translate_noop.h"
#include "modules/area/area.h"

#include "check/check_unit.h"
#include "check/messages.h"
#include "paths/drawn_passes.h"
#include "modules/area/area_messages.h"
#include "modules/pocket_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;

bool checkPoints(const AreaClearing& a, Reporter& r)
{
    if (!a.badPoints.empty()) {
        r.unit("points", msg::pointsUnreadable(a.badPoints));
        return false;
    }
    if (a.points.size() < 2) {
        r.unit("points", msg::tooFewPoints(a.points.size()));
        return false;
    }
    bool ok = true;
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        const Point2 p = a.points[i];
        if (!check::checkLength(p.x, "points", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point's X"), r) ||
            !check::checkLength(p.y, "points", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point's Y"), r))
            return false;
        if (const Stock* st = r.ctx.stock) {
            constexpr double e = 1e-9;
            if (p.x < st->x - e || p.y < st->y - e || p.x > st->x + st->width + e || p.y > st->y + st->length + e) {
                r.unit("points", msg::pointOutsideStock(i + 1, r.len(p.x), r.len(p.y)));
                ok = false;
            }
        }
        if (i > 0 && distance(p, a.points[i - 1]) < 1e-6) {
            r.unit("points", msg::passSamePoint(static_cast<int>(i)));
            ok = false;
        }
    }
    return ok;
}

// The work of the checks on the strips, estimated before it is done (the
// pairs are counted by a sweep that stops at the budget): the excursion
// test takes each pass against each boundary segment, and the unswept area
// is a Clipper union whose crossings come from the pairs of strips whose
// boxes overlap (random passes across the area: about n²/4 of them).
bool checkWork(const AreaClearing& a, Reporter& r)
{
    std::size_t segments = a.area.region->outer.segments.size();
    for (const auto& i : a.area.region->islands) segments += i.segments.size();
    const double passes = static_cast<double>(a.points.size() - 1);
    if (passes * static_cast<double>(segments) > kMaxAreaPassSegments) {
        r.unit("points", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                          "{} passes along an area of {} lines and arcs are more than "
                                                          "the checks take ({:.3g} pass-segment pairs at most); draw "
                                                          "fewer points, or simplify the area's contours"),
                                     a.points.size() - 1, segments, kMaxAreaPassSegments));
        return false;
    }
    if (overlappingStripPairs(a.points, a.diameter / 2, kMaxAreaStripPairs) > kMaxAreaStripPairs) {
        r.unit("points", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                          "the {} passes' strips overlap in more than {} pairs: "
                                                          "what they leave unswept is more than the checks take; "
                                                          "draw fewer passes, or passes that cross each other less"),
                                     a.points.size() - 1, kMaxAreaStripPairs));
        return false;
    }
    return true;
}

bool checkTool(const AreaClearing& a, Reporter& r)
{
    if (!r.ctx.library) return true;
    const auto& library = *r.ctx.library;
    if (const auto pin = a.tools.find("area"); pin != a.tools.end()) {
        const Tool* t = findTool(library, pin->second);
        if (t && !cutsDrawnPasses(*t, a.diameter)) {
            r.unit("tools", msg::pinnedDiameterDiffers(*t, r.len(a.diameter)));
            return false;
        }
        return true;  // an unknown id is check::checkPins's (the door runs it)
    }
    if (std::any_of(library.begin(), library.end(), [&](const Tool& t) { return cutsDrawnPasses(t, a.diameter); })) return true;
    std::vector<double> diameters;
    for (const Tool& t : library)
        if (t.type == ToolType::FlatEndMill && t.centreCutting) diameters.push_back(t.diameter);
    std::sort(diameters.begin(), diameters.end());
    diameters.erase(std::unique(diameters.begin(), diameters.end()), diameters.end());
    r.unit("diameter", msg::noToolOfDiameter(r.len(a.diameter), diameters, r.ctx.shownUnit));
    return false;
}

}  // namespace

std::size_t overlappingStripPairs(const std::vector<Point2>& points, double radius, std::size_t stopAt)
{
    struct Box {
        double x0, x1, y0, y1;
    };
    std::vector<Box> boxes;
    boxes.reserve(points.size());
    for (std::size_t k = 1; k < points.size(); ++k) {
        const Point2 p = points[k - 1], q = points[k];
        boxes.push_back({std::min(p.x, q.x) - radius, std::max(p.x, q.x) + radius, std::min(p.y, q.y) - radius,
                         std::max(p.y, q.y) + radius});
    }
    std::sort(boxes.begin(), boxes.end(), [](const Box& u, const Box& v) { return u.x0 < v.x0; });
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size() && boxes[j].x0 <= boxes[i].x1; ++j) {
            if (boxes[j].y0 > boxes[i].y1 || boxes[j].y1 < boxes[i].y0) continue;
            if (++pairs > stopAt) return pairs;
        }
    return pairs;
}

bool cutsDrawnPasses(const Tool& t, double diameter)
{
    return t.type == ToolType::FlatEndMill && t.centreCutting && std::abs(t.diameter - diameter) <= kFitTolerance;
}

check::UnitReport checkAreaClearing(const AreaClearing& a, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, AreaClearing::kName, ctx, [&](Reporter& r, check::UnitReport& report) {
        checkDepthField(a.depth, r);
        bool diameter =
            check::checkLength(a.diameter, "diameter", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool diameter"), r);
        if (diameter && !(a.diameter > 0.0)) {
            r.unit("diameter", msg::diameterNotPositive(r.len(a.diameter)));
            diameter = false;
        }
        const bool region = checkNamedRegion(a.area, r, "area", false);
        report.figureValid = region;
        const bool points = checkPoints(a, r);
        if (diameter) checkTool(a, r);
        if (!region || !points || !diameter || !checkWork(a, r)) return;
        const double radius = a.diameter / 2;
        if (const auto out = paths::firstExcursion(*a.area.region, a.points, radius)) {
            r.unit("points", msg::passLeavesArea(out->pass, r.len(out->at.x), r.len(out->at.y), r.len(out->by), a.area.outline));
            return;
        }
        const paths::Unswept left = paths::unsweptArea(*a.area.region, a.points, radius);
        if (left.pieces > 0)
            report.diagnostics.push_back({Severity::Warning, unitNo, AreaClearing::kName, "points",
                                          msg::unswept(left.area, left.pieces, left.largest, r.len(left.largestAt.x),
                                                       r.len(left.largestAt.y), ctx.shownUnit)});
    });
}

}  // namespace taiwa
