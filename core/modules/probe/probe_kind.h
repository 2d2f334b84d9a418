// Internal to module PROBE: the pieces its door (probe_kind.cpp) puts
// together, and what they share: the touches entered, the probe, the fit.
#pragma once

#include "modules/module_kind.h"
#include "modules/probe/probe.h"
#include "modules/probe/probe_fit.h"

#include <variant>
#include <vector>

namespace taiwa {

// The touches entered, in order (the first at 0, 0).
std::vector<probe::Touch> touchesOf(const ProbeUnit& p);
// The unit's probe: its T, or the library's only tool of type probe; null when none (or several and no T).
const Tool* probeTool(const ProbeUnit& p, const std::vector<Tool>& library);
// The fit of the unit's touches (in mm) with its probe's ball: the
// workpiece's circle or rectangle, or why not.
using UnitFit = std::variant<probe::CircleFit, probe::RectangleFit, probe::FitProblem>;
UnitFit fitOf(const ProbeUnit& p, const std::vector<probe::Touch>& touches, const Tool& probe);

namespace check {
// Input checks of one PROBE unit (lengths in mm): probe_check.cpp.
UnitReport checkProbe(const ProbeUnit& mm, int unitNo, const Context& ctx);
}  // namespace check

// The probing page's figure (ModuleKind::sketch): probe_sketch.cpp.
Sketch probeSketch(const ProbeUnit& unit, LengthUnit shown, const std::vector<Tool>& library);

}  // namespace taiwa
