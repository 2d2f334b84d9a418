// Choosing among the library's lathe tools what the turning code needs
// before there are turning steps: the finishing tool whose nose radius is
// the grinding allowance's adjustment at tangent joints (seed 001).
#pragma once

#include "model/tool.h"

#include <vector>

namespace taiwa {

// The finishing turning tool for an outer (inside = false) or inner profile:
// among the turning inserts for that side, the one with the smallest
// non-zero nose radius (finishing inserts have the small radii); of equal
// radii, the lowest id. nullptr when the library has none.
const Tool* finishingTurningTool(const std::vector<Tool>& library, bool inside);

}  // namespace taiwa
