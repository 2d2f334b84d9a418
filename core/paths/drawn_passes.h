// Area clearing by drawn passes (module AREA, seed 002's seventh abstract):
// the operator paints an area and draws passes through it, each a straight
// strip one tool wide from a point to the next. Here: what of the area the
// strips leave unswept, and where a pass would take the tool's edge out of
// the area (across its outline or into an island). The unit's check, its
// plan and the station's Figure tab ask the same functions.
#pragma once

#include "model/contour.h"

#include <optional>
#include <vector>

namespace taiwa::paths {

// The area's parts the strips of `radius` around the passes through
// `points` do not sweep. Slivers thinner than about 10 µm (a pass running
// exactly a radius from a wall leaves one of zero width) and pieces under
// kMinUnswept mm² are not counted.
inline constexpr double kMinUnswept = 0.01;  // mm²
struct Unswept {
    // Boundaries of the unswept pieces (flattened to 1 µm): outer rings
    // counter-clockwise, holes in them clockwise.
    std::vector<std::vector<Point2>> rings;
    double area = 0.0;       // mm², all pieces
    int pieces = 0;          // pieces of at least kMinUnswept
    double largest = 0.0;    // mm², the largest piece
    Point2 largestAt{};      // the middle of the largest piece's box
};
Unswept unsweptArea(const Region& region, const std::vector<Point2>& points, double radius);

// The first pass (1-based: pass k runs from points[k-1] to points[k]; pass 0
// is the start point alone) whose strip leaves the area by more than 1 µm:
// where the tool centre is when it does and by how much, exact on lines and
// arcs. Nothing when every strip stays inside.
struct Excursion {
    int pass = 0;
    Point2 at{};
    double by = 0.0;  // mm the tool's edge crosses the area's boundary
};
std::optional<Excursion> firstExcursion(const Region& region, const std::vector<Point2>& points, double radius);

// The distance from p to the passes through `points` (the polyline).
double distanceToPasses(const std::vector<Point2>& points, Point2 p);

// The nearest the segment a-b comes to the contour segment s, and the point
// of a-b where it does: exact (every place the distance can be least is
// tried: the ends, the feet of s's ends and centre, the crossings).
struct Approach {
    double distance = 0.0;
    Point2 at{};
};
Approach nearestApproach(Point2 a, Point2 b, const ContourSegment& s);

}  // namespace taiwa::paths
