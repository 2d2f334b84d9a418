// Whether a contour crosses itself (self_crossing.h): the edges paired
// through a grid, then Clipper's measure for a closed contour that is not
// clearly simple, the pieces' crossings for an open one.
#include "modules/self_crossing.h"

#include "model/clipper_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace taiwa {

namespace {

constexpr double kChord = 1e-3;  // mm

// Products of two coordinate differences on Clipper's integers (up to 2e10
// units each) need more than 64 bits.
__extension__ typedef __int128 Wide;

// Calls meet(i, j) for the pairs of edges i < j (edge k from p[k] to p[k +
// 1], a closed polygon's last back to p[0]) that are not neighbours and
// whose bounds share a cell of a grid about as wide as the edges. True as
// soon as a pair meets, false when none does; nothing when that would take
// more than about 32 pair tests an edge (a crowd of edges in a few cells).
template <class Meet>
std::optional<bool> anyPairMeets(const std::vector<Point2>& p, bool closed, const Meet& meet)
{
    const std::size_t n = p.size();
    if (n < 2) return false;
    const std::size_t edges = closed ? n : n - 1;
    Box2 all{p.front(), p.front()};
    double length = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        all.min = {std::min(all.min.x, p[k].x), std::min(all.min.y, p[k].y)};
        all.max = {std::max(all.max.x, p[k].x), std::max(all.max.y, p[k].y)};
        if (k < edges) length += distance(p[k], p[(k + 1) % n]);
    }
    const double extent = std::max({all.max.x - all.min.x, all.max.y - all.min.y, 1e-9});
    const double cell = std::max(extent / 1024.0, length / static_cast<double>(edges));
    const auto cellOf = [&](double v, double from) { return static_cast<std::uint64_t>(std::floor((v - from) / cell)); };
    const std::uint64_t across = cellOf(all.max.x, all.min.x) + 1;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;  // (cell, edge)
    entries.reserve(2 * edges);
    for (std::size_t k = 0; k < edges; ++k) {
        const Point2 a = p[k], b = p[(k + 1) % n];
        const std::uint64_t x0 = cellOf(std::min(a.x, b.x), all.min.x), x1 = cellOf(std::max(a.x, b.x), all.min.x);
        const std::uint64_t y0 = cellOf(std::min(a.y, b.y), all.min.y), y1 = cellOf(std::max(a.y, b.y), all.min.y);
        for (std::uint64_t y = y0; y <= y1; ++y)
            for (std::uint64_t x = x0; x <= x1; ++x) entries.emplace_back(y * across + x, static_cast<std::uint32_t>(k));
    }
    std::sort(entries.begin(), entries.end());
    const auto neighbours = [&](std::size_t i, std::size_t j) { return j == i + 1 || (closed && i == 0 && j == edges - 1); };
    std::size_t tests = 0;
    const std::size_t budget = 32 * edges + 4096;
    for (std::size_t a = 0, b = 0; a < entries.size(); a = b) {
        while (b < entries.size() && entries[b].first == entries[a].first) ++b;
        for (std::size_t i = a; i < b; ++i)
            for (std::size_t j = i + 1; j < b; ++j) {
                const std::size_t e = std::min(entries[i].second, entries[j].second), f = std::max(entries[i].second, entries[j].second);
                if (e == f || neighbours(e, f)) continue;
                if (++tests > budget) return std::nullopt;
                if (meet(e, f)) return true;
            }
    }
    return false;
}

// Exact orientation of c against the line a-b on Clipper's integers.
int orientation(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, const ClipperLib::IntPoint& c)
{
    const Wide v = static_cast<Wide>(b.X - a.X) * (c.Y - a.Y) - static_cast<Wide>(b.Y - a.Y) * (c.X - a.X);
    return (v > 0) - (v < 0);
}

bool within(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, const ClipperLib::IntPoint& c)
{
    return std::min(a.X, b.X) <= c.X && c.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= c.Y && c.Y <= std::max(a.Y, b.Y);
}

// Whether edges a-b and c-d cross, touch or overlap.
bool edgesMeet(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, const ClipperLib::IntPoint& c,
               const ClipperLib::IntPoint& d)
{
    const int o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) || (o3 == 0 && within(c, d, a)) ||
           (o4 == 0 && within(c, d, b));
}

// A polygon whose edges have length, turn back on none of their neighbours
// and meet no other edge: Clipper's union of it is itself.
bool clearlySimple(const std::vector<Point2>& p, const ClipperLib::Path& path)
{
    const std::size_t n = path.size();
    if (n < 4) return false;
    for (std::size_t k = 0; k < n; ++k) {
        const auto &a = path[k], &b = path[(k + 1) % n], &c = path[(k + 2) % n];
        if (a == b) return false;
        // b's neighbours back along the same line: an overlap.
        if (orientation(a, b, c) == 0 && static_cast<Wide>(b.X - a.X) * (c.X - b.X) + static_cast<Wide>(b.Y - a.Y) * (c.Y - b.Y) <= 0)
            return false;
    }
    const auto meets = anyPairMeets(p, true, [&](std::size_t i, std::size_t j) {
        return edgesMeet(path[i], path[(i + 1) % n], path[j], path[(j + 1) % n]);
    });
    return meets && !*meets;
}

bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d)
{
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

}  // namespace

bool polygonCrossesItself(const std::vector<Point2>& p)
{
    // Clipper's union of the polygon is one piece of the same area.
    const ClipperLib::Path path = toClipper(p);
    if (clearlySimple(p, path)) return false;
    ClipperLib::Paths simple;
    ClipperLib::SimplifyPolygon(path, simple, ClipperLib::pftNonZero);
    if (simple.size() != 1) return true;
    return std::abs(std::abs(ClipperLib::Area(simple[0])) - std::abs(ClipperLib::Area(path))) >
           1e-6 * std::abs(ClipperLib::Area(path)) + 100.0;
}

bool crossesItself(const Contour& c)
{
    const std::vector<Point2> p = flatten(c, kChord);
    if (c.closed) return polygonCrossesItself(p);
    // An open chain: no two pieces that are not neighbours cross.
    const auto cross = [&](std::size_t i, std::size_t j) { return segmentsCross(p[i], p[i + 1], p[j], p[j + 1]); };
    if (const auto found = anyPairMeets(p, false, cross)) return *found;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)  // a crowd: every pair
        for (std::size_t j = i + 2; j + 1 < p.size(); ++j)
            if (cross(i, j)) return true;
    return false;
}

}  // namespace taiwa
