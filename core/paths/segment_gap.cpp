// The exact nearest approach of two contour segments (segment_gap.h): seeds
// on the first segment's carrier (its ends, the second's ends, crossings,
// the points square to the other's carrier), each taken to the first
// segment and then to its nearest point of the second.
#include "paths/segment_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::paths {

namespace {

// Up to the points where the carriers (a line's infinite line, an arc's
// whole circle) of two segments cross or touch, and the points of the
// first carrier square to the second's.
struct Seeds {
    Point2 p[8];  // the most one pair adds: 4 ends, 2 square, 2 crossings
    int n = 0;
    void add(Point2 q) { p[n++] = q; }
};

Point2 unitOf(Point2 v)
{
    const double l = length(v);
    return l > 0.0 ? (1.0 / l) * v : Point2{1.0, 0.0};
}

// Where the line through a along d meets the circle (c, r).
void lineCircle(Point2 a, Point2 d, Point2 c, double r, Seeds& s)
{
    const double dd = dot(d, d);
    if (dd == 0.0) return;
    const Point2 f = a - c;
    const double b = dot(f, d), disc = b * b - dd * (dot(f, f) - r * r);
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    s.add(a + ((-b - root) / dd) * d);
    s.add(a + ((-b + root) / dd) * d);
}

void circleCircle(Point2 c1, double r1, Point2 c2, double r2, Seeds& s)
{
    const double d = distance(c1, c2);
    if (d == 0.0 || d > r1 + r2 || d < std::abs(r1 - r2)) return;
    const double along = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
    const Point2 u = (1.0 / d) * (c2 - c1), m = c1 + along * u, n{-u.y, u.x};
    s.add(m + h * n);
    s.add(m - h * n);
}

}  // namespace

SegmentGap segmentGap(const ContourSegment& a, const ContourSegment& b)
{
    Seeds s;
    s.add(a.start);
    s.add(a.end);
    s.add(b.start);  // taken to a: its nearest point
    s.add(b.end);
    if (!a.isArc() && !b.isArc()) {
        const Point2 da = a.end - a.start, db = b.end - b.start;
        const double den = cross(da, db);
        if (den != 0.0) s.add(a.start + (cross(b.start - a.start, db) / den) * da);
    } else if (!a.isArc()) {
        s.add(b.centre);  // its foot on a: square to the line through b's centre
        lineCircle(a.start, a.end - a.start, b.centre, b.radius(), s);
    } else if (!b.isArc()) {
        const Point2 n = unitOf(Point2{-(b.end - b.start).y, (b.end - b.start).x});
        const double r = a.radius();
        s.add(a.centre + r * n);
        s.add(a.centre - r * n);
        lineCircle(b.start, b.end - b.start, a.centre, r, s);
    } else {
        const double r = a.radius();
        if (distance(a.centre, b.centre) > 0.0) {
            const Point2 u = unitOf(b.centre - a.centre);
            s.add(a.centre + r * u);
            s.add(a.centre - r * u);
        }
        circleCircle(a.centre, r, b.centre, b.radius(), s);
    }
    SegmentGap best{std::numeric_limits<double>::infinity(), {}, {}};
    for (int i = 0; i < s.n; ++i) {
        const Point2 onA = a.nearest(s.p[i]);
        const Point2 onB = b.nearest(onA);
        const double g = distance(onA, onB);
        if (g < best.gap) best = {g, onA, onB};
    }
    return best;
}

double boxGap(const Box2& a, const Box2& b)
{
    const double dx = std::max({0.0, a.min.x - b.max.x, b.min.x - a.max.x});
    const double dy = std::max({0.0, a.min.y - b.max.y, b.min.y - a.max.y});
    return std::hypot(dx, dy);
}

Box2 segmentBox(const ContourSegment& s) { return bounds(Contour{{s}, false}); }

}  // namespace taiwa::paths
