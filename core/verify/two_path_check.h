// taiwa verify of a job whose machine is a two-path lathe
// (docs/two-path-lathe.md "Verify"): the plan's balanced roughing
// (Plan::balance, as the export writes it: the job's dwell and waits
// settings, meeting at the ends) run on the timeline; a deadlock, or a
// follower closer than the set revolutions behind its leader, is a finding.
#pragma once

#include "model/plan.h"
#include "verify/two_path_timeline.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::verify {

struct TwoPathCheck {
    std::vector<std::string> findings;  // one sentence each; empty: clean
    double seconds = 0.0;               // the balanced roughing on the timeline
    double leastLag = 0.0;              // revolutions
};

// Nothing when the job's machine has one path or the job has no steps; a
// plan from planJob with its tool paths (the balance is made with them).
// No roughing step or a balancing refusal is the one finding.
std::optional<TwoPathCheck> checkTwoPath(const Plan& plan);

// The findings of a timeline: its deadlocks, and every lag below `revolutions`.
TwoPathCheck checkTimeline(const Timeline& t, double revolutions);

}  // namespace taiwa::verify
