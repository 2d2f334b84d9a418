// Plane geometry of pocket outlines: orientation, convexity, inward offset,
// flattening.
#include "model/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace taiwa {

double signedArea(const std::array<Point2, 4>& p)
{
    double a = 0.0;
    for (std::size_t i = 0; i < 4; ++i) a += cross(p[i], p[(i + 1) % 4]);
    return 0.5 * a;
}

std::array<Point2, 4> counterClockwise(const std::array<Point2, 4>& p)
{
    if (signedArea(p) >= 0.0) return p;
    return {p[0], p[3], p[2], p[1]};
}

Point2 centroid(const std::array<Point2, 4>& p)
{
    return {(p[0].x + p[1].x + p[2].x + p[3].x) / 4.0, (p[0].y + p[1].y + p[2].y + p[3].y) / 4.0};
}

double shortestSide(const std::array<Point2, 4>& p)
{
    double m = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 4; ++i) m = std::min(m, distance(p[i], p[(i + 1) % 4]));
    return m;
}

bool isStrictlyConvex(const std::array<Point2, 4>& p)
{
    int sign = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        const double c = cross(p[(i + 1) % 4] - p[i], p[(i + 2) % 4] - p[(i + 1) % 4]);
        if (std::abs(c) < 1e-12) return false;
        const int s = c > 0 ? 1 : -1;
        if (sign == 0) sign = s;
        else if (s != sign) return false;
    }
    return true;
}

namespace {
bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d)
{
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}
}  // namespace

bool isSelfIntersecting(const std::array<Point2, 4>& p)
{
    return segmentsCross(p[0], p[1], p[2], p[3]) || segmentsCross(p[1], p[2], p[3], p[0]);
}

Quad offsetInward(const Quad& q, double d)
{
    const auto p = counterClockwise(q.corners);
    // Side i runs from p[i] to p[i+1]; for a counter-clockwise outline the
    // inside is on its left, so the inward normal is the left normal.
    std::array<Point2, 4> base{}, dir{};
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 t = p[(i + 1) % 4] - p[i];
        const double len = length(t);
        dir[i] = (1.0 / len) * t;
        const Point2 n{-dir[i].y, dir[i].x};
        base[i] = p[i] + d * n;
    }
    Quad out;
    out.cornerRadius = q.cornerRadius - d;
    for (std::size_t i = 0; i < 4; ++i) {
        // New corner i is where moved side i-1 meets moved side i.
        const std::size_t j = (i + 3) % 4;
        const double den = cross(dir[j], dir[i]);
        const double s = cross(base[i] - base[j], dir[i]) / den;
        out.corners[i] = base[j] + s * dir[j];
    }
    return out;
}

std::vector<Point2> flatten(const Quad& qIn, double tolerance)
{
    const auto p = counterClockwise(qIn.corners);
    const double rho = std::max(qIn.cornerRadius, 0.0);
    const Quad core = offsetInward(Quad{p, rho}, rho);  // the arc centres
    std::vector<Point2> pts;
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 c = core.corners[i];
        if (rho <= 1e-9) {
            pts.push_back(c);
            continue;
        }
        // From the outward normal of the side before the corner to that of
        // the side after it. The directions are the outline's own: the
        // core's sides are parallel to them but may have collapsed (a slot
        // whose radius is half its width has a segment for a core).
        const Point2 dPrev = p[i] - p[(i + 3) % 4], dNext = p[(i + 1) % 4] - p[i];
        const double a0 = std::atan2(-dPrev.x, dPrev.y);
        double a1 = std::atan2(-dNext.x, dNext.y);
        while (a1 < a0) a1 += 2 * std::numbers::pi;
        const double step = 2 * std::acos(std::max(0.0, 1 - tolerance / rho));
        const int n = std::max(1, static_cast<int>(std::ceil((a1 - a0) / std::max(step, 1e-3))));
        for (int k = 0; k <= n; ++k) {
            const double a = a0 + (a1 - a0) * k / n;
            pts.push_back({c.x + rho * std::cos(a), c.y + rho * std::sin(a)});
        }
    }
    return pts;
}

namespace {

// Whether the inward offset by d (corners o + d w) keeps positive
// orientation with every side pointing the way it did in p.
bool offsetHolds(const std::array<Point2, 4>& p, const std::array<Point2, 4>& o0, const std::array<Point2, 4>& w,
                 double d)
{
    std::array<Point2, 4> o{};
    for (std::size_t i = 0; i < 4; ++i) o[i] = o0[i] + d * w[i];
    if (!(signedArea(o) > 0.0)) return false;
    for (std::size_t i = 0; i < 4; ++i)
        if (!(dot(p[(i + 1) % 4] - p[i], o[(i + 1) % 4] - o[i]) > 0.0)) return false;
    return true;
}

}  // namespace

double inscribedRadius(const std::array<Point2, 4>& pIn)
{
    // The largest d whose inward offset keeps positive orientation and does
    // not turn inside out. The offset's corners move along straight lines as
    // d grows (corner(d) = corner(0) + d w), so each side's length along its
    // direction is linear in d and the area quadratic: the answer is the
    // first root among them. It runs for every unit and step of a job; a
    // bisection stands behind it for the shapes where rounding makes the
    // root disagree with the offset itself.
    // About its own centre: the radius does not depend on where the quad is,
    // its rounding does.
    auto p = counterClockwise(pIn);
    const Point2 centre = centroid(p);
    for (auto& c : p) c = c - centre;
    const Quad o0q = offsetInward(Quad{p, 0.0}, 0.0), o1q = offsetInward(Quad{p, 0.0}, 1.0);
    const auto& o0 = o0q.corners;
    std::array<Point2, 4> w{};
    for (std::size_t i = 0; i < 4; ++i) w[i] = o1q.corners[i] - o0[i];

    double first = std::numeric_limits<double>::infinity();
    double a0 = 0, a1 = 0, a2 = 0;  // twice the area: a0 + a1 d + a2 d^2
    for (std::size_t i = 0; i < 4; ++i) {
        const std::size_t j = (i + 1) % 4;
        const Point2 side = p[j] - p[i];
        const double along0 = dot(side, o0[j] - o0[i]), rate = dot(side, w[j] - w[i]);
        if (rate < 0 && along0 > 0) first = std::min(first, -along0 / rate);
        a0 += cross(o0[i], o0[j]);
        a1 += cross(o0[i], w[j]) + cross(w[i], o0[j]);
        a2 += cross(w[i], w[j]);
    }
    // The smallest positive root of the area, if it comes first.
    if (a2 != 0.0) {
        const double disc = a1 * a1 - 4 * a2 * a0;
        if (disc >= 0) {
            const double q = -0.5 * (a1 + std::copysign(std::sqrt(disc), a1));
            for (const double r : {q / a2, q != 0.0 ? a0 / q : -1.0})
                if (r > 0) first = std::min(first, r);
        }
    } else if (a1 < 0) {
        first = std::min(first, -a0 / a1);
    }
    if (std::isfinite(first) && offsetHolds(p, o0, w, first * (1 - 1e-9)) && !offsetHolds(p, o0, w, first * (1 + 1e-9)))
        return first;

    double lo = 0.0, hi = 0.0;
    for (std::size_t i = 0; i < 4; ++i) hi = std::max(hi, distance(p[i], p[(i + 2) % 4]));
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (offsetHolds(p, o0, w, mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace taiwa
