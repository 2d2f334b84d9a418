// Tool-nose paths over a tessellated surface (docs/surfaces.md): parallel
// finishing paths with the pick-feed that keeps the scallop under a set
// height, Z-level roughing leaving an allowance, paths stopped where they
// meet a cutting boundary surface (second abstract of the seed), and two
// surfaces combined path by path (eighth abstract). Every point is a tool
// nose (the cutter's lowest point on its axis), in mm; linking the paths
// (retract, pick-feed, approach) is the module's.
#pragma once

#include "occt/surface_mesh.h"

#include <limits>
#include <vector>

namespace taiwa::surface {

// The XY rectangle the paths cover.
struct Area {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Tool-nose points along the line y from x0 to x1 (or back, `reverse`),
// `step` apart and at both ends; points where nothing lies under the cutter
// break the path into pieces.
std::vector<std::vector<Point3>> dropLine(DropCutter& drop, double y, double x0, double x1, double step,
                                          bool reverse = false);

// The largest distance between neighbouring paths' ball centres that leaves
// a scallop of `height` between them on a plane: 2·√(h·(2r − h)), r the
// cutter's corner radius; on a concave bend of radius ρ > r (the surface's
// smallest, surface_checks.h) less, so that the scallop there stays within
// the height: the centres lie on a circle of ρ − r and the cusp between
// them is ρ − (ρ − r)·cos(θ/2) − √(r² − ℓ²/4) deep (θ their angle, ℓ their
// distance), solved for ℓ. 0 when ρ ≤ r (the cutter cannot follow the bend).
double scallopSpacing(const Cutter& cutter, double height,
                      double concaveRadius = std::numeric_limits<double>::infinity());

// Finishing: paths along X, one after the other in +Y, zigzag. The
// pick-feed to the next path is the largest (in Y) whose corner-circle
// centres (nose + r) stay within scallopSpacing of the previous path's at
// every sample: the scallop stays within `height` on planes and convex
// surfaces, whatever their slope (docs/surfaces.md says what concave ones
// need: the smallest concave radius, which reduces the spacing).
struct FinishingPaths {
    std::vector<std::vector<Point3>> paths;
    std::vector<double> ys;  // the Y of each path
};
FinishingPaths finishingPaths(DropCutter& drop, const Area& area, double step, double height,
                              double concaveRadius = std::numeric_limits<double>::infinity());

// The same with a fixed pick-feed in Y (a negative control of the tests).
FinishingPaths parallelPaths(DropCutter& drop, const Area& area, double step, double pickFeed);

// Roughing by Z levels from `top` down, `depth` apart, the last level at the
// surface's lowest point plus the allowance: at each level, the paths along
// X (`stepOver` apart in Y) where the level still has material above the
// surface offset by `allowance` (measured along the surface's normal: the
// drop of a cutter grown by it), riding up on the offset surface where it
// rises above the level.
struct RoughingPass {
    double level = 0.0;
    std::vector<Point3> points;
};
struct ZLevelOptions {
    double top = 0.0;
    double depth = 1.0;
    double stepOver = 1.0;
    double step = 0.5;
    double allowance = 0.2;
    bool axisOverSurface = false;  // no nose point where the tool axis is off the surface (DropCutter)
};
std::vector<RoughingPass> zLevelRoughing(const MeshIndex& surface, const Cutter& cutter, const Area& area,
                                         const ZLevelOptions& options);

// Points put between neighbours of `path` where the straight move between
// them passes more than `tolerance` under the cutter's nose at its middle
// (max(floorZ, drop's nose + raise) there), halving again up to four times.
// A ball rolling over a convex crease or the surface's edge moves its centre
// on a circle of its radius r: a move L long cuts in by L²/(8r), 1.3 µm for
// 0.25 mm with r 6, more than any bend of the surface itself.
void refineMoves(DropCutter& drop, std::vector<Point3>& path, double tolerance,
                 double floorZ = -std::numeric_limits<double>::infinity(), double raise = 0.0);

// A path stopped at a cutting boundary surface: the points up to the first
// place where its moves meet a triangle of `boundary`, that place the last
// point (exact on the move); the whole path when they never meet it.
struct StoppedPath {
    std::vector<Point3> points;
    bool stopped = false;
};
StoppedPath stopAtBoundary(const std::vector<Point3>& path, const MeshIndex& boundary);

// The paths as one tool path of nose points (model/toolpath.h), in their
// order: from `safeZ` a rapid over each path's first point, a rapid down to
// `clearance` above it, the plunge feed onto it, the cutting feeds along it,
// a rapid back to `safeZ` (the pick-feed to the next path goes over the
// surface: `safeZ` must be above it). Paths of fewer than one point are
// skipped; nothing but the start for no paths. `materialTop`: the highest
// the material can be over a path's start (the stock top for a module's
// step, whose Z-level passes start in what the level above left); the rapid
// down stops `clearance` above it or above the first point, whichever is
// higher (−infinity: above the first point).
ToolPath linkPaths(const std::vector<std::vector<Point3>>& paths, double safeZ, double clearance,
                   double materialTop = -std::numeric_limits<double>::infinity());

// Combining two surfaces (eighth abstract): along each path of the second
// surface (point sequences), a point on the kept side of the first (above or
// below it) stays, one on the other side is replaced by the point of the
// first surface straight above or below it; points with no first surface
// over them stay. The paths keep their number of points, so the result is a
// surface of paths again.
enum class KeepSide { Above, Below };
std::vector<std::vector<Point3>> combineSurfaces(const MeshIndex& first,
                                                 const std::vector<std::vector<Point3>>& secondPaths, KeepSide keep);

}  // namespace taiwa::surface
