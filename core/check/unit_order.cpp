// Machining order of the units (docs/input-checks.md, "Unit order"): start
// with the unit the operator put first, then always go to the nearest unit
// not yet machined (centre to centre), ties going to the earlier unit.
#include "check/unit_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::check {

std::vector<int> machiningOrder(const std::vector<Point2>& centres)
{
    const std::size_t n = centres.size();
    std::vector<int> order;
    if (n == 0) return order;
    order.reserve(n);
    // The centres not yet machined, by grid cell (about one centre a cell):
    // the nearest is found by looking at rings of cells around the current
    // one, stopping when a ring is farther than the best found (100,000
    // units took 44 s by scanning them all at every step).
    double minX = centres[0].x, minY = centres[0].y, maxX = minX, maxY = minY;
    for (const auto& c : centres) {
        minX = std::min(minX, c.x), maxX = std::max(maxX, c.x);
        minY = std::min(minY, c.y), maxY = std::max(maxY, c.y);
    }
    const double extent = std::max({maxX - minX, maxY - minY, 1e-6});
    const long side = std::clamp<long>(static_cast<long>(std::sqrt(static_cast<double>(n))), 1, 2048);
    const double cell = extent / static_cast<double>(side) * (1 + 1e-9);
    const auto cellOf = [&](Point2 p) {
        return std::pair<long, long>{std::min(static_cast<long>((p.x - minX) / cell), side - 1),
                                     std::min(static_cast<long>((p.y - minY) / cell), side - 1)};
    };
    std::vector<std::vector<int>> cells(static_cast<std::size_t>(side * side));
    for (std::size_t u = 0; u < n; ++u) {
        const auto [cx, cy] = cellOf(centres[u]);
        cells[static_cast<std::size_t>(cy * side + cx)].push_back(static_cast<int>(u));
    }
    const auto take = [&](int u) {
        const auto [cx, cy] = cellOf(centres[static_cast<std::size_t>(u)]);
        auto& v = cells[static_cast<std::size_t>(cy * side + cx)];
        v.erase(std::find(v.begin(), v.end(), u));
    };

    int current = 0;  // the unit the operator put first
    take(current);
    order.push_back(current);
    for (std::size_t step = 1; step < n; ++step) {
        const Point2 from = centres[static_cast<std::size_t>(current)];
        const auto [cx, cy] = cellOf(from);
        int next = -1;
        double best = std::numeric_limits<double>::infinity();
        for (long ring = 0; ring <= side; ++ring) {
            // Every centre outside the rings looked at so far is at least this far.
            if (next >= 0 && (static_cast<double>(ring) - 1) * cell > best) break;
            for (long y = cy - ring; y <= cy + ring; ++y)
                for (long x = cx - ring; x <= cx + ring; ++x) {
                    if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;  // the ring only
                    if (x < 0 || y < 0 || x >= side || y >= side) continue;
                    for (const int u : cells[static_cast<std::size_t>(y * side + x)]) {
                        const double d = distance(from, centres[static_cast<std::size_t>(u)]);
                        if (d < best || (d == best && u < next)) best = d, next = u;  // ties: the earlier unit
                    }
                }
        }
        current = next;
        take(current);
        order.push_back(current);
    }
    return order;
}

}  // namespace taiwa::check
