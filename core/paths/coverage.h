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

// True when the rings alone are known to clear a rectangular outline (any
// rotation, corners rounded to at least R): the centre rings are the inward
// offsets of the outline by `offsets` (in any order: the least R, the
// greatest within 1e-4 of the deepest), and no two neighbours are more than
// (1 + 1/sqrt 2) R apart. Then every point of the outline lies within R of
// a ring, and cleanupPoints would find nothing: planning skips the proof.
// False says nothing (the proof must be made).
bool ringsClearRectangle(const Quad& outline, double radius, const std::vector<double>& offsets);

}  // namespace taiwa::paths
