// Balanced roughing on a two-path lathe (seed 003; docs/two-path-lathe.md):
// a roughing step's explicit passes analysed into one command block per cut
// (approach, cut, retract, return), the blocks handed round-robin to the
// machine's paths, path 2's coordinates converted from path 1's, each
// block's infeed doubled after the first (each path skips the other's
// cuts), a wait M-code at the meeting points where the paths' cycles differ
// in length (or everywhere when asked), and the follower's dwell of at
// least half a spindle revolution computed from the spindle speed at the
// cut's diameter (under constant surface speed too).
#pragma once

#include "machine/machine.h"
#include "model/job.h"
#include "model/plan.h"
#include "model/result.h"
#include "model/two_path.h"

namespace taiwa::turning {

struct BalanceSettings {
    double dwellRevolutions = 1.0;  // the follower's delay behind the leader; at least 0.5
    bool waitsEverywhere = false;   // a wait at every meeting point, not only where the cycles differ
    // The paths meet before the first cut and after the last: the job's
    // other steps run on path 1 before and after the balanced roughing
    // (the export's programs); without it both programs start together.
    bool meetAtEnds = false;
    std::optional<int> firstWait;   // the first wait M-code (none: the machine's first)
};

// The job's two-path settings (Job::twoPath) as the balancing takes them,
// the paths meeting at the ends when `meetAtEnds` (the export's programs).
BalanceSettings balanceSettings(const TwoPathSettings& job, bool meetAtEnds);

// One block per cut of `path` (in path 1's coordinates, no waits or dwells
// yet, all on path 1) and what is left after the last cut (the tail).
struct AnalysedRoughing {
    std::vector<BalancedBlock> blocks;
    std::vector<TurnMove> tail;
    double stockLevel = 0.0;  // the radius the first cut's infeed is counted from
};
AnalysedRoughing analyseRoughing(const TurnPath& path);

// Whether an arc's sense (G2/G3) turns between path 1 and path `p`:
// exactly one of the axes mirrored.
bool flipsArcs(const MultiPath& mp, std::size_t p);

// The roughing `path` cut with `cutting` balanced between `machine`'s
// paths. Refused (a Failure naming the field): a machine of one path, a
// dwell below half a revolution, wait codes beyond the machine's range, a
// path with no cut.
Result<BalancedCut> balanceRoughing(const TurnPath& path, const TurnCutting& cutting, const Machine& machine,
                                    const BalanceSettings& settings = {});

// The plan's roughing step a two-path lathe balances (its first turning
// roughing step) and that step balanced as the export's programs have it
// (the job's settings, the paths meeting at the ends). planJob keeps it in
// Plan::balance, which the post, the two-path verification, the sheet and
// the station read. Nothing when the plan has no turning roughing step
// (each says so in its own words).
std::optional<PlannedBalance> balancePlanRoughing(const Plan& plan, const Machine& machine);

}  // namespace taiwa::turning
