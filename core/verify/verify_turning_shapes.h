// The half-section shapes the lathe verification works with
// (verify_turning.cpp): boxes and booleans of Clipper polygons in (z, r),
// grown outlines, areas and turned volumes, the distance of a point to an
// outline and the deepest point of a region from it, the shadow a roughing
// pass along Z cannot reach, and what a finishing contour bridges on purpose.
#pragma once

#include "sim/turned_clipper.h"
#include "model/turned.h"


#include <limits>
#include <utility>
#include <vector>

namespace taiwa::verify::turned {

using ClipperLib::Path;
using ClipperLib::Paths;
using turning::ZR;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFar = 1000.0;  // beyond any bar [mm]

Path box(double z0, double z1, double r0, double r1);
Paths boolean(ClipperLib::ClipType op, const Paths& a, const Paths& b);
// Polygons grown by d [mm] (shrunk for a negative d), round corners within tol.
Paths grown(const Paths& p, double d, double tol);
// The area of polygons [mm²], holes taken off.
double areaOf(const Paths& p);
// The volume a region of the half-section is when turned about the axis
// [mm³]: 2π times its first moment about the axis (Pappus).
double volumeOf(const Paths& p);

// The edges of polygons, for the distance of a point to their outline.
class Outline {
public:
    explicit Outline(const Paths& polys);
    double distance(ZR p) const;

private:
    std::vector<std::pair<ZR, ZR>> edges_;
};

// The point of a region's outline farthest from an outline, the outline
// sampled every `spacing` mm: how deep a tool's sweep went into the part or
// the stock (the region being their overlap), how thick material left is.
struct Deepest {
    double depth = -kInf;
    ZR at{};
};
Deepest deepest(const Paths& region, const Outline& from, double spacing);

// The region under polygons as seen from the stock's surface: swept toward
// the axis (outer) or away from it (inner), the part's shadow that a
// roughing pass along Z cannot reach.
Paths shadowOf(const Paths& polys, bool inner);

// What the finishing contour bridges on purpose (the planner's note says
// so): each run of the deformed profile's edges it need not follow (an
// edge of the grinding allowance its insert cannot follow, a line shorter
// than two nose radii into a concave corner: anything but an edge of the
// part, original or moved, longer than two nose radii), as the hull of the
// run and two nose radii of its neighbours.
Paths bridgedOf(const turning::DeformedProfile& d, double nose);

}  // namespace taiwa::verify::turned
