// A space curve divided into equal lengths, its refusals naming it as the
// caller does ("curve 1"): shared by the curves' and the ruled surfaces'
// files (surface_curves.cpp, surface_ruled.cpp). Internal to core/occt.
#pragma once

#include "occt/surface_curves.h"

#include <string>
#include <vector>

namespace taiwa::surface {

// The points dividing `curve` into `pieces` equal lengths (pieces + 1 of
// them), or why not, the reason starting with `name`.
Result<std::vector<Point3>> divideNamed(const SpaceCurve& curve, int pieces, const std::string& name);

}  // namespace taiwa::surface
