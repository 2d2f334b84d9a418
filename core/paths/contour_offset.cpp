// Side milling's tool-centre chains: the exact one-sided offset of an open
// contour (parallels, rounded convex joints, trimmed concave joints) and of
// a closed one through offsetRegion (contour_offset.h).
#include "paths/contour_offset.h"

#include "paths/region_offset.h"
#include "paths/segment_gap.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace taiwa::paths {

namespace {

constexpr double kSame = 1e-9;  // mm: points closer are one point
constexpr double kTwoPi = 2.0 * std::numbers::pi;

Point2 leftNormal(Point2 d) { return {-d.y, d.x}; }

// The parallel of one segment at distance d on side `side` (+1 left, -1
// right of its direction); nothing when an arc's radius would not stay
// positive.
std::optional<ContourSegment> parallel(const ContourSegment& s, double side, double d)
{
    if (!s.isArc()) {
        const Point2 n = (side * d) * leftNormal(s.startDirection());
        return ContourSegment::line(s.start + n, s.end + n);
    }
    const double r = s.radius();
    const double towardCentre = (s.kind == ContourSegment::Kind::ArcCCW ? 1.0 : -1.0) * side;
    const double nr = r - towardCentre * d;
    if (nr <= 1e-6) return std::nullopt;
    const auto move = [&](Point2 p) { return s.centre + (nr / r) * (p - s.centre); };
    return ContourSegment{s.kind, move(s.start), move(s.end), s.centre};
}

// Where two segments' carriers (the whole line, the whole circle) cross.
std::vector<Point2> crossings(const ContourSegment& a, const ContourSegment& b)
{
    std::vector<Point2> out;
    const auto lineCircle = [&](const ContourSegment& l, const ContourSegment& c) {
        const Point2 d = l.startDirection();
        const Point2 f = l.start - c.centre;
        const double r = c.radius();
        const double B = dot(f, d), C = dot(f, f) - r * r;
        const double disc = B * B - C;
        if (disc < -1e-12 * std::max(1.0, r * r)) return;  // a tangent line: its one point, whatever the rounding
        const double s = std::sqrt(std::max(disc, 0.0));
        out.push_back(l.start + (-B - s) * d);
        if (s > 0) out.push_back(l.start + (-B + s) * d);
    };
    if (!a.isArc() && !b.isArc()) {
        const Point2 da = a.end - a.start, db = b.end - b.start;
        const double den = cross(da, db);
        if (std::abs(den) < 1e-12 * std::max(1.0, dot(da, da) * dot(db, db))) return out;
        const double t = cross(b.start - a.start, db) / den;
        out.push_back(a.start + t * da);
    } else if (!a.isArc()) {
        lineCircle(a, b);
    } else if (!b.isArc()) {
        lineCircle(b, a);
    } else {
        const double r0 = a.radius(), r1 = b.radius();
        const Point2 d = b.centre - a.centre;
        const double l = std::hypot(d.x, d.y);
        if (l < kSame || l > r0 + r1 + 1e-9 || l < std::abs(r0 - r1) - 1e-9) return out;
        const double x = (l * l + r0 * r0 - r1 * r1) / (2 * l);
        const double h = std::sqrt(std::max(r0 * r0 - x * x, 0.0));
        const Point2 u = (1.0 / l) * d;
        const Point2 m = a.centre + x * u;
        out.push_back(m + h * leftNormal(u));
        if (h > 0) out.push_back(m - h * leftNormal(u));
    }
    return out;
}

// The place of p (on the segment's carrier) along the segment: 0 at its
// start, 1 at its end, below 0 before the start, above 1 after the end.
double place(const ContourSegment& s, Point2 p)
{
    if (!s.isArc()) {
        const Point2 d = s.end - s.start;
        return dot(p - s.start, d) / dot(d, d);
    }
    const double sweep = std::abs(s.sweep());
    const double sign = s.kind == ContourSegment::Kind::ArcCCW ? 1.0 : -1.0;
    const Point2 a = s.start - s.centre, b = p - s.centre;
    double angle = sign * std::atan2(cross(a, b), dot(a, b));
    if (angle < 0) angle += kTwoPi;
    if (angle <= sweep + 1e-12) return angle / sweep;
    return kTwoPi - angle < angle - sweep ? -(kTwoPi - angle) / sweep : angle / sweep;
}

// Appends the parallel `e` to the chain, joined to the chain's last piece.
// Where the two cross within both (the chain's last piece before its end,
// e after its start) the joint is concave: both are trimmed there (a piece
// the crossing reverses is left out). Otherwise it is convex: an arc of
// radius d about `corner`, the contour point e's parallel starts from, from
// where the last piece meets that circle to e's start.
Result<void> join(std::vector<ContourSegment>& out, ContourSegment e, Point2 corner, double side, double d)
{
    for (;;) {
        if (out.empty()) {
            out.push_back(e);
            return {};
        }
        ContourSegment& last = out.back();
        if (distance(last.end, e.start) < kSame) {
            e.start = last.end;
            out.push_back(e);
            return {};
        }
        const Point2 gap = 0.5 * (last.end + e.start);
        const auto nearest = [](const std::vector<Point2>& xs, Point2 to) {
            return *std::min_element(xs.begin(), xs.end(), [&](Point2 p, Point2 q) { return distance(p, to) < distance(q, to); });
        };
        if (const std::vector<Point2> xs = crossings(last, e); !xs.empty()) {
            const Point2 x = nearest(xs, gap);
            const double inLast = place(last, x), inE = place(e, x);
            if (inLast <= 1.0 + 1e-9 && inE >= -1e-9) {  // concave
                if (inE > 1.0 + 1e-9) return {};         // the trimming reverses e: leave it out
                if (inLast < -1e-9) {                     // it reverses the last piece: leave that out
                    out.pop_back();
                    continue;
                }
                last.end = x;
                e.start = x;
                out.push_back(e);
                return {};
            }
        }
        // Convex: round the corner.
        if (std::abs(distance(last.end, corner) - d) > 1e-7) {
            const ContourSegment circle = ContourSegment::arc(corner + Point2{d, 0.0}, corner + Point2{d, 0.0}, corner, true);
            const std::vector<Point2> xs = crossings(last, circle);
            if (xs.empty()) {
                // The piece before passes the rounding by (two lines all but
                // on one carrier, an arc left out between them, their figure
                // coordinates rounded to 1e-6): a straight bridge to e's
                // start, which the SIDE planning proves against the contour
                // as every chain.
                out.push_back(ContourSegment::line(last.end, e.start));
                out.push_back(e);
                return {};
            }
            const Point2 x = nearest(xs, last.end);
            if (place(last, x) < -1e-9) {
                out.pop_back();
                continue;
            }
            last.end = x;
        }
        // The piece before reaches e's start itself (the parallels of two
        // lines on one carrier, an arc left out between them): no rounding,
        // which would be a full circle from a point to itself.
        if (distance(last.end, e.start) < 1e-7) {
            e.start = last.end;
            out.push_back(e);
            return {};
        }
        out.push_back(ContourSegment::arc(last.end, e.start, corner, side < 0));
        out.push_back(e);
        return {};
    }
}

Contour rectangleAround(const Contour& c, double margin)
{
    const Box2 b = bounds(c);
    const Point2 p0{b.min.x - margin, b.min.y - margin}, p2{b.max.x + margin, b.max.y + margin};
    const Point2 p1{p2.x, p0.y}, p3{p0.x, p2.y};
    Contour r;
    r.closed = true;
    r.segments = {ContourSegment::line(p0, p1), ContourSegment::line(p1, p2), ContourSegment::line(p2, p3),
                  ContourSegment::line(p3, p0)};
    return r;
}

}  // namespace

bool toolInside(const Contour& closed, bool left) { return (signedArea(closed) > 0) == left; }

Result<Contour> offsetOpen(const Contour& c, bool left, double d)
{
    if (!(d > 0.0) || !std::isfinite(d)) return Failure{"the offset distance must be positive"};
    const double side = left ? 1.0 : -1.0;
    std::vector<ContourSegment> out;
    for (const ContourSegment& s : c.segments) {
        const auto e = parallel(s, side, d);
        if (!e) continue;
        if (auto r = join(out, *e, s.start, side, d); !r) return r.failure();
    }
    if (out.empty()) return Failure{"nothing of the contour is left at that distance"};
    Contour chain;
    for (const ContourSegment& s : out)
        if (distance(s.start, s.end) > kSame || (s.isArc() && std::abs(s.sweep()) > 1e-9)) chain.segments.push_back(s);
    if (chain.segments.empty()) return Failure{"nothing of the contour is left at that distance"};
    return chain;
}

Result<std::vector<Contour>> offsetSide(const Contour& c, bool left, double d)
{
    if (!c.closed) {
        auto chain = offsetOpen(c, left, d);
        if (!chain) return chain.failure();
        return std::vector<Contour>{std::move(*chain)};
    }
    if (!(d > 0.0) || !std::isfinite(d)) return Failure{"the offset distance must be positive"};
    Region region;
    const bool inside = toolInside(c, left);
    if (inside) region.outer = c;
    else {
        region.outer = rectangleAround(c, 2 * d + 10.0);
        region.islands = {c};
    }
    auto pieces = offsetRegion(region, d);
    if (!pieces) return pieces.failure();
    std::vector<Contour> loops;
    for (const Region& piece : *pieces) {
        if (inside) loops.push_back(piece.outer);
        else
            for (const Contour& island : piece.islands) loops.push_back(island);
    }
    // Each loop in the contour's direction (an offset keeps the orientation).
    const bool ccw = signedArea(c) > 0;
    for (Contour& loop : loops)
        if ((signedArea(loop) > 0) != ccw) loop = reversed(loop);
    return loops;
}

Clearance chainClearance(const Contour& c, const std::vector<Contour>& chains)
{
    std::vector<Box2> boxes;
    boxes.reserve(c.segments.size());
    for (const ContourSegment& s : c.segments) boxes.push_back(segmentBox(s));
    Clearance best{1e300, {}};
    for (const Contour& chain : chains)
        for (const ContourSegment& s : chain.segments) {
            const Box2 box = segmentBox(s);
            for (std::size_t i = 0; i < c.segments.size(); ++i) {
                if (boxGap(box, boxes[i]) >= best.nearest) continue;  // no point of the two comes nearer
                const SegmentGap g = segmentGap(s, c.segments[i]);
                if (g.gap < best.nearest) best = {g.gap, g.onA};
            }
        }
    return best;
}

}  // namespace taiwa::paths
