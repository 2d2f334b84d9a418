// Exact line and arc geometry of the half-section (segment_math.h).
#include "model/turned_geometry.h"

#include <algorithm>
#include <numbers>

namespace taiwa::turning {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double angleOf(ZR centre, ZR p) { return std::atan2(p.r - centre.r, p.z - centre.z); }

// An angle brought into [0, 2π).
double wrap(double a)
{
    a = std::fmod(a, kTwoPi);
    return a < 0.0 ? a + kTwoPi : a;
}

// Angle swept from angle a0 to a1 in the arc's direction, in [0, 2π).
double sweptFrom(const Segment& s, double a0, double a1) { return s.ccw ? wrap(a1 - a0) : wrap(a0 - a1); }

ZR onCircle(ZR centre, double radius, double angle)
{
    return {centre.z + radius * std::cos(angle), centre.r + radius * std::sin(angle)};
}

}  // namespace

Segment lineSegment(ZR a, ZR b) { return Segment{false, a, b, {}, 0.0, false}; }

Segment arcSegment(ZR a, ZR b, ZR centre, bool ccw)
{
    return Segment{true, a, b, centre, 0.5 * (dist(a, centre) + dist(b, centre)), ccw};
}

Segment reversed(const Segment& s)
{
    Segment r = s;
    std::swap(r.a, r.b);
    r.ccw = !s.ccw;
    if (!s.arc) r.ccw = false;
    return r;
}

double sweep(const Segment& s)
{
    if (!s.arc) return 0.0;
    const double sw = sweptFrom(s, angleOf(s.centre, s.a), angleOf(s.centre, s.b));
    return sw <= 1e-15 ? kTwoPi : sw;
}

double length(const Segment& s) { return s.arc ? s.radius * sweep(s) : dist(s.a, s.b); }

ZR tangentAt(const Segment& s, ZR p)
{
    if (!s.arc) return unit(s.b - s.a);
    const ZR radial = unit(p - s.centre);
    return s.ccw ? leftNormal(radial) : -1.0 * leftNormal(radial);
}
ZR tangentAtStart(const Segment& s) { return tangentAt(s, s.a); }
ZR tangentAtEnd(const Segment& s) { return tangentAt(s, s.b); }

ZR pointAt(const Segment& s, double t)
{
    if (!s.arc) return s.a + t * unit(s.b - s.a);
    const double a0 = angleOf(s.centre, s.a);
    return onCircle(s.centre, s.radius, s.ccw ? a0 + t / s.radius : a0 - t / s.radius);
}

ZR midpoint(const Segment& s) { return pointAt(s, 0.5 * length(s)); }

double parameterOf(const Segment& s, ZR p)
{
    if (!s.arc) return dot(p - s.a, unit(s.b - s.a));
    return s.radius * sweptFrom(s, angleOf(s.centre, s.a), angleOf(s.centre, p));
}

bool contains(const Segment& s, ZR p, double tol)
{
    if (dist(p, s.a) <= tol || dist(p, s.b) <= tol) return true;
    if (!s.arc) {
        const ZR d = unit(s.b - s.a);
        if (std::abs(cross(d, p - s.a)) > tol) return false;
        const double t = dot(p - s.a, d);
        return t >= -tol && t <= length(s) + tol;
    }
    if (std::abs(dist(p, s.centre) - s.radius) > tol) return false;
    return parameterOf(s, p) <= length(s) + tol;
}

Segment piece(const Segment& s, ZR p, ZR q)
{
    if (!s.arc) return lineSegment(p, q);
    Segment r = s;
    r.a = p;
    r.b = q;
    return r;
}

double turnDegrees(ZR u, ZR v) { return std::atan2(cross(u, v), dot(u, v)) * 180.0 / std::numbers::pi; }

Curve curveOf(const Segment& s)
{
    if (s.arc) return Curve{true, s.centre, {}, s.radius};
    return Curve{false, s.a, unit(s.b - s.a), 0.0};
}

Curve lineThrough(ZR p, ZR direction) { return Curve{false, p, unit(direction), 0.0}; }

std::vector<ZR> intersections(const Curve& a, const Curve& b)
{
    if (!a.circle && !b.circle) {
        const double den = cross(a.direction, b.direction);
        if (std::abs(den) < 1e-14) return {};
        const double t = cross(b.point - a.point, b.direction) / den;
        return {a.point + t * a.direction};
    }
    if (a.circle && !b.circle) return intersections(b, a);
    if (!a.circle) {  // line a, circle b
        const ZR foot = a.point + dot(b.point - a.point, a.direction) * a.direction;
        const double h = dist(foot, b.point);
        if (h > b.radius + 1e-9) return {};
        if (h >= b.radius - 1e-12) return {foot};
        const double half = std::sqrt(b.radius * b.radius - h * h);
        return {foot - half * a.direction, foot + half * a.direction};
    }
    const double d = dist(a.point, b.point);
    if (d < 1e-14) return {};
    if (d > a.radius + b.radius + 1e-9 || d < std::abs(a.radius - b.radius) - 1e-9) return {};
    const double x = (d * d + a.radius * a.radius - b.radius * b.radius) / (2.0 * d);
    const double h2 = a.radius * a.radius - x * x;
    const ZR u = (1.0 / d) * (b.point - a.point);
    const ZR base = a.point + x * u;
    if (h2 <= 1e-18) return {base};
    const double h = std::sqrt(h2);
    return {base + h * leftNormal(u), base - h * leftNormal(u)};
}

std::optional<ZR> nearest(const std::vector<ZR>& pts, ZR p)
{
    if (pts.empty()) return std::nullopt;
    return *std::min_element(pts.begin(), pts.end(), [&](ZR x, ZR y) { return dist(x, p) < dist(y, p); });
}

std::vector<ZR> crossings(const Segment& a, const Segment& b)
{
    std::vector<ZR> out;
    for (ZR p : intersections(curveOf(a), curveOf(b)))
        if (contains(a, p) && contains(b, p)) out.push_back(p);
    // Edges on one curve (collinear lines, concentric arcs of one radius)
    // meet wherever one's end lies on the other.
    const Curve ca = curveOf(a), cb = curveOf(b);
    const bool sameCurve = ca.circle == cb.circle &&
                           (ca.circle ? dist(ca.point, cb.point) < 1e-9 && std::abs(ca.radius - cb.radius) < 1e-9
                                      : std::abs(cross(ca.direction, cb.direction)) < 1e-12 &&
                                            std::abs(cross(ca.direction, cb.point - ca.point)) < 1e-9);
    if (sameCurve) {
        for (ZR p : {a.a, a.b})
            if (contains(b, p)) out.push_back(p);
        for (ZR p : {b.a, b.b})
            if (contains(a, p)) out.push_back(p);
    }
    return out;
}

std::optional<Segment> offset(const Segment& s, double d, int side)
{
    if (!s.arc) {
        const ZR n = static_cast<double>(side) * d * leftNormal(unit(s.b - s.a));
        return lineSegment(s.a + n, s.b + n);
    }
    // The left of a counter-clockwise arc is its centre's side.
    const double r = s.radius + static_cast<double>(side) * d * (s.ccw ? -1.0 : 1.0);
    if (r <= kPointTol) return std::nullopt;
    return arcSegment(s.centre + r * unit(s.a - s.centre), s.centre + r * unit(s.b - s.centre), s.centre, s.ccw);
}

double signedArea(const std::vector<Segment>& loop)
{
    double area = 0.0;
    for (const auto& s : loop) {
        area += 0.5 * cross(s.a, s.b);
        if (s.arc) {
            const double t = sweep(s);
            area += (s.ccw ? 0.5 : -0.5) * s.radius * s.radius * (t - std::sin(t));
        }
    }
    return area;
}

}  // namespace taiwa::turning
