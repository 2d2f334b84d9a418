// taiwa verify of a job whose machine is a two-path lathe
// (docs/two-path-lathe.md "Verify"): the job's first roughing step balanced
// as the export writes it (the job's dwell and waits settings, meeting at
// the ends) and run on the timeline; a deadlock, or a follower closer than
// the set revolutions behind its leader, is a finding.
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "model/two_path.h"
#include "verify/two_path_timeline.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {
struct Machine;  // machine/machine.h
}  // namespace taiwa

namespace taiwa::verify {

struct TwoPathCheck {
    std::vector<std::string> findings;  // one sentence each; empty: clean
    double seconds = 0.0;               // the balanced roughing on the timeline
    double leastLag = 0.0;              // revolutions
};

// The job's first roughing step balanced as the export balances it (the
// job's dwell and waits settings, meeting at the ends): the cut, the step's
// index, the revolutions the follower keeps; or why not (no roughing step, a
// balancing refusal).
struct BalancedRoughing {
    BalancedCut cut;
    std::size_t step = 0;
    double dwellRevolutions = 0.0;
};
Result<BalancedRoughing> balancedRoughing(const Plan& plan, const Machine& machine);

// Nothing when the job's machine has one path or the job has no steps.
std::optional<TwoPathCheck> checkTwoPath(const Plan& plan);

// The findings of a timeline: its deadlocks, and every lag below `revolutions`.
TwoPathCheck checkTimeline(const Timeline& t, double revolutions);

}  // namespace taiwa::verify
