// Where figure elements cross (crossings.h).
#include "figure/crossings.h"

#include <algorithm>
#include <cmath>

namespace taiwa::figure {

Line lineThrough(Point2 a, Point2 b)
{
    return {a, (1.0 / length(b - a)) * (b - a)};
}

std::optional<Point2> lineCrossing(const Line& a, const Line& b)
{
    const double det = cross(a.dir, b.dir);
    if (std::abs(det) <= 1e-12) return std::nullopt;
    return a.point + (cross(b.point - a.point, b.dir) / det) * a.dir;
}

std::vector<Point2> circleCrossings(const Circle& a, const Circle& b)
{
    const Point2 d = b.centre - a.centre;
    const double dist = length(d), ra = a.radius, rb = b.radius;
    if (dist <= kTolerance || dist > ra + rb + kTolerance || dist < std::abs(ra - rb) - kTolerance) return {};
    const Point2 e = (1.0 / dist) * d;
    const double along = std::clamp((dist * dist + ra * ra - rb * rb) / (2 * dist), -ra, ra);
    const Point2 base = a.centre + along * e;
    if (std::abs(dist - (ra + rb)) <= kTolerance || std::abs(dist - std::abs(ra - rb)) <= kTolerance) return {base};
    const double h = std::sqrt(std::max(0.0, ra * ra - along * along));
    const Point2 left{-e.y, e.x};
    return {base + h * left, base - h * left};
}

std::vector<Point2> lineCircleCrossings(const Line& l, const Circle& c)
{
    const Point2 foot = l.point + dot(c.centre - l.point, l.dir) * l.dir;
    const double h = length(c.centre - foot);
    if (h > c.radius + kTolerance) return {};
    if (std::abs(h - c.radius) <= kTolerance) return {foot};
    const double half = std::sqrt(c.radius * c.radius - h * h);
    return {foot + half * l.dir, foot - half * l.dir};
}

}  // namespace taiwa::figure
