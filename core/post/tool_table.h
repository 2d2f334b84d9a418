// The machine's own tool table from the library, for the control to load:
// LinuxCNC's tool table file (tool.tbl: T, pocket, diameter, for a turning
// tool the nose diameter and tip orientation) and a FANUC program that
// writes the offsets with G10 (cutter radius geometry L12 on a mill; on a
// lathe the nose radius R and imaginary tip Q of each tool's offset). Tool
// lengths are the machine's to measure: both say so and leave them at zero.
// And a lathe tape's own table (STEM.tbl, exported beside a LinuxCNC lathe
// tape): its turret stations with their nose diameters and orientations.
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/tool.h"

#include <string>
#include <vector>

namespace taiwa {

// `units`: the machine's (LinuxCNC's table is in the machine's units).
std::string linuxcncToolTable(const std::vector<Tool>& tools, LengthUnit units);
std::string fanucOffsetProgram(const std::vector<Tool>& tools, LengthUnit units, int programNumber = 9000);

// The tool table a LinuxCNC lathe tape runs with (docs/turning.md "The
// tape"): one line per turret station the tape calls (T1 M6 G43 …,
// latheStations), `T<station> P<station> X0 Z0 D<nose diameter> Q<tip
// orientation> ;library T<id> <name>`, the orientation the tape's header
// gives (the steps'), a drill's D 0. In inches: the unit LinuxCNC's
// interpreter reads a tool table in when no machine configuration says
// otherwise (rs274 -t), whatever the tape's G20/G21; the first line says so.
// `orderedSteps`: the tape's turning steps in machining order; `planTools`:
// the plan's own tools they were bound to (post/bound_tool.h).
std::string linuxcncLatheToolTable(const std::vector<Step>& orderedSteps, const std::vector<Tool>& planTools,
                                   const std::string& stem);

}  // namespace taiwa
