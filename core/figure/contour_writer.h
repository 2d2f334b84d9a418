// One contour written as figure definitions (figure_from_contours.h): its
// points, circles and lines (tangent junctions as TANTO, so that they stay
// one point whatever the rounding), the modifiers that choose each junction,
// and its CONTOUR statement. Internal to core/figure/.
#pragma once

#include "figure/contour_names.h"
#include "figure/figure_text.h"
#include "model/contour.h"

#include <vector>

namespace taiwa::figure {

// The contour's definitions in order: points, circles, lines, CONTOUR, every
// number to the nearest 1/scale mm (scale a power of ten). Throws Refusal
// (model/result.h) for a contour that cannot be written so: no segments, a
// closed contour of one line, beyond the text's reach, a radius that rounds
// to nothing, junctions that no longer meet or that no modifier can choose.
std::vector<Definition> contourDefinitions(Namer& names, const Contour& c, double scale);

}  // namespace taiwa::figure
