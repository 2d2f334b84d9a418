// taiwa verify of a job whose machine is a two-path lathe
// (docs/two-path-lathe.md "Verify"): the job's first roughing step balanced
// as the export writes it (the job's dwell and waits settings, meeting at
// the ends) and run on the timeline; a deadlock, or a follower closer than
// the set revolutions behind its leader, is a finding.
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

// Nothing when the job's machine has one path or the job has no steps.
std::optional<TwoPathCheck> checkTwoPath(const Plan& plan);

// The findings of a timeline: its deadlocks, and every lag below `revolutions`.
TwoPathCheck checkTimeline(const Timeline& t, double revolutions);

}  // namespace taiwa::verify
