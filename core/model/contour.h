// Exact plane contours of lines and arcs, and the pocket regions they bound:
// what figure-element chains (core/figure/) and DXF import evaluate to, and
// what the contour modules' tool paths follow, arcs staying arcs. All lengths
// in mm. Flattening to chords is for Clipper, proofs and drawing only.
#pragma once

#include "model/geometry.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// One piece of a contour: a straight line from `start` to `end`, or an arc
// from `start` to `end` around `centre`, counter-clockwise or clockwise.
// An arc whose end is its start is a full circle.
struct ContourSegment {
    enum class Kind { Line, ArcCCW, ArcCW };
    Kind kind = Kind::Line;
    Point2 start{};
    Point2 end{};
    Point2 centre{};  // arcs only

    bool isArc() const { return kind != Kind::Line; }
    double radius() const { return distance(start, centre); }
    // The signed sweep [rad]: counter-clockwise positive in (0, 2π],
    // clockwise negative in [-2π, 0); 0 for a line.
    double sweep() const;
    double length() const;
    // The point a fraction t in [0, 1] along the segment.
    Point2 at(double t) const;
    // The unit direction of travel at the start and at the end.
    Point2 startDirection() const;
    Point2 endDirection() const;
    // The nearest point of the segment to p.
    Point2 nearest(Point2 p) const;
    ContourSegment reversed() const;

    static ContourSegment line(Point2 a, Point2 b) { return {Kind::Line, a, b, {}}; }
    static ContourSegment arc(Point2 a, Point2 b, Point2 c, bool ccw)
    {
        return {ccw ? Kind::ArcCCW : Kind::ArcCW, a, b, c};
    }
    friend bool operator==(const ContourSegment&, const ContourSegment&) = default;
};

// A chain of segments, each starting where the one before it ends. A closed
// contour's last segment ends where its first starts.
struct Contour {
    std::vector<ContourSegment> segments;
    bool closed = false;

    bool empty() const { return segments.empty(); }
    Point2 start() const { return segments.front().start; }
    Point2 end() const { return segments.back().end; }
    friend bool operator==(const Contour&, const Contour&) = default;
};

// The area enclosed by a closed contour, arcs exact; positive when
// counter-clockwise.
double signedArea(const Contour& c);
// The same contour run the other way.
Contour reversed(const Contour& c);
// The length along all segments.
double length(const Contour& c);
// The contour as points (a closed contour without repeating its first point
// at the end): line ends exact, each arc replaced by chords whose ends lie
// on it and which stray at most `tolerance` from it.
std::vector<Point2> flatten(const Contour& c, double tolerance);
// The smallest box around the contour, arcs exact.
struct Box2 {
    Point2 min{}, max{};
};
Box2 bounds(const Contour& c);
// The distance from p to the nearest point of the contour, exact.
double distanceTo(const Contour& c, Point2 p);
// True when p lies inside the closed contour (its winding number is not
// zero), arcs exact; a point on the contour may count either way.
bool contains(const Contour& c, Point2 p);
// The gap over which each segment fails to start where the one before it
// ends (a closed contour: also the last to the first): the largest such gap.
double largestGap(const Contour& c);
// The contour's segments of zero length (shorter than 1e-9 mm) left out.
Contour withoutDegenerateSegments(const Contour& c);

// The contours of a job's figure elements by name, evaluated in mm.
using ContourTable = std::map<std::string, Contour>;

// A pocket's plan: the area inside `outer` and outside every island. The
// outer boundary runs counter-clockwise, islands clockwise (normalise()
// makes them so), so that the material side is always on the right.
struct Region {
    Contour outer;
    std::vector<Contour> islands;
    friend bool operator==(const Region&, const Region&) = default;
};

// The region with the outer boundary counter-clockwise and each island
// clockwise.
Region normalised(Region r);
// The area of the region (outer less islands) [mm²].
double area(const Region& r);
// Signed distance from p to the region's boundary: negative inside the
// region (in the pocket), positive in the material outside it or in an island.
double signedDistance(const Region& r, Point2 p);

// signedDistance for many points of one region, its polygons flattened once.
class RegionDistance {
public:
    explicit RegionDistance(const Region& r);
    double operator()(Point2 p) const;
    // Whether the signed distance at p is at most `limit`: the same answer
    // as (*this)(p) <= limit, found without the edges when the distance
    // last worked out on this thread for this region, at a point q, is
    // farther from the limit than |p - q| (the distance changes no faster
    // than the point moves). A verification asks the cells of a row in
    // order, most of them far from the walls.
    bool within(Point2 p, double limit) const;

private:
    std::vector<ContourSegment> segments_;
    std::vector<std::vector<Point2>> polygons_;  // outer, then islands, within 0.1 µm
    std::vector<std::vector<Point2>> coarse_;    // the same within 20 µm, for points farther away
    unsigned long long id_ = 0;                  // this region among all made (within's memory is per region)
};

}  // namespace taiwa
