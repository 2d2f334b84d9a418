// A space curve divided into equal lengths, its refusals naming it as the
// caller does ("curve 1: …"): shared by the curves' and the ruled surfaces'
// files (surface_curves.cpp, surface_ruled.cpp). Internal to core/occt.
#pragma once

#include "occt/surface_curves.h"

#include <string>
#include <vector>

namespace taiwa::surface {

// The points dividing `curve` into `pieces` equal lengths (pieces + 1 of
// them), or why not, the reason starting with the curve's name (`which`:
// 1 "curve 1", 2 "curve 2", 0 "the curve"; curveRefusal).
Result<std::vector<Point3>> divideNamed(const SpaceCurve& curve, int pieces, int which);

}  // namespace taiwa::surface
