// The half-section shapes of the lathe verification (verify_turning_shapes.h).
#include "verify/verify_turning_shapes.h"

#include "model/turned_geometry.h"
#include "sim/turned_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::verify::turned {

using sim::zrOf;

namespace {

double distanceToSegment(ZR p, ZR a, ZR b)
{
    const ZR d = b - a;
    const double l2 = turning::dot(d, d);
    const double t = l2 > 0.0 ? std::clamp(turning::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return turning::dist(p, a + t * d);
}

}  // namespace

Path box(double z0, double z1, double r0, double r1)
{
    return sim::clipperPolygon({{z0, r0}, {z1, r0}, {z1, r1}, {z0, r1}});
}

Paths boolean(ClipperLib::ClipType op, const Paths& a, const Paths& b)
{
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    Paths out;
    c.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

// Polygons grown by d [mm] (shrunk for a negative d), round corners within tol.
Paths grown(const Paths& p, double d, double tol)
{
    ClipperLib::ClipperOffset o(2.0, tol * kClipperScale);
    o.AddPaths(p, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths out;
    o.Execute(out, d * kClipperScale);
    return out;
}

// The area of polygons [mm²], holes taken off.
double areaOf(const Paths& p)
{
    double a = 0.0;
    for (const Path& q : p) a += ClipperLib::Area(q);
    return a / (kClipperScale * kClipperScale);
}

// The volume a region of the half-section is when turned about the axis
// [mm³]: 2π times its first moment about the axis (Pappus).
double volumeOf(const Paths& p)
{
    double m = 0.0;
    for (const Path& q : p)
        for (std::size_t i = 0; i < q.size(); ++i) {
            const ZR a = zrOf(q[i]), b = zrOf(q[(i + 1) % q.size()]);
            m += (a.r + b.r) * turning::cross(a, b) / 6.0;
        }
    return 2.0 * std::numbers::pi * m;
}

Outline::Outline(const Paths& polys)
{
    for (const Path& q : polys)
        for (std::size_t i = 0; i < q.size(); ++i) edges_.emplace_back(zrOf(q[i]), zrOf(q[(i + 1) % q.size()]));
}

double Outline::distance(ZR p) const
{
    double best = kInf;
    for (const auto& [a, b] : edges_) {
        if (p.z < std::min(a.z, b.z) - best || p.z > std::max(a.z, b.z) + best || p.r < std::min(a.r, b.r) - best ||
            p.r > std::max(a.r, b.r) + best)
            continue;
        best = std::min(best, distanceToSegment(p, a, b));
    }
    return best;
}

// The point of a region's outline farthest from an outline, the outline
// sampled every `spacing` mm: how deep a tool's sweep went into the part or
// the stock (the region being their overlap), how thick material left is.
Deepest deepest(const Paths& region, const Outline& from, double spacing)
{
    Deepest d;
    for (const Path& q : region)
        for (std::size_t i = 0; i < q.size(); ++i) {
            const ZR a = zrOf(q[i]), b = zrOf(q[(i + 1) % q.size()]);
            const int n = std::max(1, static_cast<int>(std::ceil(turning::dist(a, b) / spacing)));
            for (int k = 0; k < n; ++k) {
                const ZR p = a + (static_cast<double>(k) / n) * (b - a);
                const double v = from.distance(p);
                if (v > d.depth) d = {v, p};
            }
        }
    return d;
}

// The region under polygons as seen from the stock's surface: swept toward
// the axis (outer) or away from it (inner), the part's shadow that a
// roughing pass along Z cannot reach.
Paths shadowOf(const Paths& polys, bool inner)
{
    const double h = inner ? kFar : -kFar;
    Paths all = polys;
    for (const Path& q : polys)
        for (std::size_t i = 0; i < q.size(); ++i) {
            const ZR a = zrOf(q[i]), b = zrOf(q[(i + 1) % q.size()]);
            if (a.z == b.z) continue;
            all.push_back(sim::clipperPolygon({a, b, b + ZR{0.0, h}, a + ZR{0.0, h}}));
        }
    return boolean(ClipperLib::ctUnion, all, {});
}

// What the finishing contour bridges on purpose (the planner's note says
// so): each run of the deformed profile's edges it need not follow (an
// edge of the grinding allowance its insert cannot follow, a line shorter
// than two nose radii into a concave corner: anything but an edge of the
// part, original or moved, longer than two nose radii), as the hull of the
// run and two nose radii of its neighbours.
Paths bridgedOf(const turning::DeformedProfile& d, double nose)
{
    const auto follows = [&](const turning::DeformedEdge& e) {
        return (e.origin == turning::Origin::Original || e.origin == turning::Origin::Moved) &&
               turning::length(e.geometry) > 2.0 * nose;
    };
    Paths out;
    const std::size_t n = d.edges.size();
    for (std::size_t i = 0; i < n;) {
        if (follows(d.edges[i])) {
            ++i;
            continue;
        }
        std::size_t j = i;
        std::vector<turning::Segment> run;
        while (j < n && !follows(d.edges[j])) run.push_back(d.edges[j++].geometry);
        std::vector<ZR> pts = turning::flatten(run);
        pts.push_back(run.back().b);
        if (i > 0) {
            const turning::Segment& before = d.edges[i - 1].geometry;
            const double l = turning::length(before);
            pts.push_back(turning::pointAt(before, std::max(0.0, l - 2.0 * nose)));
        }
        if (j < n)
            pts.push_back(
                turning::pointAt(d.edges[j].geometry, std::min(turning::length(d.edges[j].geometry), 2.0 * nose)));
        out.push_back(sim::clipperPolygon(turning::convexHull(std::move(pts))));
        i = j;
    }
    return out;
}

}  // namespace taiwa::verify::turned
