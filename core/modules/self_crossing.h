// Whether a contour a unit names crosses itself (CP's and AREA's outlines
// and islands, SIDE's path): a closed contour by Clipper's measure (its
// union is one piece of the same area), an open one where two pieces that
// are not neighbours cross. Both flattened to 1 µm chords. Edges are paired
// only where their bounds share a cell of a grid about as wide as the
// edges, so that an outline of thousands of edges is not looked at pair by
// pair; a closed contour none of whose edges meet but its neighbours at
// their ends is simple without asking Clipper, whose strictly-simple pass
// compares the points of its output pairwise. Called from the modules'
// checks.
#pragma once

#include "model/contour.h"

#include <vector>

namespace taiwa {

bool crossesItself(const Contour& c);
// The closed polygon through `p` (a contour flattened), by Clipper's measure.
bool polygonCrossesItself(const std::vector<Point2>& p);

}  // namespace taiwa
