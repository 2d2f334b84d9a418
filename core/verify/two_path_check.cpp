// The two-path verification (two_path_check.h): balance, run the timeline,
// report deadlocks and short lags.
#include "verify/two_path_check.h"

#include "machine/machine.h"
#include "turning/balanced_roughing.h"
#include "verify/two_path_timeline.h"

#include <fmt/format.h>

namespace taiwa::verify {

Result<BalancedRoughing> balancedRoughing(const Plan& plan, const Machine& machine)
{
    auto balance = turning::balancePlanRoughing(plan, machine);
    if (!balance)
        return Failure{fmt::format("machine {} is a two-path lathe and the job has no roughing step to balance", plan.mmJob.machine)};
    if (!balance->cut) return Failure{"balanced cut: " + balance->cut.error()};
    return BalancedRoughing{std::move(*balance->cut), balance->step, balance->settings.dwellRevolutions};
}

std::optional<TwoPathCheck> checkTwoPath(const Plan& plan)
{
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || plan.steps.empty() || !machine || !machine->layout.multiPath) return std::nullopt;
    const auto balanced = balancedRoughing(plan, *machine);
    if (!balanced) return TwoPathCheck{{balanced.error()}};
    return checkTimeline(runTimeline(balanced->cut, *machine), balanced->dwellRevolutions);
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
