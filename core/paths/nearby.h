// Whether any boundary segment lies nearer than a limit to a point: the
// question an exact inward offset (region_offset.cpp) asks of every piece of
// its candidates. Internal to core/paths/.
//
// The segments sit in a tree of runs of consecutive segments, in boundary
// order. A run is bounded by its chord (first start to last end) thickened
// by the farthest its segments stray from it. Boxes would not do: a disc
// nearly tangent to a round outline from inside (a tool near the inscribed
// radius) comes within a box's slack of every segment along a long stretch,
// so each query looked at O(√n) segments and their cells at O(n). A run's
// thickness shrinks with the square of its length along a smooth outline, so
// such a query keeps a node or two a level: O(log n).
#pragma once

#include "model/contour.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace taiwa::paths::offset {

class Nearby {
public:
    explicit Nearby(const std::vector<const ContourSegment*>& segs);
    // True when some segment lies nearer than `limit` to p.
    bool anyNearer(Point2 p, double limit) const;
    // The nodes the last query looked at (tests hold the tree to its bound).
    std::size_t lastVisited() const { return visited_; }

private:
    // A run of segments [first, first + count): a leaf when count is 1; its
    // halves are the next node and node `second`.
    struct Node {
        Point2 a{}, b{};     // the chord
        double thick = 0.0;  // no point of the run is farther from the chord
        std::uint32_t first = 0, count = 0, second = 0;
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t count);

    const std::vector<const ContourSegment*>& segs_;
    std::vector<Node> nodes_;
    mutable std::size_t visited_ = 0;
};

}  // namespace taiwa::paths::offset
