// Proof that a pocket layer is fully cleared: the area the tool sweeps along
// its centre path (Clipper's round offset of the flattened path) must cover
// the region the step may cut. Returns points the tool centre must still
// visit to clear what is left (empty when nothing is left).
#pragma once

#include "model/geometry.h"
#include "model/toolpath.h"

#include <vector>

namespace taiwa::paths {

// Uncut area (mm^2) left inside `region` by a tool of radius R whose centre
// runs along the XY projection of the path's feed moves; the region is
// shrunk by `band` mm first (what the tool reaches within `band` of the
// outline counts as reached).
double uncutArea(const Quad& region, const ToolPath& path, double radius, double band = 0.001);

// Centre points that clear what the path leaves uncut, each inside
// `allowedCentres` (the tool centre's no-gouge region). Empty when the area
// left is below `tolerance` mm^2. Judged within a 5 µm band of the outline:
// fast enough for planning; the tests prove coverage within 1 µm.
std::vector<Point2> cleanupPoints(const Quad& region, const Quad& allowedCentres, const ToolPath& path, double radius,
                                  double tolerance = 1e-3);

}  // namespace taiwa::paths
