// Where a lathe tool's reference point may go: the part's half-section grown
// by the allowance it must leave and by the tool's own shape (the insert's
// nose and both cutting edges, a blade's rectangle), as polygons in the
// (z, r) half-plane, with the queries the turning paths ask of it: the free
// stretches of a line along Z or across it, and whether a straight move
// stays free. Clipper builds the region (a Minkowski sum made of one convex
// hull per part edge, united); arcs are flattened within kFlatten and the
// region grown by it, so a point the region calls free is free of the exact
// part (docs/turning.md "Roughing").
#pragma once

#include "model/turned.h"

#include <optional>
#include <utility>
#include <vector>

namespace taiwa::turning {

// Chord tolerance of the flattened part and the growth that covers it [mm].
constexpr double kFlatten = 0.002;

// The closed loop as a polygon, arcs flattened so that no chord strays more
// than `tol` from its arc.
std::vector<ZR> flatten(const std::vector<Segment>& loop, double tol = kFlatten);

// A convex shape relative to the tool's reference point (insert: its nose
// centre; blade: its front corner), counter-clockwise.
using ToolShape = std::vector<ZR>;

class ForbiddenRegion {
public:
    ForbiddenRegion() = default;
    // The part (a closed loop of exact edges) grown by `shape` and by the
    // allowances ax (across the axis, radius) and az (along it).
    // `growth` covers the flattening (a blade that must fit a groove of its
    // own width takes none, with a finer flattening).
    static ForbiddenRegion make(const std::vector<Segment>& partLoop, const ToolShape& shape, double ax, double az,
                                double growth = kFlatten, double flattenTol = kFlatten);

    // The free stretches [z0, z1] of the line r = const between zLo and zHi, ascending.
    std::vector<std::pair<double, double>> freeAlongZ(double r, double zLo, double zHi) const;
    // The free stretches [r0, r1] of the line z = const between rLo and rHi, ascending.
    std::vector<std::pair<double, double>> freeAlongR(double z, double rLo, double rHi) const;
    // Whether the straight move from a to b stays out of the region.
    bool segmentFree(ZR a, ZR b) const;
    bool inside(ZR p) const;
    const std::vector<std::vector<ZR>>& polygons() const { return polygons_; }

private:
    std::vector<std::vector<ZR>> polygons_;  // even-odd: outer loops and holes
};

// The hull of a circle (as a circumscribed polygon, so it holds the circle)
// and extra points: an insert's nose with the far ends of its edges.
ToolShape convexHull(std::vector<ZR> points);
std::vector<ZR> circumscribedCircle(ZR centre, double radius, int sides = 24);

}  // namespace taiwa::turning
