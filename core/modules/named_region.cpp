// Resolving and checking the named contours of a contour unit's area
// (modules/named_region.h).
#include "modules/named_region.h"
#include "model/translate_noop.h"

#include "check/messages.h"
#include "figure/figure_text.h"
#include "io/job_messages.h"
#include "model/clipper_scale.h"
#include "modules/length_fields.h"
#include "modules/region_messages.h"
#include "modules/self_crossing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace taiwa {

void NamedRegion::resolve(const ContourTable& table)
{
    resolved = true;
    unknown.clear();
    figureContours.clear();
    closedContours.clear();
    region.reset();
    Region r;
    bool all = true;
    const auto take = [&](const std::string& name, Contour& into) {
        const auto it = table.find(name);
        if (it == table.end()) {
            if (!name.empty()) unknown.push_back(name);
            all = false;
            return;
        }
        into = it->second;
        closedContours.push_back(it->second.closed);
    };
    take(outline, r.outer);
    r.islands.resize(islands.size());
    for (std::size_t i = 0; i < islands.size(); ++i) take(islands[i], r.islands[i]);
    if (all) region = std::move(r);
    // The figure's contours, for the message that a name is none of them;
    // a unit that finds its own keeps no list (thousands of units each held
    // every name: quadratic in time and memory).
    if (!unknown.empty())
        for (const auto& [name, contour] : table) figureContours.push_back(name);
}

namespace {

// The contour names of the job file's array at `key` ("islands"); empty
// when the key is absent.
std::vector<std::string> readContourNames(const io::ObjectFields& f, const char* key)
{
    std::vector<std::string> names;
    const nlohmann::json* list = f.find(key);
    if (!list) return names;
    if (!list->is_array()) {
        f.error(key, msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of contour names"), *list));
        return names;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
        const auto& v = (*list)[i];
        if (v.is_string()) names.push_back(v.get<std::string>());
        else
            f.error(std::string(key) + "[" + std::to_string(i) + "]",
                    msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a contour name"), v));
    }
    return names;
}

}  // namespace

NamedRegion readNamedRegion(const io::ObjectFields& f)
{
    NamedRegion n;
    n.outline = f.string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline")).value_or("");
    n.islands = readContourNames(f, "islands");
    return n;
}

void writeNamedRegion(const NamedRegion& n, nlohmann::ordered_json& u)
{
    u["outline"] = n.outline;
    if (!n.islands.empty()) u["islands"] = n.islands;
}

std::optional<Quad> regionBox(const std::optional<Region>& region)
{
    if (!region || region->outer.empty()) return std::nullopt;
    const Box2 b = bounds(region->outer);
    return Quad{{b.min, Point2{b.max.x, b.min.y}, b.max, Point2{b.min.x, b.max.y}}, 0.0};
}

RegionCavity regionCavity(const Region& region, double depth)
{
    const Region normal = normalised(region);
    RegionCavity out;
    const Box2 box = bounds(normal.outer);
    out.cavity.min = box.min;
    out.cavity.max = box.max;
    out.cavity.depth = depth;
    out.distance = std::make_shared<const RegionDistance>(normal);
    return out;
}

std::vector<Point2> regionPolygon(const std::optional<Region>& region)
{
    constexpr double kPolygonChord = 1e-3;  // mm: the outline flattened for the interference check
    if (!region) return {};
    return flatten(normalised(*region).outer, kPolygonChord);
}

std::string middleRectangleFigure(const Stock& s)
{
    const auto n = [](double v) { return figure::formatNumber(std::round(v * 1000.0) / 1000.0); };
    return "P1 = POINT/" + n(s.x + 0.2 * s.width) + ", " + n(s.y + 0.2 * s.length) + "\n" +
           "P2 = POINT/" + n(s.x + 0.6 * s.width) + ", " + n(s.y + 0.6 * s.length) + "\n" +
           "L1 = LINE/P1, ATANGL, 0\n"
           "L2 = LINE/P2, ATANGL, 90\n"
           "L3 = LINE/P2, ATANGL, 180\n"
           "L4 = LINE/P1, ATANGL, 270\n";
}

void convertRegionLengths(Region& region, const LengthMap& f) { convertEach(f, region); }

namespace {

using check::Reporter;

constexpr double kChord = 1e-3;  // mm

ClipperLib::Path polygon(const Contour& c)
{
    auto p = toClipper(flatten(c, kChord));
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    return p;
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

}  // namespace

bool regionWithinLimits(const Region& region)
{
    std::size_t segments = region.outer.segments.size();
    for (const auto& i : region.islands) segments += i.segments.size();
    return segments <= kMaxRegionSegments && region.islands.size() <= kMaxRegionIslands;
}

bool checkNamedRegion(const NamedRegion& p, check::Reporter& r, const char* what, bool refuseSharpInsideCorners)
{
    if (p.outline.empty()) {
        r.unit(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline"),
               msg::contourNotNamed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline")));
        return false;
    }
    if (!p.resolved) return false;  // no figure evaluated (a unit checked on its own)
    bool ok = true;
    for (const auto& name : p.unknown) {
        r.unit(name == p.outline ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline") : "islands",
               msg::contourUnknown(name, p.figureContours));
        ok = false;
    }
    if (!ok || !p.region) return false;
    if (p.region->islands.size() > kMaxRegionIslands) {
        r.unit("islands", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                           "{} islands; a {} may have at most {} (the checks compare "
                                                           "every two of them)"),
                                      p.region->islands.size(), what, kMaxRegionIslands));
        return false;
    }
    if (!regionWithinLimits(*p.region)) {
        std::size_t segments = p.region->outer.segments.size();
        for (const auto& i : p.region->islands) segments += i.segments.size();
        r.unit(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline"),
               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "the {}'s outline {} and its islands have {} lines and arcs; at most {} "
                                                "are taken (simplify the contours, or join short lines into arcs)"),
                           what, p.outline, segments, kMaxRegionSegments));
        return false;
    }
    const Region region = normalised(*p.region);
    std::vector<std::pair<std::string, const Contour*>> all{{p.outline, &region.outer}};
    for (std::size_t i = 0; i < region.islands.size() && i < p.islands.size(); ++i)
        all.push_back({p.islands[i], &region.islands[i]});
    for (std::size_t k = 0; k < all.size(); ++k) {
        const char* field = k == 0 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline") : "islands";
        if (k < p.closedContours.size() && !p.closedContours[k]) {
            r.unit(field, msg::contourOpen(all[k].first, what,
                                           k == 0 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline")
                                                  : TAIWA_TRANSLATE_NOOP("taiwa::msg", "island")));
            ok = false;
        } else if (polygonCrossesItself(flatten(*all[k].second, kChord))) {
            r.unit(field, msg::contourCrossesItself(all[k].first));
            ok = false;
        }
    }
    if (!ok) return false;
    if (const Stock* st = r.ctx.stock) {
        const Box2 b = bounds(region.outer);
        constexpr double e = 1e-9;
        if (b.min.x < st->x - e || b.min.y < st->y - e || b.max.x > st->x + st->width + e || b.max.y > st->y + st->length + e) {
            r.unit(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline"),
                   msg::outsideStock(std::string(what) + "'s outline " + p.outline));
            ok = false;
        }
    }
    const auto outer = polygon(region.outer);
    std::vector<ClipperLib::Path> islands;
    for (std::size_t k = 1; k < all.size(); ++k) {
        islands.push_back(polygon(*all[k].second));
        if (commonArea(islands.back(), outer, ClipperLib::ctDifference) > 1e-6) {
            r.unit("islands", msg::islandOutside(all[k].first, what, p.outline));
            ok = false;
        }
        for (std::size_t j = 0; j + 1 < islands.size(); ++j)
            if (commonArea(islands[j], islands.back(), ClipperLib::ctIntersection) > 1e-6) {
                r.unit("islands", msg::islandsOverlap(all[j + 1].first, all[k].first));
                ok = false;
            }
    }
    for (std::size_t k = 0; ok && refuseSharpInsideCorners && k < all.size(); ++k)
        if (const auto corner = sharpInsideCorner(*all[k].second)) {
            r.unit(k == 0 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline") : "islands",
                   msg::sharpInsideCorner(all[k].first, r.len(corner->x), r.len(corner->y)));
            ok = false;
        }
    return ok;
}


}  // namespace taiwa
