// Space curves and ruled surfaces for 3-D surface machining (docs/surfaces.md):
// a space curve from its projections on two planes sharing one axis, the
// division of a space curve into N equal lengths, and the ruled surface
// joining the matching division points of two space curves (N for roughing,
// M > N for finishing). OpenCASCADE does the interpolation and the division
// behind this header; what comes out is Taiwa's own values (model/), lengths
// in mm. A refusal is a Failure naming the projection or curve and the point.
#pragma once

#include "model/geometry.h"
#include "model/result.h"
#include "model/toolpath.h"

#include <array>
#include <string>
#include <vector>

namespace taiwa::surface {

// The plane a projection lies in, its two coordinates in that order: XY is
// (x, y), YZ is (y, z), ZX is (z, x).
enum class ProjectionPlane { XY, YZ, ZX };

struct Projection {
    ProjectionPlane plane = ProjectionPlane::XY;
    // The curve as a point sequence in the plane's coordinates (figure
    // elements are handed over flattened to points).
    std::vector<Point2> points;
    // true: a cubic B-spline through the points (OpenCASCADE's
    // interpolation); false: straight lines between them (a figure of lines).
    bool smooth = true;
};

// A space curve as points along it (in order) and whether they are joined by
// a smooth curve through them or by straight lines.
struct SpaceCurve {
    std::vector<Point3> points;
    bool smooth = true;
};

// The space curve whose projections on two planes sharing one axis are
// `first` and `second` (ninth abstract of the seed): `first` is divided by
// length into pieces of at most `step` mm; at each division point (a, b), b
// on the shared axis, the point of `second` with that b gives c, and the
// space point is (a, b, c) in x, y, z order. The shared coordinate must be
// strictly monotonic along each projection (refused with the projection,
// the point's number from 1 and its value otherwise); the curve covers the
// range the two share, refused when they share none. Planes that are the
// same or share no axis are refused too.
Result<SpaceCurve> spaceCurveFromProjections(const Projection& first, const Projection& second, double step);

// `n` points dividing the curve into n − 1 pieces of equal length along it
// (the first and last point are its ends). Refused for fewer than two points
// on the curve or a curve of no length.
Result<std::vector<Point3>> divideByLength(const SpaceCurve& curve, int pieces);

// A ruled surface: rulings joining first[i] and second[i] (sixth abstract:
// both curves divided into the same number of pieces and the matching
// division points joined). Between two rulings the surface is the bilinear
// patch of their four ends.
struct RuledSurface {
    std::vector<Point3> first, second;  // same size, at least 2

    // u along the curves (0 … pieces), v along the rulings (0 … 1).
    Point3 point(double u, double v) const;
    int pieces() const { return static_cast<int>(first.size()) - 1; }
};

// The surface as point-sequence paths: `alongRulings` + 1 paths across the
// rulings (from the first curve to the second), each of pieces ×
// betweenRulings + 1 points, for tessellating (surface_mesh.h meshRuled)
// and checking (surface_checks.h).
std::vector<std::vector<Point3>> pathsOfRuled(const RuledSurface& s, int alongRulings, int betweenRulings);

// How many pieces a step-over along the curves implies (the operator may
// give N or M as a step-over): the longer curve's length over it, rounded
// up, at least 1. Refused for a step-over not above 0 or a curve that
// cannot be measured.
Result<int> piecesForStepOver(const SpaceCurve& first, const SpaceCurve& second, double stepOver);

// A refusal of a curve after its name, "curve 1: why" (`which`: 1 or 2; 0
// "the curve: why"). The name is part of the template the station
// translates (not "{}: {}"): it reads a message by the template with the
// most words, and a generic one such as "{} has no {}" or "{}: it needs at
// least two points, it has {}" would otherwise take "curve 1: projection 1
// (XY)" for one argument.
std::string curveRefusal(int which, const std::string& why);

// Both curves divided into `pieces` equal lengths and joined (refusals as
// divideByLength, naming "curve 1" or "curve 2").
Result<RuledSurface> ruledSurface(const SpaceCurve& first, const SpaceCurve& second, int pieces);

// The roughing (N pieces) and finishing (M pieces) surfaces of two space
// curves. N ≥ M, or N < 1, is refused naming N and M.
struct RoughAndFinish {
    RuledSurface roughing, finishing;
};
Result<RoughAndFinish> roughAndFinishSurfaces(const SpaceCurve& first, const SpaceCurve& second, int n, int m);

// The plane a ruled surface lies in, when it is one within `tolerance`
// (OpenCASCADE's GeomLib_IsPlanarSurface on the surface as a B-spline of
// degree 1 × 1): a point on it and its unit normal (z ≥ 0). Failure when the
// surface is not planar.
struct Plane3 {
    Point3 origin;
    std::array<double, 3> normal{};
};
Result<Plane3> planeOf(const RuledSurface& surface, double tolerance);

}  // namespace taiwa::surface
