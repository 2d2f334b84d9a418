// Every program of an export posted once (posted_job.h).
#include "post/posted_job.h"

#include "machine/machine.h"
#include "model/translate_noop.h"
#include "model/turn_path.h"
#include "post/probe_program.h"
#include "post/two_path_post.h"

#include <fmt/format.h>

#include <utility>

namespace taiwa {

std::optional<Result<PostedTwoPath>> postTwoPath(const Plan& plan, const PostOptions& post)
{
    using Posted = Result<PostedTwoPath>;
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || plan.steps.empty() || !machine || !machine->layout.multiPath) return std::nullopt;
    // Path 1 faces before and finishes after the balanced roughing: the paths meet at the ends.
    const std::optional<PlannedBalance>& balance = plan.balance;
    if (!balance)
        return Posted{Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "machine: {} is a two-path lathe and the job has no "
                                                                             "roughing step to balance between its paths"),
                                          plan.mmJob.machine)}};
    if (!balance->cut) return Posted{Failure{balance->cut.error()}};
    const std::size_t index = balance->step;
    PostedTwoPath out{*balance->cut, index, {}};
    try {
        out.programs = postBalancedCut(out.cut, plan.steps, index, *machine->layout.multiPath, plan.tools, post);
    } catch (const Refusal& e) {
        return Posted{Failure{e.what()}};
    }
    return Posted{std::move(out)};
}

std::vector<PostedProbing> postProbing(const Plan& plan, const PostOptions& post, const post::Dialect& dialect)
{
    // The O-numbers after the tape's, one for each program.
    int next = post.programNumber;
    PostOptions o = post;
    o.units = LengthUnit::Millimetre;
    std::vector<PostedProbing> out;
    try {
        for (const WorkSetup& w : plan.setups) {
            PostedProbing p;
            p.unit = w.unit;
            if (w.measured) {
                o.programNumber = (next++) % 9999 + 1;
                p.setting = settingProgram(w, o, dialect);
            }
            o.programNumber = (next++) % 9999 + 1;
            p.probe = probingProgram(w, o, dialect);
            out.push_back(std::move(p));
        }
    } catch (const Refusal&) {
        return {};  // a dialect that writes no probing programs
    }
    return out;
}

PostedJob postJob(const Plan& plan, const PostOptions& post)
{
    return postJob(plan, post, postProcess(plan.steps, plan.tools, post), post::dialectNamed(post.dialect));
}

PostedJob postJob(const Plan& plan, const PostOptions& post, PostedProgram tape, const post::Dialect& dialect)
{
    PostedJob job;
    job.tape = std::move(tape);
    job.twoPath = postTwoPath(plan, post);
    if (!plan.setups.empty()) job.probing = postProbing(plan, post, dialect);
    return job;
}

}  // namespace taiwa
