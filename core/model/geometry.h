// Plane geometry value types used across the core: points, the convex
// quadrilateral outline of a pocket with rounded corners, and its inward offset.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace taiwa {

struct Point2 {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const Point2&, const Point2&) = default;
};

inline Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.y}; }
inline double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
inline double length(Point2 a) { return std::hypot(a.x, a.y); }
inline double distance(Point2 a, Point2 b) { return length(a - b); }
// Tangent of an angle given in degrees (tapers, wall angles).
inline double tanDeg(double degrees) { return std::tan(degrees * std::numbers::pi / 180.0); }

// A closed four-sided outline with every corner rounded to the same radius.
// Corners are stored counter-clockwise (positive area); the sharp corners are
// the intersections of the straight sides, the rounding lies inside them.
struct Quad {
    std::array<Point2, 4> corners{};
    double cornerRadius = 0.0;
    friend bool operator==(const Quad&, const Quad&) = default;
};

// Signed area of the sharp polygon (positive when counter-clockwise).
double signedArea(const std::array<Point2, 4>& p);

// The four corners in counter-clockwise order (reversed when clockwise).
std::array<Point2, 4> counterClockwise(const std::array<Point2, 4>& p);

// Mean of the four corners: the pilot-hole position of module M4.
Point2 centroid(const std::array<Point2, 4>& p);

// Length of the shortest side.
double shortestSide(const std::array<Point2, 4>& p);

// True when the polygon is strictly convex (no reflex or straight corner).
bool isStrictlyConvex(const std::array<Point2, 4>& p);

// True when two non-adjacent sides cross each other.
bool isSelfIntersecting(const std::array<Point2, 4>& p);

// Each straight side moved inward by d (counter-clockwise input), the new
// corners being the intersections of the moved sides; corner radius r - d.
// Exact for convex outlines: the inward offset of a rounded convex polygon.
Quad offsetInward(const Quad& q, double d);

// The rounded quad as a closed polygon, counter-clockwise: straight sides
// exact, each corner arc replaced by chords whose ends lie on the arc and
// which stray at most `tolerance` from it (sharp corners, r <= 1e-9, are one
// point). The one flattening of outlines: the coverage proof, the
// interference check and the preview's outlines use it.
std::vector<Point2> flatten(const Quad& q, double tolerance);

// Radius of the largest circle that fits inside the sharp convex polygon
// (used for the pilot-hole and tool-entry checks).
double inscribedRadius(const std::array<Point2, 4>& p);

}  // namespace taiwa
