// Entering a closed tool-centre loop on a lead circle, as the wall passes
// do (wall_finishing.cpp, region_walls.cpp, SIDE's closed contours): the
// piece a loop is entered on, the loop started at that piece's middle, the
// largest lead circle that fits, and the moves along a contour's lines and
// arcs.
#pragma once

#include "model/contour.h"
#include "paths/path_builder.h"

#include <cstddef>

namespace taiwa::paths {

// The loop's longest piece, lines first (an arc counts half its length):
// where a wall pass enters it.
std::size_t longestPiece(const Contour& loop);

// The loop started at the middle of its piece `k`: that piece split in two,
// its second half first.
Contour startedAtMiddle(const Contour& loop, std::size_t k);

// The moves along the contour's pieces at height z (lines fed, arcs as
// arcs); the builder must be at the contour's start.
void appendPieces(PathBuilder& b, const Contour& contour, double z);

// The largest lead radius, at most `wanted`, for which fits(radius) holds;
// `fits` holds up to some radius and not beyond it (lead circles tangent to
// the loop at one point grow nested), so bisection finds it.
template <class Fits>
double largestLead(double wanted, const Fits& fits)
{
    if (fits(wanted)) return wanted;
    double lo = 0.0, hi = wanted;
    for (int it = 0; it < 50; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace taiwa::paths
