// Booleans of closed loops of lines and arcs in the half-section, through
// OpenCASCADE planar faces, so that arcs stay exact arcs. The door speaks
// Taiwa's own types (turning/profile.h); nothing outside core/occt/ includes
// OpenCASCADE.
#pragma once

#include "model/result.h"
#include "model/turned.h"

#include <vector>

namespace taiwa::turning {

using Loop = std::vector<Segment>;  // closed: each segment ends where the next starts, the last at the first's start

// The boundary of ((∪ add) − (∪ cut)) ∪ (∪ keep): every loop of it, each a
// chain of exact lines and arcs in order, outer boundaries counter-clockwise,
// holes clockwise. `keep` is united after the cut, so nothing of it is cut
// (the grinding allowance keeps the part whole: its grooves come off the
// allowance shapes only). The loops' edges are split wherever an input
// loop's edge begins or ends on them, so every piece lies on exactly one
// input edge's curve. A Failure when OpenCASCADE refuses the shapes.
Result<std::vector<Loop>> regionBoundary(const std::vector<Loop>& add, const std::vector<Loop>& cut,
                                         const std::vector<Loop>& keep = {});

// True when `p` lies strictly inside the closed loop.
bool insideLoop(const Loop& loop, ZR p);

}  // namespace taiwa::turning
