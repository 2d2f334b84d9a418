// The forbidden region of a lathe tool's reference point (turn_region.h).
#include "turning/turn_region.h"

#include "model/clipper_scale.h"
#include "model/turned_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::turning {

namespace {

ClipperLib::IntPoint toInt(ZR p) { return toClipper(Point2{p.z, p.r}); }

double crossOf(ZR o, ZR a, ZR b) { return cross(a - o, b - o); }

// Crossings of the polygons' edges with the line where `along` varies and
// the other coordinate is `at` (z-line: along = z), sorted.
template <class Coord, class Other>
std::vector<double> crossingsOf(const std::vector<std::vector<ZR>>& polys, double at, Coord along, Other other)
{
    std::vector<double> xs;
    for (const auto& poly : polys) {
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const ZR a = poly[i], b = poly[(i + 1) % poly.size()];
            const double oa = other(a), ob = other(b);
            if ((oa > at) == (ob > at)) continue;  // half-open: a vertex on the line counts once
            const double t = (at - oa) / (ob - oa);
            xs.push_back(along(a) + t * (along(b) - along(a)));
        }
    }
    std::sort(xs.begin(), xs.end());
    return xs;
}

// The complement of the even-odd inside intervals within [lo, hi].
std::vector<std::pair<double, double>> freeBetween(const std::vector<double>& xs, double lo, double hi)
{
    std::vector<std::pair<double, double>> out;
    double from = lo;
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
        const double in0 = xs[i], in1 = xs[i + 1];
        if (in1 <= lo) continue;
        if (in0 >= hi) break;
        if (in0 > from) out.emplace_back(from, in0);
        from = std::max(from, in1);
    }
    if (hi > from) out.emplace_back(from, hi);
    return out;
}

}  // namespace

std::vector<ZR> flatten(const std::vector<Segment>& loop, double tol)
{
    std::vector<ZR> pts;
    for (const auto& s : loop) {
        pts.push_back(s.a);
        if (!s.arc) continue;
        // Chords of sagitta at most tol: the angle per chord 2 acos(1 - tol / R).
        const double sw = sweep(s);
        const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tol / std::max(s.radius, tol)));
        const int n = std::clamp(static_cast<int>(std::ceil(sw / std::max(step, 1e-6))), 1, 100000);
        const double len = length(s);
        for (int i = 1; i < n; ++i) pts.push_back(pointAt(s, len * i / n));
    }
    return pts;
}

std::vector<ZR> circumscribedCircle(ZR centre, double radius, int sides)
{
    std::vector<ZR> pts;
    const double R = radius / std::cos(std::numbers::pi / sides);
    for (int i = 0; i < sides; ++i) {
        const double a = 2.0 * std::numbers::pi * (i + 0.5) / sides;
        pts.push_back({centre.z + R * std::cos(a), centre.r + R * std::sin(a)});
    }
    return pts;
}

ToolShape convexHull(std::vector<ZR> p)
{
    std::sort(p.begin(), p.end(), [](ZR a, ZR b) { return a.z < b.z || (a.z == b.z && a.r < b.r); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<ZR> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && crossOf(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && crossOf(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

ForbiddenRegion ForbiddenRegion::make(const std::vector<Segment>& partLoop, const ToolShape& shape, double ax, double az,
                                      double growth, double flattenTol)
{
    // The reference point is forbidden where the tool, placed there, meets
    // the grown part: the part plus (-shape) grown by the allowances and the
    // flattening tolerance, as a convex pattern.
    std::vector<ZR> pattern;
    const double gz = az + growth, gr = ax + growth;
    for (const ZR q : shape)
        for (const ZR c : {ZR{-gz, -gr}, ZR{gz, -gr}, ZR{gz, gr}, ZR{-gz, gr}}) pattern.push_back(ZR{-q.z, -q.r} + c);
    pattern = convexHull(std::move(pattern));

    const std::vector<ZR> poly = flatten(partLoop, flattenTol);
    ClipperLib::Paths pieces;
    pieces.reserve(poly.size() + 1);
    {
        ClipperLib::Path part;
        for (const ZR p : poly) part.push_back(toInt(p));
        pieces.push_back(std::move(part));
    }
    // One convex hull per edge of the polygon: the pattern swept along it.
    std::vector<ZR> two;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const ZR a = poly[i], b = poly[(i + 1) % poly.size()];
        two.clear();
        for (const ZR q : pattern) {
            two.push_back(a + q);
            two.push_back(b + q);
        }
        ClipperLib::Path hull;
        for (const ZR p : convexHull(two)) hull.push_back(toInt(p));
        pieces.push_back(std::move(hull));
    }
    ClipperLib::Clipper c;
    for (auto& p : pieces) {
        if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
        c.AddPath(p, ClipperLib::ptSubject, true);
    }
    ClipperLib::Paths solution;
    c.Execute(ClipperLib::ctUnion, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ForbiddenRegion f;
    for (const auto& path : solution) {
        std::vector<ZR> loop;
        loop.reserve(path.size());
        for (const auto& ip : path) {
            const Point2 p = fromClipper(ip);
            loop.push_back({p.x, p.y});
        }
        f.polygons_.push_back(std::move(loop));
    }
    return f;
}

std::vector<std::pair<double, double>> ForbiddenRegion::freeAlongZ(double r, double zLo, double zHi) const
{
    return freeBetween(crossingsOf(polygons_, r, [](ZR p) { return p.z; }, [](ZR p) { return p.r; }), zLo, zHi);
}

std::vector<std::pair<double, double>> ForbiddenRegion::freeAlongR(double z, double rLo, double rHi) const
{
    return freeBetween(crossingsOf(polygons_, z, [](ZR p) { return p.r; }, [](ZR p) { return p.z; }), rLo, rHi);
}

bool ForbiddenRegion::inside(ZR p) const
{
    const auto xs = crossingsOf(polygons_, p.r, [](ZR q) { return q.z; }, [](ZR q) { return q.r; });
    const auto n = std::count_if(xs.begin(), xs.end(), [&](double z) { return z < p.z; });
    return n % 2 == 1;
}

bool ForbiddenRegion::segmentFree(ZR a, ZR b) const
{
    if (inside(a) || inside(b)) return false;
    for (const auto& poly : polygons_) {
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const ZR c = poly[i], d = poly[(i + 1) % poly.size()];
            const double d1 = crossOf(a, b, c), d2 = crossOf(a, b, d), d3 = crossOf(c, d, a), d4 = crossOf(c, d, b);
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return false;
        }
    }
    return true;
}

}  // namespace taiwa::turning
