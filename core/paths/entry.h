// How a pocket-clearing tool gets down to a layer: a plunge into the pilot
// hole, a helical ramp, a zig-zag ramp along a slot too narrow for a helix,
// or (only where neither fits) a straight plunge.
#pragma once

#include "model/geometry.h"
#include "paths/path_builder.h"

namespace taiwa::paths {

struct Entry {
    enum class Kind { PilotHole, Helix, LinearRamp, Plunge };
    Kind kind = Kind::Plunge;
    Point2 point;       // where the entry starts and ends (helix: its centre)
    double radius = 0;  // helix radius
    Point2 other;       // linear ramp: the far end of the ramp line
};

// The entry for a pocket whose tool-centre region is `centres` (the outline
// moved inward by R): into the hole when `hole` (>0 = its diameter) is at
// least the tool diameter and at `holeAt` inside the region; else a helix of
// at most R/2 around the middle of the region, a linear ramp when the
// region is a slot too narrow for a helix, a plunge when it is a point.
Entry chooseEntry(const Quad& outline, double toolRadius, double hole, Point2 holeAt);

// Appends the moves from the builder's height (at e.point) down to z,
// ending at e.point; ramps at `rampAngle` degrees, in the milling sense
// `ccw`.
void appendEntry(PathBuilder& b, const Entry& e, double z, double rampAngle, bool ccw);

}  // namespace taiwa::paths
