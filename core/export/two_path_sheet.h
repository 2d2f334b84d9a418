// The instruction sheet's part for a job on a two-path lathe
// (docs/two-path-lathe.md "The sheet"): which path runs each step, and the
// balanced roughing on the timeline as a Gantt-style table, one column per
// path and one row per stretch of time in which no path changes what it
// does (a block's way in, its cut, its way out, a wait with its M-code), so
// that the waits stand side by side where the paths meet. Made here, above
// the sheet's layer, because it runs the timeline (verify/); the sheet lays
// the sections out (SheetOptions::paths).
#pragma once

#include "model/plan.h"
#include "sheet/sheet.h"
#include "verify/two_path_timeline.h"

#include <vector>

namespace taiwa {

// Nothing when the job's machine has one path; else the "Paths" section
// and, when the roughing balances, the timeline's (a balancing refusal is
// said in the first section's note).
std::vector<sheet::Section> twoPathSheet(const Plan& plan);

// The Gantt-style table of a timeline: rows of [from, to) seconds, a cell
// per path ("CB3 cut", "M102 wait", "CB3 in, dwell 0.12 s", "CB3 out",
// "end wait", "-": done).
sheet::Table timelineTable(const Timeline& t, std::size_t paths);

}  // namespace taiwa
