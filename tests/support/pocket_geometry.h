// Geometry oracle for the tests: the final pocket of a unit as a solid (its
// cross-section at every depth) and how far a tool whose tip is at a point
// would cut beyond it. Written from the spec's definitions, independently of
// the tool-path code it judges.
#pragma once

#include "model/job.h"
#include "model/tool.h"
#include "model/toolpath.h"

namespace taiwa::test {

// Cross-section of the finished pocket at a depth (mm, positive down).
Quad pocketSection(const ModuleInput& mmModule, double depth);
// Depth T of the pocket.
double pocketDepth(const ModuleInput& mmModule);

// Radius of the tool's solid at height h above its tip.
double toolRadiusAt(const Tool& tool, double h);

// Signed distance of a point to a rounded convex outline: negative inside
// (minus the distance to the boundary), positive outside.
double signedDistance(const Quad& outline, Point2 p);

// Signed distance (mm) from the tip's plan position to the finished pocket's
// wall at the tip's depth: negative inside the pocket.
double wallDistance(const ModuleInput& mmModule, Point3 tip);

// How far (mm) a tool with its tip at `tip` reaches beyond the finished
// pocket (walls and floor); <= 0 when it stays inside. Above the stock top
// (z >= 0) nothing can be gouged.
double gouge(const ModuleInput& mmModule, const Tool& tool, Point3 tip);

}  // namespace taiwa::test
