// The tool-centre contours of a pocket's contour-parallel passes: the exact
// inward offset of a Region (model/contour.h) by the cutter radius, arcs
// staying arcs. Clipper may prove and clear polygonal remains; the finishing
// passes and the tape follow these exact lines and arcs.
//
// Own exact geometry, no OpenCASCADE: each boundary segment's parallel (line
// or concentric arc) plus an arc of radius d round every corner that points
// into the pocket, all split where they cross one another, the pieces kept
// whose points lie no nearer than d to the boundary, chained into loops.
// (OpenCASCADE's BRepOffsetAPI_MakeOffset was measured first: 1.3 s on the
// bench case below, and wrong where an island's loop meets the outer one: it
// kept the island arcs outside the pocket.)
#pragma once

#include "model/contour.h"
#include "model/result.h"

#include <vector>

namespace taiwa::paths {

// Where the centre of a cutter of radius d may run along the boundary of the
// pocket `region` (outer boundary and islands, either orientation,
// normalised here): every point at distance exactly d from the boundary on
// the pocket side, as closed loops of exact lines and arcs.
//  - a line of the boundary gives a parallel line, an arc a concentric arc
//    (radius r - d for an arc curving round the pocket, left out when that
//    is not positive; r + d for an arc bulging into it: an island's full
//    circle of radius r gives a full circle of radius r + d);
//  - a corner that points into the pocket (an island's corner, the inner
//    corner of an L) gives an arc of radius d round the corner; the other
//    corners come out sharp (the parallels trimmed where they cross);
//  - the outer boundary shrinks and the islands grow; where they meet, the
//    loops merge and the tool-centre area may fall apart into pieces.
//
// The answer is that area in its connected pieces, largest first, each a
// Region: `outer` its outer loop, `islands` the loops round what the tool
// centre must keep out of inside it. Orientation as Region's: outer loops
// counter-clockwise, island loops clockwise, so that along every loop the
// material is on the right of the direction of travel: climb milling with a
// clockwise (M3) spindle, as core/paths/contour.h runs pocket walls. A
// parallel split by a crossing that does not survive is joined again, so a
// line stays one line and an island's full circle one full circle.
//
// Empty when d leaves no room at all; d = 0 gives the normalised region
// back. A Failure (never an exception) when d is negative or not finite, a
// loop of the region is empty or does not close (gap over 1e-6 mm), or the
// kept pieces do not close into loops (a region whose loops cross).
//
// Measured (RelWithDebInfo, one thread, on the 2-core build machine while
// other builds ran): a gear outline of 2,000 segments (1,000 lines, 1,000
// arcs, 10 mm teeth on R400) with 20 islands (10 circles, 10 rounded
// squares), as in tests/test_region_offset.cpp: 20 ms per offset at d = 1 mm
// (3,090 segments out, 2,050 of them arcs), 14 ms at d = 3 mm (best of 10).
// OpenCASCADE took 1.3 s for the same offsets.
Result<std::vector<Region>> offsetRegion(const Region& region, double d);

// True when a round cutter of radius d rolling along the whole boundary of
// `region` (outer loop and islands) stays inside it to `tolerance`: every
// candidate of offsetRegion(region, d) (the parallels and the arcs round
// the corners that point into the pocket), split at their crossings, lies
// no nearer than d - tolerance to the boundary, and an arc curving round the
// pocket tighter than d leaves a sliver no thicker than twice the tolerance
// ((d - r)(1/cos(φ/2) - 1) over its sweep φ; a full circle: never). Then the
// cutter sweeps the whole region but slivers of about the tolerance: what reachRadius
// (paths/region.h) asks, by bisection. Near-linear in the segments (a sweep
// for the crossings, a grid for the nearness), stopping at the first piece
// too near, and never a Failure. False for d not positive.
bool rollsAround(const Region& region, double d, double tolerance);

// All loops of the pieces in order, each piece's outer loop then its islands.
std::vector<Contour> loopsOf(const std::vector<Region>& pieces);

}  // namespace taiwa::paths
