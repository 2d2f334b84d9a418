// Plane geometry of pocket outlines: orientation, convexity, inward offset,
// flattening.
#include "model/geometry.h"

#include <algorithm>
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

double inscribedRadius(const std::array<Point2, 4>& pIn)
{
    // Bisection on the inward offset: the largest d whose offset quad keeps
    // positive orientation and does not turn inside out.
    const auto p = counterClockwise(pIn);
    double lo = 0.0, hi = 0.0;
    for (std::size_t i = 0; i < 4; ++i) hi = std::max(hi, distance(p[i], p[(i + 2) % 4]));
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        const Quad o = offsetInward(Quad{p, 0.0}, mid);
        bool ok = signedArea(o.corners) > 0.0;
        for (std::size_t i = 0; ok && i < 4; ++i) {
            const Point2 a = p[(i + 1) % 4] - p[i];
            const Point2 b = o.corners[(i + 1) % 4] - o.corners[i];
            ok = dot(a, b) > 0.0;
        }
        (ok ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace taiwa
