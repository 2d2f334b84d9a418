// The SURFACE steps' tapes read back through rs274, judged against a
// surface of paths (the step's finishing surface): how far the tool, grown
// by a margin, goes into it at the worst point sampled along the feed moves
// of one step (the drop-cutter on the surface's triangles, independent of
// the paths the module made); and the unit's finishing surface as its
// definition says, for the oracles that measure against it exactly.
#pragma once

#include "modules/surface/surface.h"
#include "occt/surface_curves.h"

#include "model/tool.h"
#include "model/toolpath.h"
#include "support/rs274.h"

#include <vector>

namespace taiwa::test {

struct SurfaceDepth {
    double deepest = -1e9;  // mm the tool is into the surface at worst (negative: above it)
    int feeds = 0;          // feed moves of the step looked at
};

// The feed moves of step `step` (1-based) sampled every 0.1 mm: the ball
// (or bull-nose) of `tool` grown by `grow` on every side, its nose `grow`
// below the tape's, dropped on `surface`; the deepest the tape's nose is
// under the dropped one. `grow` is the allowance a roughing step leaves
// (its cut is judged against the surface grown by it), or a negative
// control's larger tool.
SurfaceDepth intoSurface(const std::vector<CanonMove>& moves, int step, const std::vector<std::vector<Point3>>& surface,
                         const Tool& tool, double grow);

// The unit's finishing surface rebuilt from its curves by the core (the
// curves' division is what the surface is; the module's mesh is not used),
// divided into `m` pieces.
surface::RuledSurface finishingSurface(const SurfaceUnit& u, int m);

}  // namespace taiwa::test
