// Process decomposition (pipeline stage 3, first half): each module's final
// shape into its ordered process steps, exactly as spec/milling-modules.md
// says. Inputs are in mm and already checked; tools and paths are not chosen
// here (Step::tool, path and minutes stay empty).
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"

#include <vector>

namespace taiwa {

// M4 (2.5-D pocket). `unit` is the 0-based unit index stored in each step.
std::vector<Step> decomposeM4(const M4Pocket& pocket, const TechnologyData& tech, int unit);

// M2D (geometric 3-D pocket). The roughing layer count depends on the
// roughing tool's diameter D: n = round-half-up((T - beta2) / (gamma * D)).
std::vector<Step> decomposeM2D(const M2DPocket& pocket, const TechnologyData& tech, double roughingToolDiameter,
                               int unit);

// M2D geometry: the pocket's cross-section at a depth (vertical corners keep r1).
Quad m2dCrossSection(const M2DPocket& pocket, double depth);

}  // namespace taiwa
