// The tool-centre chains of side milling (module SIDE): a contour, open or
// closed, offset by a distance on one side, exactly, lines staying lines and
// arcs arcs (G2/G3 on the tape).
//
// An open contour is offset here: each segment's parallel (a line moved
// along its normal, an arc concentric with its radius grown or shrunk by d;
// an arc curving round the tool's side whose radius would not stay positive
// is left out), a convex joint (the contour turns away from the tool's
// side) rounded by an arc of radius d about the corner, a concave joint
// trimmed where the two parallels cross (the crossing nearest the gap), and
// a parallel that the trimming reverses (the crossing lies before its start,
// or after its end) left out, its neighbours then trimmed to each other.
// Where an arc is left out between two parallels that meet end to end (one
// carrier) they join without a rounding; where the rounding misses the
// piece before (the same, carriers 1e-6 apart) a straight bridge joins them.
// Only neighbours are trimmed: a channel narrower than 2d between distant
// parts of the contour is not seen here (the SIDE planning proves the chain
// against the contour before it is cut: chainClearance).
//
// A closed contour goes through paths::offsetRegion (region_offset.h): with
// the tool inside it the contour is the region; outside it, an island of a
// rectangle far enough around it for the two never to meet.
#pragma once

#include "model/contour.h"
#include "model/result.h"

#include <vector>

namespace taiwa::paths {

// True when a tool on the left (`left`) or the right of the closed contour's
// direction runs inside it.
bool toolInside(const Contour& closed, bool left);

// The chains the tool centre runs at distance d > 0 from `c` on its left
// (`left`) or right, each in c's direction: one chain for an open contour,
// the loops for a closed one (none when d leaves no room inside). A Failure
// when the offset cannot be made (d not positive, a crossing missing at a
// concave joint, offsetRegion's failures).
Result<std::vector<Contour>> offsetSide(const Contour& c, bool left, double d);

// The open offset alone (offsetSide's first step for an open contour).
Result<Contour> offsetOpen(const Contour& c, bool left, double d);

// The nearest any point of the chains comes to the contour, exactly (the
// least gap of every pair of a chain's and the contour's segments that can
// come nearer than the best so far: segment_gap.h), and where on a chain:
// at least d (less rounding) when the chains keep off the contour, less
// where a part of the contour the trimming did not see comes nearer (a
// narrow channel), 0 where a chain crosses it.
struct Clearance {
    double nearest = 0.0;
    Point2 where{};
};
Clearance chainClearance(const Contour& c, const std::vector<Contour>& chains);

}  // namespace taiwa::paths
