// Exact plane geometry of the half-section's lines and arcs (model/turned.h
// Segment): tangents, normals, lengths, points along an edge, the infinite
// curve an edge lies on and where two such curves meet. Nothing here turns
// an arc into a polygon; OpenCASCADE is not needed for any of it.
#pragma once

#include "model/geometry.h"
#include "model/turned.h"

#include <cmath>
#include <optional>
#include <vector>

namespace taiwa::turning {

// The half-section's vector algebra is the plane's (model/geometry.h), Z as
// its x and the radius as its y: one formula each, the same bits.
inline Point2 planar(ZR a) { return {a.z, a.r}; }
inline ZR fromPlanar(Point2 p) { return {p.x, p.y}; }
inline ZR operator+(ZR a, ZR b) { return fromPlanar(planar(a) + planar(b)); }
inline ZR operator-(ZR a, ZR b) { return fromPlanar(planar(a) - planar(b)); }
inline ZR operator*(double s, ZR a) { return fromPlanar(s * planar(a)); }
inline double dot(ZR a, ZR b) { return taiwa::dot(planar(a), planar(b)); }
inline double cross(ZR a, ZR b) { return taiwa::cross(planar(a), planar(b)); }
inline double norm(ZR a) { return taiwa::length(planar(a)); }
inline double dist(ZR a, ZR b) { return taiwa::distance(planar(a), planar(b)); }
inline ZR unit(ZR a) { const double n = norm(a); return n > 0.0 ? (1.0 / n) * a : ZR{}; }
inline ZR leftNormal(ZR t) { return {-t.r, t.z}; }  // t turned +90° in the profile view

// Geometric tolerances of the turning code: points closer than kPointTol are
// the same point; directions within kAngleTolDeg degrees are the same.
constexpr double kPointTol = 1e-7;   // mm
constexpr double kAngleTolDeg = 1e-4;

Segment lineSegment(ZR a, ZR b);
// The arc from a to b about `centre`, counter-clockwise or not.
Segment arcSegment(ZR a, ZR b, ZR centre, bool ccw);
Segment reversed(const Segment& s);

double length(const Segment& s);
// Sweep of an arc in radians, in (0, 2π]; 0 for a line.
double sweep(const Segment& s);
// Unit tangent in the direction of travel at the start, the end, or at `p` on the edge.
ZR tangentAtStart(const Segment& s);
ZR tangentAtEnd(const Segment& s);
ZR tangentAt(const Segment& s, ZR p);
// The point at arc length `t` from the start.
ZR pointAt(const Segment& s, double t);
ZR midpoint(const Segment& s);
// Arc length from the start to `p` (p on the edge's curve; for arcs measured
// in the direction of travel, in [0, 2πR)).
double parameterOf(const Segment& s, ZR p);
// True when `p` lies on the edge itself (its curve and its extent), within tol.
bool contains(const Segment& s, ZR p, double tol = 1e-6);
// The part of `s` from p to q (both on it, p before q).
Segment piece(const Segment& s, ZR p, ZR q);
// Signed turn from direction u to v in degrees, in (-180, 180].
double turnDegrees(ZR u, ZR v);

// The infinite curve an edge lies on: a line (point, unit direction) or a full circle.
struct Curve {
    bool circle = false;
    ZR point;      // line: a point on it; circle: the centre
    ZR direction;  // line: unit direction
    double radius = 0.0;
};
Curve curveOf(const Segment& s);
Curve lineThrough(ZR p, ZR direction);
// Where two curves meet (0, 1 or 2 points; tangent circles give one).
std::vector<ZR> intersections(const Curve& a, const Curve& b);
// The point of `pts` nearest to `p`; nullopt when empty.
std::optional<ZR> nearest(const std::vector<ZR>& pts, ZR p);
// Where two edges cross or touch, within their extents.
std::vector<ZR> crossings(const Segment& a, const Segment& b);

// The same edge moved parallel to itself by d toward `side` (+1 left of the
// travel direction, -1 right): a line shifted, an arc concentric with radius
// R ± d. Its end points are the moved end points (normals at the ends).
// nullopt when an arc's radius would vanish.
std::optional<Segment> offset(const Segment& s, double d, int side);

// Signed area of a closed loop of edges (positive counter-clockwise), with
// the circular segments of its arcs.
double signedArea(const std::vector<Segment>& loop);

}  // namespace taiwa::turning
