// The strips of drawn passes against their area (paths/drawn_passes.h):
// Clipper for what is left unswept, exact distances for excursions.
#include "paths/drawn_passes.h"

#include "model/clipper_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::paths {

namespace {

constexpr double kChord = 1e-3;    // mm: the area flattened for Clipper
constexpr double kSliver = 5e-3;   // mm: opened away (half the thinnest piece counted)
constexpr double kTolerance = 1e-3;  // mm: an excursion smaller than this is none

// The point of segment a-b nearest to p.
Point2 foot(Point2 a, Point2 b, Point2 p)
{
    const Point2 d = b - a;
    const double l2 = dot(d, d);
    if (l2 <= 0.0) return a;
    return a + std::clamp(dot(p - a, d) / l2, 0.0, 1.0) * d;
}

}  // namespace

double distanceToPasses(const std::vector<Point2>& points, Point2 p)
{
    double d = points.empty() ? std::numeric_limits<double>::infinity() : distance(p, points.front());
    for (std::size_t k = 1; k < points.size(); ++k) d = std::min(d, distance(p, foot(points[k - 1], points[k], p)));
    return d;
}

Approach nearestApproach(Point2 a, Point2 b, const ContourSegment& s)
{
    std::vector<Point2> candidates{a, b, foot(a, b, s.start), foot(a, b, s.end)};
    const Point2 d = b - a;
    if (s.isArc()) {
        candidates.push_back(foot(a, b, s.centre));
        // Where a-b crosses the circle.
        const Point2 f = a - s.centre;
        const double A = dot(d, d), B = 2 * dot(f, d), C = dot(f, f) - s.radius() * s.radius();
        const double disc = B * B - 4 * A * C;
        if (A > 0.0 && disc >= 0.0)
            for (const double t : {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)})
                if (t >= 0.0 && t <= 1.0) candidates.push_back(a + t * d);
    } else {
        // Where a-b crosses the line.
        const Point2 e = s.end - s.start;
        const double den = cross(d, e);
        if (std::abs(den) > 1e-15) {
            const double t = cross(s.start - a, e) / den, u = cross(s.start - a, d) / den;
            if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0) candidates.push_back(a + t * d);
        }
    }
    Approach best{std::numeric_limits<double>::infinity(), a};
    for (const Point2 q : candidates) {
        const double dq = distance(q, s.nearest(q));
        if (dq < best.distance) best = {dq, q};
    }
    return best;
}

std::optional<Excursion> firstExcursion(const Region& regionIn, const std::vector<Point2>& points, double radius)
{
    if (points.empty() || regionIn.outer.empty()) return std::nullopt;
    const Region region = normalised(regionIn);
    const RegionDistance inside(region);
    // The start: its disc inside the area.
    if (const double d0 = inside(points.front()); d0 > -radius + kTolerance) return Excursion{0, points.front(), radius + d0};
    std::vector<const ContourSegment*> boundary;
    for (const auto& s : region.outer.segments) boundary.push_back(&s);
    for (const auto& i : region.islands)
        for (const auto& s : i.segments) boundary.push_back(&s);
    // A strip that starts inside and never comes nearer than the radius to
    // the boundary stays inside.
    for (std::size_t k = 1; k < points.size(); ++k) {
        Approach worst{std::numeric_limits<double>::infinity(), points[k - 1]};
        for (const ContourSegment* s : boundary) {
            const Approach a = nearestApproach(points[k - 1], points[k], *s);
            if (a.distance < worst.distance) worst = a;
        }
        if (worst.distance < radius - kTolerance) {
            // The deepest the edge goes: where the region's signed distance
            // is largest along the pass, searched every 10 µm (the nearest
            // approach, worst.at, is where it first comes too near).
            Excursion e{static_cast<int>(k), worst.at, radius - worst.distance};
            const double len = distance(points[k - 1], points[k]);
            const int n = static_cast<int>(std::ceil(len / 0.01));
            for (int i = 0; i <= n; ++i) {
                const Point2 q = points[k - 1] + (static_cast<double>(i) / std::max(n, 1)) * (points[k] - points[k - 1]);
                if (const double by = radius + inside(q); by > e.by + 1e-9) e = {static_cast<int>(k), q, by};
            }
            return e;
        }
    }
    return std::nullopt;
}

Unswept unsweptArea(const Region& regionIn, const std::vector<Point2>& points, double radius)
{
    Unswept u;
    if (regionIn.outer.empty()) return u;
    const Region region = normalised(regionIn);
    ClipperLib::Paths area{toClipper(flatten(region.outer, kChord))};
    for (const auto& i : region.islands) area.push_back(toClipper(flatten(i, kChord)));

    ClipperLib::Paths strips;
    if (!points.empty() && radius > 0.0) {
        ClipperLib::ClipperOffset o;
        o.ArcTolerance = kChord * kClipperScale / 4;
        o.AddPath(toClipper(points), ClipperLib::jtRound, ClipperLib::etOpenRound);
        o.Execute(strips, radius * kClipperScale);
    }
    ClipperLib::Clipper c;
    c.AddPaths(area, ClipperLib::ptSubject, true);
    c.AddPaths(strips, ClipperLib::ptClip, true);
    ClipperLib::Paths left;
    c.Execute(ClipperLib::ctDifference, left, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    // Open away the slivers along walls the strips graze.
    ClipperLib::ClipperOffset shrink, grow;
    ClipperLib::Paths thin;
    shrink.AddPaths(left, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    shrink.ArcTolerance = kChord * kClipperScale / 4;
    shrink.Execute(thin, -kSliver * kClipperScale);
    grow.AddPaths(thin, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    grow.ArcTolerance = kChord * kClipperScale / 4;
    ClipperLib::PolyTree tree;
    grow.Execute(tree, kSliver * kClipperScale);
    const auto ring = [](const ClipperLib::Path& p) {
        std::vector<Point2> r;
        r.reserve(p.size());
        for (const auto& q : p) r.push_back(fromClipper(q));
        return r;
    };
    // Each piece: an outer ring less the holes in it (islands left whole in
    // an unswept piece); pieces inside holes are nodes of their own.
    std::vector<const ClipperLib::PolyNode*> outers;
    for (const ClipperLib::PolyNode* n = tree.GetFirst(); n; n = n->GetNext())
        if (!n->IsHole()) outers.push_back(n);
    for (const ClipperLib::PolyNode* n : outers) {
        double a = clipperAreaMm2(n->Contour);
        for (const ClipperLib::PolyNode* h : n->Childs) a -= clipperAreaMm2(h->Contour);
        if (a < kMinUnswept) continue;
        u.area += a;
        ++u.pieces;
        std::vector<Point2> outer = ring(n->Contour);
        if (a > u.largest) {
            Box2 box{outer.front(), outer.front()};
            for (const Point2 q : outer) {
                box.min = {std::min(box.min.x, q.x), std::min(box.min.y, q.y)};
                box.max = {std::max(box.max.x, q.x), std::max(box.max.y, q.y)};
            }
            u.largest = a;
            u.largestAt = 0.5 * (box.min + box.max);
        }
        u.rings.push_back(std::move(outer));
        for (const ClipperLib::PolyNode* h : n->Childs) u.rings.push_back(ring(h->Contour));
    }
    u.area = std::max(u.area, 0.0);
    return u;
}

}  // namespace taiwa::paths
