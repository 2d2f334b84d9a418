// Exact plane contours of lines and arcs (model/contour.h): lengths, areas,
// bounds, distances and flattening, with the arc sweep read the way
// toolpath.h's arcSweep reads a G2/G3 move.
#include "model/contour.h"

#include "model/winding.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

namespace taiwa {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double angleOf(Point2 v) { return std::atan2(v.y, v.x); }

// The angle from `from` to `to` turning the arc's way, in [0, 2π).
double turned(double from, double to, bool ccw)
{
    double d = ccw ? to - from : from - to;
    d = std::fmod(d, kTwoPi);
    if (d < 0.0) d += kTwoPi;
    return d;
}

// True when the direction at angle `a` from the centre lies on the arc.
bool onArc(const ContourSegment& s, double a)
{
    const bool ccw = s.kind == ContourSegment::Kind::ArcCCW;
    return turned(angleOf(s.start - s.centre), a, ccw) <= std::abs(s.sweep()) + 1e-12;
}

Point2 unit(Point2 v)
{
    const double l = length(v);
    return l > 0.0 ? (1.0 / l) * v : Point2{1.0, 0.0};
}

}  // namespace

double ContourSegment::sweep() const
{
    if (!isArc()) return 0.0;
    const Point2 a = start - centre, b = end - centre;
    double t = std::atan2(cross(a, b), dot(a, b));
    if (kind == Kind::ArcCCW) {
        if (t <= 0.0) t += kTwoPi;
    } else if (t >= 0.0) {
        t -= kTwoPi;
    }
    return t;
}

double ContourSegment::length() const
{
    return isArc() ? std::abs(sweep()) * radius() : distance(start, end);
}

Point2 ContourSegment::at(double t) const
{
    if (!isArc()) return start + t * (end - start);
    if (t >= 1.0) return end;
    const double a = angleOf(start - centre) + t * sweep(), r = radius();
    return {centre.x + r * std::cos(a), centre.y + r * std::sin(a)};
}

Point2 ContourSegment::startDirection() const
{
    if (!isArc()) return unit(end - start);
    const Point2 rad = unit(start - centre);
    return kind == Kind::ArcCCW ? Point2{-rad.y, rad.x} : Point2{rad.y, -rad.x};
}

Point2 ContourSegment::endDirection() const
{
    if (!isArc()) return unit(end - start);
    const Point2 rad = unit(end - centre);
    return kind == Kind::ArcCCW ? Point2{-rad.y, rad.x} : Point2{rad.y, -rad.x};
}

Point2 ContourSegment::nearest(Point2 p) const
{
    if (!isArc()) {
        const Point2 d = end - start;
        const double l2 = dot(d, d);
        if (l2 == 0.0) return start;
        return start + std::clamp(dot(p - start, d) / l2, 0.0, 1.0) * d;
    }
    const Point2 v = p - centre;
    if (taiwa::length(v) > 0.0 && onArc(*this, angleOf(v))) return centre + (radius() / taiwa::length(v)) * v;
    return distance(p, start) <= distance(p, end) ? start : end;
}

ContourSegment ContourSegment::reversed() const
{
    ContourSegment r = *this;
    std::swap(r.start, r.end);
    if (kind == Kind::ArcCCW) r.kind = Kind::ArcCW;
    else if (kind == Kind::ArcCW) r.kind = Kind::ArcCCW;
    return r;
}

double signedArea(const Contour& c)
{
    double a = 0.0;
    for (const auto& s : c.segments) {
        a += 0.5 * cross(s.start, s.end);
        if (s.isArc()) {
            const double t = s.sweep(), r = s.radius();
            a += 0.5 * r * r * (t - std::sin(t));
        }
    }
    return a;
}

Contour reversed(const Contour& c)
{
    Contour r;
    r.closed = c.closed;
    r.segments.reserve(c.segments.size());
    for (auto it = c.segments.rbegin(); it != c.segments.rend(); ++it) r.segments.push_back(it->reversed());
    return r;
}

double length(const Contour& c)
{
    double l = 0.0;
    for (const auto& s : c.segments) l += s.length();
    return l;
}

std::vector<Point2> flatten(const Contour& c, double tolerance)
{
    std::vector<Point2> pts;
    for (const auto& s : c.segments) {
        pts.push_back(s.start);
        if (!s.isArc()) continue;
        const double r = s.radius(), t = s.sweep();
        const double step = r > tolerance ? 2.0 * std::acos(1.0 - tolerance / r) : std::numbers::pi / 2.0;
        const int n = std::max(1, static_cast<int>(std::ceil(std::abs(t) / std::max(step, 1e-4))));
        const double a0 = angleOf(s.start - s.centre);
        for (int k = 1; k < n; ++k) {
            const double a = a0 + t * k / n;
            pts.push_back({s.centre.x + r * std::cos(a), s.centre.y + r * std::sin(a)});
        }
    }
    if (!c.closed && !c.segments.empty()) pts.push_back(c.end());
    return pts;
}

Box2 bounds(const Contour& c)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box2 b{{inf, inf}, {-inf, -inf}};
    const auto add = [&](Point2 p) {
        b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
        b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
    };
    for (const auto& s : c.segments) {
        add(s.start);
        add(s.end);
        if (!s.isArc()) continue;
        const double r = s.radius();
        for (int q = 0; q < 4; ++q) {
            const double a = q * std::numbers::pi / 2.0;
            if (onArc(s, a)) add({s.centre.x + r * std::cos(a), s.centre.y + r * std::sin(a)});
        }
    }
    return b;
}

namespace {

// The distance from p to the nearest of `segments`, without working out the
// nearest point of an arc whose whole circle is farther than the best so
// far, nor the root of a distance whose square is larger (both with a
// margin, so that the result is the plain minimum to the last bit).
double nearestDistance(const std::vector<ContourSegment>& segments, Point2 p)
{
    double d = std::numeric_limits<double>::infinity();
    constexpr double kMargin = 1.0 + 1e-9;
    for (const auto& s : segments) {
        if (s.isArc() && std::abs(taiwa::length(p - s.centre) - s.radius()) > d * kMargin) continue;
        const Point2 q = s.nearest(p);
        if (dot(p - q, p - q) > d * d * kMargin) continue;
        d = std::min(d, distance(p, q));
    }
    return d;
}

}  // namespace

double distanceTo(const Contour& c, Point2 p) { return nearestDistance(c.segments, p); }


bool contains(const Contour& c, Point2 p)
{
    // Winding number of the polygon within 0.1 µm of the arcs.
    return windingNumber(flatten(c, 1e-4), p) != 0;
}

double largestGap(const Contour& c)
{
    double g = 0.0;
    for (std::size_t i = 1; i < c.segments.size(); ++i)
        g = std::max(g, distance(c.segments[i - 1].end, c.segments[i].start));
    if (c.closed && !c.segments.empty()) g = std::max(g, distance(c.end(), c.start()));
    return g;
}

Contour withoutDegenerateSegments(const Contour& c)
{
    Contour r;
    r.closed = c.closed;
    for (const auto& s : c.segments)
        if (s.length() >= 1e-9 || (s.isArc() && s.start == s.end && s.radius() >= 1e-9)) r.segments.push_back(s);
    return r;
}

Region normalised(Region r)
{
    if (signedArea(r.outer) < 0.0) r.outer = reversed(r.outer);
    for (auto& i : r.islands)
        if (signedArea(i) > 0.0) i = reversed(i);
    return r;
}

double area(const Region& r)
{
    double a = std::abs(signedArea(r.outer));
    for (const auto& i : r.islands) a -= std::abs(signedArea(i));
    return a;
}

double signedDistance(const Region& r, Point2 p) { return RegionDistance(r)(p); }

namespace {
// A point farther than this from the boundary lies on the same side of the
// coarse polygons as of the exact contours; nearer, the fine ones decide.
constexpr double kCoarse = 0.02;  // mm
constexpr double kFine = 1e-4;    // mm
}  // namespace

RegionDistance::RegionDistance(const Region& r)
{
    static std::atomic<unsigned long long> made{0};
    id_ = ++made;
    polygons_.push_back(flatten(r.outer, kFine));
    coarse_.push_back(flatten(r.outer, kCoarse));
    segments_ = r.outer.segments;
    for (const auto& i : r.islands) {
        polygons_.push_back(flatten(i, kFine));
        coarse_.push_back(flatten(i, kCoarse));
        segments_.insert(segments_.end(), i.segments.begin(), i.segments.end());
    }
}

double RegionDistance::operator()(Point2 p) const
{
    const double d = nearestDistance(segments_, p);
    const auto& polygons = d > 2 * kCoarse ? coarse_ : polygons_;
    bool inside = windingNumber(polygons[0], p) != 0;
    for (std::size_t i = 1; inside && i < polygons.size(); ++i)
        if (windingNumber(polygons[i], p) != 0) inside = false;
    return inside ? -d : d;
}

bool RegionDistance::within(Point2 p, double limit) const
{
    struct Known {
        unsigned long long region = 0;  // the id, not the address: a new region may take a freed one's
        Point2 at{};
        double distance = 0.0;
    };
    thread_local Known last;
    if (last.region == id_) {
        // |d(p) - d(q)| <= |p - q|, with a margin for the rounding of both.
        const double moved = length(p - last.at) + 1e-9 * (1.0 + std::abs(last.distance) + std::abs(limit));
        if (last.distance - moved > limit) return false;
        if (last.distance + moved <= limit) return true;
    }
    last = {id_, p, (*this)(p)};
    return last.distance <= limit;
}

}  // namespace taiwa
