// Rounded-quadrilateral contours with exact corner arcs.
#include "paths/contour.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa::paths {

namespace {

constexpr double kSharp = 1e-9;

struct Geometry {
    std::array<Point2, 4> core;  // arc centres (sharp corners when rho = 0)
    std::array<Point2, 4> dir;   // unit direction of side i (core[i] -> core[i+1])
    std::array<Point2, 4> out;   // outward (right) normal of side i
    double rho = 0.0;
};

Geometry geometryOf(const Quad& q)
{
    Geometry g;
    g.rho = q.cornerRadius > kSharp ? q.cornerRadius : 0.0;
    const auto p = counterClockwise(q.corners);
    g.core = offsetInward(Quad{p, g.rho}, g.rho).corners;
    // The directions are the quad's own sides': the core's are parallel to
    // them but may collapse (a slot whose radius is half its width has a
    // segment for a core), and a side of rounding noise would send its
    // corner arcs the long way round.
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 t = p[(i + 1) % 4] - p[i];
        if (!(length(t) > 0.0)) throw std::logic_error("contour of a quadrilateral with a side of no length");
        g.dir[i] = (1.0 / length(t)) * t;
        g.out[i] = {g.dir[i].y, -g.dir[i].x};
    }
    return g;
}

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }

}  // namespace

ContourStart contourStart(const Quad& centre, bool ccw)
{
    const Geometry g = geometryOf(centre);
    const Point2 mid = 0.5 * (g.core[0] + g.core[1]) + g.rho * g.out[0];
    return {mid, ccw ? g.dir[0] : -1.0 * g.dir[0]};
}

void appendContour(PathBuilder& b, const Quad& centre, double z, bool ccw)
{
    const Geometry g = geometryOf(centre);
    const Point2 mid = 0.5 * (g.core[0] + g.core[1]) + g.rho * g.out[0];
    // Counter-clockwise: along side i to its end, round corner i+1, next side.
    if (ccw) {
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t i = k, j = (k + 1) % 4;
            b.feed(at(g.core[j] + g.rho * g.out[i], z));
            if (g.rho > 0) b.arc(true, at(g.core[j] + g.rho * g.out[j], z), g.core[j]);
        }
    } else {
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t i = (4 - k) % 4;  // sides 0, 3, 2, 1 walked backwards
            b.feed(at(g.core[i] + g.rho * g.out[i], z));
            const std::size_t prev = (i + 3) % 4;
            if (g.rho > 0) b.arc(false, at(g.core[i] + g.rho * g.out[prev], z), g.core[i]);
        }
    }
    b.feed(at(mid, z));
}

double signedDistance(const Quad& q, Point2 p) { return QuadDistance(q)(p); }

QuadDistance::QuadDistance(const Quad& q)
{
    const Geometry g = geometryOf(q);
    core_ = g.core;
    out_ = g.out;
    rho_ = g.rho;
}

double QuadDistance::operator()(Point2 p) const
{
    // The rounded quad is its sharp core (sides moved in by the radius)
    // grown by the radius.
    // Inside the core the nearest side decides; outside, the nearest
    // point of the core's outline (measured only then).
    bool inside = true;
    double nearestSide = 1e300;
    for (std::size_t i = 0; i < 4; ++i) {
        const double out = dot(p - core_[i], out_[i]);
        if (out > 0) inside = false;
        nearestSide = std::min(nearestSide, -out);
    }
    if (inside) return -nearestSide - rho_;
    // The roots only of the sides nearest by their squares (within
    // rounding), so the least is the least of all four roots.
    std::array<Point2, 4> foot{};
    std::array<double, 4> d2{};
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 a = core_[i], ab = core_[(i + 1) % 4] - a;
        const double len2 = dot(ab, ab);
        const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        foot[i] = a + t * ab;
        d2[i] = dot(p - foot[i], p - foot[i]);
    }
    const double least = *std::min_element(d2.begin(), d2.end()) * (1.0 + 1e-9);
    double outside = 1e300;
    for (std::size_t i = 0; i < 4; ++i)
        if (d2[i] <= least) outside = std::min(outside, distance(p, foot[i]));
    return outside - rho_;
}

bool offsetExists(const Quad& outline, double d)
{
    const auto p = counterClockwise(outline.corners);
    const Quad o = offsetInward(Quad{p, 0.0}, d);
    if (!(signedArea(o.corners) > 0.0)) return false;
    for (std::size_t i = 0; i < 4; ++i)
        if (dot(p[(i + 1) % 4] - p[i], o.corners[(i + 1) % 4] - o.corners[i]) <= 0.0) return false;
    return true;
}

double maxOffset(const Quad& outline)
{
    double lo = 0.0, hi = 0.0;
    const auto& p = outline.corners;
    for (std::size_t i = 0; i < 4; ++i) hi = std::max(hi, distance(p[i], p[(i + 2) % 4]));
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (offsetExists(outline, mid) ? lo : hi) = mid;
    }
    return lo;
}

Quad centreQuad(const Quad& outline, double d)
{
    Quad q = offsetInward(Quad{counterClockwise(outline.corners), outline.cornerRadius}, d);
    q.cornerRadius = std::max(q.cornerRadius, 0.0);
    return q;
}

}  // namespace taiwa::paths
