// The machine's own tool table from the library, for the control to load:
// LinuxCNC's tool table file (tool.tbl: T, pocket, diameter, for a turning
// tool the nose diameter and tip orientation) and a FANUC program that
// writes the offsets with G10 (cutter radius geometry L12 on a mill; on a
// lathe the nose radius R and imaginary tip Q of each tool's offset). Tool
// lengths are the machine's to measure: both say so and leave them at zero.
#pragma once

#include "model/job.h"
#include "model/tool.h"

#include <string>
#include <vector>

namespace taiwa {

// `units`: the machine's (LinuxCNC's table is in the machine's units).
std::string linuxcncToolTable(const std::vector<Tool>& tools, LengthUnit units);
std::string fanucOffsetProgram(const std::vector<Tool>& tools, LengthUnit units, int programNumber = 9000);

}  // namespace taiwa
