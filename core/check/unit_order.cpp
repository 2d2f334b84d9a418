// Machining order of the units (docs/input-checks.md, "Unit order"): start
// with the unit the operator put first, then always go to the nearest unit
// not yet machined (centre to centre), ties going to the earlier unit.
#include "check/unit_checks.h"

#include <limits>

namespace taiwa::check {

std::vector<int> machiningOrder(const std::vector<Point2>& centres)
{
    const std::size_t n = centres.size();

    std::vector<int> order;
    order.reserve(n);
    std::vector<bool> done(n, false);
    std::size_t current = 0;
    for (std::size_t step = 0; step < n; ++step) {
        order.push_back(static_cast<int>(current));
        done[current] = true;
        std::size_t next = n;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t u = 0; u < n; ++u) {
            if (done[u]) continue;
            const double d = distance(centres[current], centres[u]);
            if (next == n || d < best) best = d, next = u;
        }
        current = next;
    }
    return order;
}

}  // namespace taiwa::check
