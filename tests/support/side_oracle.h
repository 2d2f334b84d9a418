// Geometry oracle of side milling (module SIDE) for the tests, written from
// the definitions independently of the path code: the contour's wall as
// the exact lines and arcs of the unit's contour (an open one continued
// along the tangents of its end elements), the tool's side from the side
// code, and how far a tool would cut across the wall or below T.
#pragma once

#include "model/contour.h"
#include "model/job.h"
#include "model/tool.h"
#include "model/toolpath.h"

#include <optional>

namespace taiwa::test {

// Signed distance from p to the contour: positive on its left, negative on
// its right; an open contour continued by rays along its end tangents.
double leftSignedDistance(const Contour& c, Point2 p);

// For a SIDE unit (nothing for other modules): the signed distance from
// the tip's plan position to the wall, negative on the tool's side; the
// depth T; how far a tool with its tip at `tip` cuts beyond the finished
// shape (across the wall, or below T).
std::optional<double> sideWallDistance(const ModuleInput& m, Point3 tip);
std::optional<double> sideDepth(const ModuleInput& m);
std::optional<double> sideGouge(const ModuleInput& m, const Tool& tool, Point3 tip);

}  // namespace taiwa::test
