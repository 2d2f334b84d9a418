// Planning steps shared by the pocket modules (M4, M2D): the tools of one
// unit's steps with the operator's pins, and the pilot hole handed to the
// roughing that plunges into it. Called from a module's door, never from the
// pipeline.
#pragma once

#include "modules/module_kind.h"

namespace taiwa {

// Chooses the tools of `steps` (one unit, decomposition order) in place;
// problems become diagnostics of the unit (field "tools"). Then tells every
// roughing step where the pilot hole is and how wide it was drilled.
void choosePocketTools(std::vector<Step>& steps, const ToolPins& pins, const UnitPlanContext& ctx, const char* module,
                       Diagnostics& out);

// The unit's own step-over (a fraction of D) to its roughing steps; the
// technology data's stays in force when the unit has none.
void setStepOver(std::vector<Step>& steps, std::optional<double> stepOver);

}  // namespace taiwa
