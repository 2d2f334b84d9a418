// The two-path verification (two_path_check.h): the plan's balanced roughing
// run on the timeline, its deadlocks and short lags reported.
#include "verify/two_path_check.h"

#include "machine/machine.h"
#include "verify/two_path_timeline.h"

#include <fmt/format.h>

namespace taiwa::verify {

std::optional<TwoPathCheck> checkTwoPath(const Plan& plan)
{
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || plan.steps.empty() || !machine || !machine->layout.multiPath) return std::nullopt;
    const std::optional<PlannedBalance>& balance = plan.balance;
    if (!balance)
        return TwoPathCheck{{fmt::format("machine {} is a two-path lathe and the job has no roughing step to balance",
                                         plan.mmJob.machine)}};
    if (!balance->cut) return TwoPathCheck{{"balanced cut: " + balance->cut.error()}};
    return checkTimeline(runTimeline(*balance->cut, *machine), plan.mmJob.twoPath.dwellRevolutions);
}

TwoPathCheck checkTimeline(const Timeline& t, double revolutions)
{
    TwoPathCheck out;
    out.seconds = t.seconds();
    out.leastLag = t.leastLag();
    for (const Deadlock& d : t.deadlocks)
        out.findings.push_back(fmt::format("two-path timeline: deadlock on path {} at M{}: {}", d.path + 1, d.waitCode, d.why));
    for (const CutLag& l : t.lags)
        if (l.revolutions < revolutions - 1e-6)
            out.findings.push_back(fmt::format("two-path timeline: CB{} follows CB{} {:.2f} revolutions behind, fewer than "
                                               "the set {:g}",
                                               l.follower, l.leader, l.revolutions, revolutions));
    return out;
}

}  // namespace taiwa::verify
