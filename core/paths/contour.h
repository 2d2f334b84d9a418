// The tool-centre contour of a rounded convex quadrilateral: straight sides
// joined by corner arcs (arcs stay arcs), starting and ending at the middle
// of the first side, counter-clockwise (climb milling of a pocket wall with a
// clockwise spindle) or clockwise.
#pragma once

#include "model/geometry.h"
#include "paths/path_builder.h"

#include <vector>

namespace taiwa::paths {

// The middle of side 0 of the contour (where contours start and end) and the
// unit direction of travel there.
struct ContourStart {
    Point2 point;
    Point2 direction;
};
ContourStart contourStart(const Quad& centre, bool ccw);

// Signed distance of a point to a rounded convex quad: negative inside.
double signedDistance(const Quad& q, Point2 p);

// The same for many points of one quad, its geometry worked out once.
class QuadDistance {
public:
    explicit QuadDistance(const Quad& q);
    double operator()(Point2 p) const;

private:
    std::array<Point2, 4> core_{};  // the sharp core (the arc centres)
    std::array<Point2, 4> out_{};   // outward normals of the sides
    double rho_ = 0.0;
};

// Appends the closed contour at height z; the builder must already be at
// contourStart(centre, ccw).point.
void appendContour(PathBuilder& b, const Quad& centre, double z, bool ccw);

// True when offsetting the outline inward by d still gives a proper
// quadrilateral (same orientation, sides not reversed).
bool offsetExists(const Quad& outline, double d);

// The largest inward offset for which offsetExists holds (bisection).
double maxOffset(const Quad& outline);

// The centre quad after an inward offset, with a corner radius that is
// never negative (sharp corners where the offset passes the rounding).
Quad centreQuad(const Quad& outline, double d);

}  // namespace taiwa::paths
