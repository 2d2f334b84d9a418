// Where two lines, two circles, or a line and a circle, of the figure
// cross (circles within kTolerance: none where they miss, one where they
// touch, two where they cross), and the line through two points. The one computation of a contour's junctions (figure_contour.cpp)
// and of the check of a contour written from a drawing (contour_writer.cpp),
// so that the writer finds the junctions exactly as the evaluation will.
#pragma once

#include "figure/figure_eval.h"

#include <optional>
#include <vector>

namespace taiwa::figure {

// The line through a and b as LINE/P1, P2 makes it (a to b, a unit
// direction); a and b must be apart.
Line lineThrough(Point2 a, Point2 b);
// Where two lines cross; none where they are parallel.
std::optional<Point2> lineCrossing(const Line& a, const Line& b);
std::vector<Point2> circleCrossings(const Circle& a, const Circle& b);
std::vector<Point2> lineCircleCrossings(const Line& l, const Circle& c);

}  // namespace taiwa::figure
