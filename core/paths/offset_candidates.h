// The candidate elements of an exact inward offset (region_offset.h) and
// what is asked of them: each boundary segment's parallel and an arc round
// each corner that points into the pocket (addCandidates), split where they
// cross one another (splitAll, a sweep over their bounding boxes). Which
// pieces lie nearer than the offset to the boundary is paths/nearby.h's.
// Internal to core/paths/: offsetRegion and rollsAround build on it.
#pragma once

#include "model/contour.h"

#include <cmath>
#include <utility>
#include <vector>

namespace taiwa::paths::offset {

constexpr double kSplitEnd = 1e-7;  // a crossing nearer than this [mm] to an element's end is that end
constexpr double kSame = 1e-9;      // crossings nearer than this [mm] along an element are one

// One candidate: a line from a to b, or an arc round c of radius r from
// angle a0 turning `sweep` (signed), a full circle when `closed`. Its
// parameter runs along it in mm from 0 to len().
struct Element {
    bool arc = false;
    bool closed = false;
    Point2 a{}, b{};
    Point2 c{};
    double r = 0.0, a0 = 0.0, sweep = 0.0;

    double len() const { return arc ? std::abs(sweep) * r : distance(a, b); }
    Point2 at(double s) const;
    // The parameter of a point on (or next to) the element's curve, or a
    // negative number when it lies off the element's extent.
    double paramOf(Point2 p) const;
};

// A point where an element is cut, at parameter s.
struct Split {
    double s;
    Point2 p;
};

// The candidates of one loop, material on its right: each segment's
// parallel on the left at d, and an arc of radius d round each corner that
// turns right.
void addCandidates(const Contour& loop, double d, std::vector<Element>& out);

// Each element's splits, its ends included, in order along it.
std::vector<std::vector<Split>> splitAll(const std::vector<Element>& elems);

}  // namespace taiwa::paths::offset
