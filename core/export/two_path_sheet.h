// The instruction sheet's part for a job on a two-path lathe
// (docs/two-path-lathe.md "The sheet"): which path runs each step, and the
// balanced roughing on the timeline as a Gantt-style table, one column per
// path and one row per stretch of time in which no path changes what it
// does (a block's way in, its cut, its way out, a wait with its M-code), so
// that the waits stand side by side where the paths meet. Made here, above
// the sheet's layer, because it runs the timeline (verify/); the sheet lays
// the sections out (SheetOptions::paths). The station draws the same
// stretches of the same balanced roughing as a chart (ui/two_path_chart.h).
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "model/two_path.h"
#include "sheet/sheet.h"
#include "verify/two_path_timeline.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// The balanced roughing of a two-path job as the export writes it (the
// plan's, Plan::balance: the job's first roughing step, the job's two-path
// settings, the paths meeting at the ends) and its timeline.
struct BalancedRoughing {
    std::size_t step = 0;                    // the roughing step's index; plan.steps.size(): the job has none
    std::optional<Result<BalancedCut>> cut;  // none without a roughing step; a Failure: the balancing's refusal
    std::optional<Timeline> timeline;        // when the cut balances
    double onePathSeconds = 0.0;             // the same roughing on one path, by the same clock
};

// Nothing when the job's machine has one path (or the job is not a lathe's).
std::optional<BalancedRoughing> balancedRoughing(const Plan& plan);

// What a path does over [from, to) of a timeline: a block's way in (the
// approach, after a wait the dwell, the infeed), its cut, its way out, a
// wait held or met at once (from == to), the tail and the end wait.
struct TimelineStretch {
    enum Kind { In, Wait, Cut, Out, Tail };
    double from = 0.0, to = 0.0;
    Kind kind = In;
    int block = 0;       // CB number (0: the tail)
    int waitCode = 0;    // Wait
    double dwell = 0.0;  // In: the follower's dwell in it [s]
    std::string what;    // "CB3 in, dwell 0.120 s", "M102 wait", "CB3 cut", "CB3 out", "tail, end wait"
};
std::vector<TimelineStretch> timelineStretches(const Timeline& t, std::size_t path);

// Nothing when the job's machine has one path; else the "Paths" section
// and, when the roughing balances, the timeline's (a balancing refusal is
// said in the first section's note).
std::vector<sheet::Section> twoPathSheet(const Plan& plan);

// The Gantt-style table of a timeline: rows of [from, to) seconds, a cell
// per path ("CB3 cut", "M102 wait", "CB3 in, dwell 0.12 s", "CB3 out",
// "end wait", "-": done).
sheet::Table timelineTable(const Timeline& t, std::size_t paths);

}  // namespace taiwa
