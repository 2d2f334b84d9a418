// Chaining pieces of contour into contours: ends within the gap tolerance
// are joined (the nearest first, found through a grid on the ends), pieces
// reversed where needed; gaps a little over the tolerance and ends where
// three or more pieces meet are reported with their positions. Internal to
// core/dxf/.
#pragma once

#include "dxf/dxf_geometry.h"

#include <vector>

namespace taiwa::dxf::detail {

struct ChainResult {
    std::vector<DxfContour> contours;
    std::vector<DxfGap> gaps;
    std::vector<DxfBranch> branches;
    int joinsOverZero = 0;  // joins over more than 1e-9 mm
    double largestJoin = 0.0;
    Point2 largestJoinAt{};
};

// `tolerance`: ends this close are joined; `reportDistance` (> tolerance):
// ends this close but not joined are reported as gaps.
ChainResult chainPieces(std::vector<Piece> pieces, double tolerance, double reportDistance);

}  // namespace taiwa::dxf::detail
