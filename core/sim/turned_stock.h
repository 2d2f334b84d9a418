// The bar's half-section as the turning steps leave it (issue: the stock
// after each step of a lathe job, exact in 2-D): the bar minus what each
// step's tool sweeps, the insert as its nose circle and the edge above it
// (the chip), a blade as its
// rectangle, a drill as its body on the axis; the finishing contour (run
// with nose-radius compensation) takes off everything within 3 mm (or two
// nose radii) outside it. Clipper on the core's 0.1 µm grid, arcs flattened within 2 µm.
#pragma once

#include "model/plan.h"
#include "model/turned.h"

#include <vector>

namespace taiwa::sim {

// Closed loops in (z, r), even-odd; empty for a job without a bar. `last`:
// the index of the last step cut (-1: the bar as it is clamped).
std::vector<std::vector<turning::ZR>> turnedStockAfter(const Plan& plan, int last);

// Area of such loops [mm²] (holes counted negative).
double loopsArea(const std::vector<std::vector<turning::ZR>>& loops);

}  // namespace taiwa::sim
