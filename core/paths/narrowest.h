// Where a pocket region is narrowest for a round cutter, and what makes it
// so: an island touching the outline or another island, the gap between
// two contours, a neck of one contour, or an inside arc. The refusals of
// the contour units name this place (CP's islands and outline, SIDE's
// contour) instead of a bare reach. An independent measure of the reach
// (reachRadius, region.h) found by rolling balls: for every point p of the
// boundary, the largest disc touching it from inside the region has radius
// min over the other boundary points q of |q − p|² / (2 (q − p)·n), n the
// inward normal at p; its smallest over p is half the narrowest gap, or the
// smallest inside radius.
#pragma once

#include "model/contour.h"

#include <optional>

namespace taiwa::paths {

struct NarrowestPlace {
    enum class Kind {
        Touch,      // two contours meet (gap under 1 µm)
        Gap,        // between two contours
        Neck,       // one contour comes near itself
        InsideArc,  // an arc curving round the pocket
    };
    Kind kind = Kind::Gap;
    // The contours involved, as indices into the region: 0 the outline,
    // k ≥ 1 the island k − 1. For a neck or an arc both are the same.
    int first = 0, second = 0;
    // Gap, touch, neck: the nearest points of the two sides (a on `first`);
    // an inside arc: a its middle and b its centre.
    Point2 a{}, b{};
    // Gap, touch, neck: the distance |a − b| (exact distance of a to the
    // other side); an inside arc: its radius.
    double width = 0.0;
    // The largest disc radius that reaches the place (half the width, or
    // the arc's radius): the reach it limits.
    double reach = 0.0;
};

// The narrowest place of the region (any orientation), its boundary sampled
// about `spacing` mm apart (coarser on long boundaries: at most 8,000
// samples, the search being quadratic). Nothing when the region is empty.
std::optional<NarrowestPlace> narrowestPlace(const Region& region, double spacing = 0.05);

// The smallest distance between two different contours of the region (an
// island and the outline, two islands): exact distances from each island's
// points about `spacing` mm apart and its segment ends. Infinity without
// islands. Half of it bounds the reach: reachRadius (region.h) rolls along
// each contour and takes an island touching the outline for room.
double smallestIslandGap(const Region& region, double spacing = 0.05);

}  // namespace taiwa::paths
