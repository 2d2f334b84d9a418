// Where two circles, or a line and a circle, of the figure cross, within
// kTolerance: none where they miss, one where they touch, two where they
// cross. The one computation of a contour's junctions (figure_contour.cpp)
// and of the check of a contour written from a drawing (contour_writer.cpp),
// so that the writer finds the junctions exactly as the evaluation will.
#pragma once

#include "figure/figure_eval.h"

#include <vector>

namespace taiwa::figure {

std::vector<Point2> circleCrossings(const Circle& a, const Circle& b);
std::vector<Point2> lineCircleCrossings(const Line& l, const Circle& c);

}  // namespace taiwa::figure
