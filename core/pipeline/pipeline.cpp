// planJob: the pipeline of spec/milling-modules.md end to end, headless.
// Input processing stops it; otherwise every unit is planned through its
// module's door (decomposition and tool choice), the steps of the whole job
// ordered, and each step given its path and time.
#include "pipeline/pipeline.h"
#include "pipeline/plan_cache.h"

#include "machine/motion_time.h"

#include "job/job_check.h"
#include "machine/machine.h"
#include "modules/registry.h"
#include "tools/cutting.h"
#include "tools/step_order.h"
#include "turning/balanced_roughing.h"
#include "model/turn_path.h"

#include <fmt/format.h>

#include <algorithm>
#include <future>
#include <string>
#include <thread>
#include <tuple>
#include <utility>

namespace taiwa {

namespace {

Diagnostic unitError(const Job& job, int unit, std::string field, std::string message)
{
    return {Severity::Error, unit + 1, job.units[static_cast<std::size_t>(unit)].module.name(), std::move(field),
            std::move(message)};
}

// One unit through its module's door; a turning unit's deformed profile
// first: its steps cut it. `checked`: the one its check made, else the
// door makes it.
UnitPlan planUnit(const Plan& plan, int u, const std::vector<Tool>& library, const Machine* machine,
                  const std::optional<TurnedPart>* checked)
{
    UnitPlan r;
    const ModuleInput& module = plan.mmJob.units[static_cast<std::size_t>(u)].module;
    UnitPlanContext ctx{plan.technology, library, plan.mmJob.material, u, &plan.mmJob, machine, plan.job.lengthUnit};
    std::optional<TurnedPart> part = checked && *checked ? **checked : moduleKind(module).turned(module, ctx);
    if (part) ctx.turned = &*part;
    r.steps = moduleKind(module).plan(module, ctx, r.diagnostics);
    if (auto setup = moduleKind(module).setup(module, ctx)) {
        setup->workOffset = plan.job.workOffset;
        r.setup = std::move(*setup);
    }
    if (part) {
        part->name = plan.job.units[static_cast<std::size_t>(u)].name;
        r.turned = std::move(*part);
    }
    return r;
}

// Rearranges `steps` so that step k is the one at order[k] before (order
// being a permutation), moving each step once along the permutation's
// cycles instead of into a second vector.
void putInOrder(std::vector<Step>& steps, std::vector<int> order)
{
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (static_cast<std::size_t>(order[k]) == k) continue;
        Step held = std::move(steps[k]);
        std::size_t at = k;
        for (;;) {
            const auto from = static_cast<std::size_t>(order[at]);
            order[at] = static_cast<int>(at);  // in place now
            if (from == k) {
                steps[at] = std::move(held);
                break;
            }
            steps[at] = std::move(steps[from]);
            at = from;
        }
    }
}

// Each unit through its module's door (decomposition, tool choice and
// whatever the module settles between them), the steps of the whole job in
// order, the operator's S and F by step key.
void planSteps(Plan& plan, const std::vector<Tool>& library, const PathParameters& params, const Machine* machine,
               PlanCache* cache, const std::vector<std::optional<TurnedPart>>& checkedTurned)
{
    std::vector<Step> unordered;
    unordered.reserve(plan.mmJob.units.size() * 4);  // most units have a few steps
    TextPool reasons;
    if (cache) cache->begin(plan, library, params);
    for (const int u : plan.unitOrder) {
        const auto at = static_cast<std::size_t>(u);
        const auto compute = [&] {
            return planUnit(plan, u, library, machine, at < checkedTurned.size() ? &checkedTurned[at] : nullptr);
        };
        UnitPlan fresh;
        const UnitPlan& done = cache ? cache->unit(plan, u, library, compute) : (fresh = compute());
        plan.diagnostics.insert(plan.diagnostics.end(), done.diagnostics.begin(), done.diagnostics.end());
        if (done.setup) plan.setups.push_back(*done.setup);
        if (done.turned) plan.turned.push_back(*done.turned);
        const std::size_t first = unordered.size();
        if (cache) unordered.insert(unordered.end(), done.steps.begin(), done.steps.end());
        else unordered.insert(unordered.end(), std::make_move_iterator(fresh.steps.begin()), std::make_move_iterator(fresh.steps.end()));
        // Alike units give their steps the same reasons: each sentence kept once.
        for (std::size_t i = first; i < unordered.size(); ++i)
            if (unordered[i].tool) reasons.share(unordered[i].tool->reason);
    }
    std::sort(plan.setups.begin(), plan.setups.end(), [](const WorkSetup& a, const WorkSetup& b) { return a.unit < b.unit; });
    std::sort(plan.turned.begin(), plan.turned.end(), [](const TurnedPart& a, const TurnedPart& b) { return a.unit < b.unit; });
    if (!plan.ok()) return;

    // The steps are put in order where they are: a second vector of them
    // would double the peak of a large job (100,000 pocket units make some
    // 390,000 steps).
    plan.steps = std::move(unordered);
    if (plan.mmJob.bar) {
        // A bar is cut in the order of the steps' kinds (facing, drilling,
        // roughing, finishing, grooving, parting off), units in turn within
        // each: every unit's roughing before any finishing.
        std::stable_sort(plan.steps.begin(), plan.steps.end(), [&](const Step& a, const Step& b) {
            return std::tuple(static_cast<int>(a.kind), a.unit) < std::tuple(static_cast<int>(b.kind), b.unit);
        });
    } else {
        putInOrder(plan.steps, orderSteps(plan.steps));
    }

    // The operator's speeds and feeds, by step key: a milling step's go into
    // the speeds and feeds bound below (stepSpeedsFeeds); a turning step's
    // cutting data has them already (turn_plan).
    for (auto& step : plan.steps) {
        const auto& cutting = plan.mmJob.units[static_cast<std::size_t>(step.unit)].cutting;
        if (const auto it = cutting.find(toKey(step.kind)); it != cutting.end()) step.cutting = it->second;
    }
}

// Each step bound once to its tool entry (the plan's own copy: a library
// edited after planning changes nothing posted from it) and to its speeds
// and feeds; the tool entry of each step, by index, for the paths.
std::vector<const Tool*> bindTools(Plan& plan, const std::vector<Tool>& library, bool withToolPaths)
{
    int currentTool = 0;
    std::vector<const Tool*> toolOf(plan.steps.size(), nullptr);
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        Step& step = plan.steps[i];
        const Tool& tool = *findTool(library, step.tool->toolId);
        toolOf[i] = &tool;
        if (!plan.tool(tool.id)) plan.tools.push_back(tool);
        if (tool.id != currentTool) ++plan.toolChanges;
        currentTool = tool.id;
        if (turnOf(step)) continue;
        // The automatic S and F within the job's machine (docs/tools.md).
        const Machine* machine = findMachine(plan.mmJob.machine);
        step.speeds = machine ? stepSpeedsFeeds(step, tool, plan.mmJob.material, machine->maxSpindleSpeed, machine->maxFeed)
                              : stepSpeedsFeeds(step, tool, plan.mmJob.material);
        if (withToolPaths && !step.speeds)
            plan.diagnostics.push_back(unitError(plan.mmJob, step.unit, "tools." + std::string(toKey(step.kind)),
                "tool T" + std::to_string(tool.id) + " (" + tool.name + ") has no cutting data for material " +
                    plan.mmJob.material + "; add it in the tool library"));
    }
    return toolOf;
}

// The budget: estimated before any path is computed (each step's moves
// weighed by what its module's moves cost: estimateWork), so that no job can
// exhaust the memory (the checks' ranges bound every step; this bounds the
// job). It is part of input processing: `taiwa check` (a plan without paths)
// refuses what export would. False, with the diagnostic on the unit with the
// most moves and the field its door says drives them, when the paths would
// not fit it.
bool withinMoveBudget(Plan& plan, const std::vector<const Tool*>& toolOf, const PathParameters& params)
{
    double estimated = 0.0;
    std::vector<double> perUnit(plan.mmJob.units.size(), 0.0);
    std::vector<double> biggestStep(plan.mmJob.units.size(), -1.0);
    std::vector<std::size_t> biggestStepOf(plan.mmJob.units.size(), 0);
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& step = plan.steps[i];
        const double moves = estimateWork(step, *toolOf[i], plan.technology, params);
        estimated += moves;
        const auto u = static_cast<std::size_t>(step.unit);
        perUnit[u] += moves;
        if (moves > biggestStep[u]) biggestStep[u] = moves, biggestStepOf[u] = i;
    }
    if (estimated <= kMaxPlanMoves) return true;
    const auto biggest = static_cast<std::size_t>(std::max_element(perUnit.begin(), perUnit.end()) - perUnit.begin());
    const ModuleInput& unit = plan.mmJob.units[biggest].module;
    const ModuleKind& kind = moduleKind(unit);
    const std::string field = kind.movesField(unit, plan.steps[biggestStepOf[biggest]]);
    const std::string weighed =
        kind.workPerMove() == 1.0 ? "" : fmt::format("; each of this unit's counts as {:g}", kind.workPerMove());
    plan.diagnostics.push_back(unitError(
        plan.mmJob, static_cast<int>(biggest), field,
        fmt::format("the tool paths would hold about {:.3g} moves ({:.3g} of them this unit's{}), more than the "
                    "{:.3g} a job may have; make the job smaller, the allowances or the depth of cut (γ) larger",
                    estimated, perUnit[biggest], weighed, kMaxPlanMoves)));
    return false;
}

// The paths of the steps and their times. They are independent of each
// other: those the cache does not have are computed on every core (at most
// kMaxPathThreads).
void makePaths(Plan& plan, const std::vector<const Tool*>& toolOf, const PathParameters& params, const Machine* machine,
               PlanCache* cache)
{
    const bool motion = machine && hasMotionModel(*machine);
    std::vector<std::size_t> todo;
    todo.reserve(plan.steps.size());
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        Step& step = plan.steps[i];
        if (turnOf(step)) {  // turning steps come with their paths and plain times
            if (motion) step.machineMinutes = turnMachineMinutes(*turnOf(step), *machine);
            continue;
        }
        if (const StepPath* known = cache ? cache->findPath(step) : nullptr) {
            step.path = known->path;
            step.minutes = known->minutes;
            step.machineMinutes = known->machineMinutes;
            continue;
        }
        todo.push_back(i);
    }
    const auto work = [&](std::size_t first, std::size_t stride) {
        for (std::size_t t = first; t < todo.size(); t += stride) {
            Step& step = plan.steps[todo[t]];
            step.path = makeToolPath(step, *toolOf[todo[t]], plan.technology, params);
            const SpeedsFeeds sf = *step.speeds;
            step.minutes = estimateMinutes(*step.path, sf);
            if (motion) step.machineMinutes = machineMinutes(*step.path, {sf.feed, sf.plungeFeed}, *machine);
        }
    };
    const std::size_t threads =
        std::clamp<std::size_t>(std::min<std::size_t>(std::thread::hardware_concurrency(), todo.size()), 1, kMaxPathThreads);
    std::vector<std::future<void>> running;
    for (std::size_t t = 1; t < threads; ++t) running.push_back(std::async(std::launch::async, work, t, threads));
    work(0, threads);
    for (auto& r : running) r.get();  // rethrows a worker's exception here
    if (cache) {
        for (const std::size_t i : todo) {
            const Step& step = plan.steps[i];
            cache->keepPath(step, {*step.path, *step.minutes, step.machineMinutes});
        }
        cache->end();
    }
}

// The job's times (tool changes included) and the tool-life warnings.
void addTimes(Plan& plan, const std::vector<Tool>& library, const PlanOptions& options, const Machine* machine)
{
    for (const auto& step : plan.steps) plan.totalMinutes += *step.minutes;
    plan.totalMinutes += plan.toolChanges * options.toolChangeSeconds / 60.0;
    const bool motion = machine && hasMotionModel(*machine);
    if (motion && std::all_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return s.machineMinutes.has_value(); })) {
        double total = plan.toolChanges * options.toolChangeSeconds / 60.0;
        for (const auto& step : plan.steps) total += *step.machineMinutes;
        plan.totalMachineMinutes = total;
    }
    // Tool life: a warning on the step's unit, not an error.
    for (const auto& note : planToolLife(plan.steps, library)) {
        const Step& step = plan.steps[static_cast<std::size_t>(note.stepIndex)];
        Diagnostic d = unitError(plan.mmJob, step.unit, "tools." + std::string(toKey(step.kind)), note.message);
        d.severity = Severity::Warning;
        plan.diagnostics.push_back(std::move(d));
    }
}

}  // namespace

Plan planJob(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options)
{
    return planJob(std::move(checked), library, options, nullptr);
}

Plan planJob(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options, PlanCache* cache)
{
    Plan plan;
    plan.job = std::move(checked.job);
    plan.mmJob = std::move(checked.mmJob);
    plan.diagnostics = std::move(checked.diagnostics);
    if (!plan.ok()) return plan;
    plan.technology = *checked.technology;
    plan.unitOrder = machiningOrder(plan.mmJob);
    const Machine* machine = findMachine(plan.mmJob.machine);
    planSteps(plan, library, options.path, machine, cache, checked.turned);
    if (!plan.ok()) return plan;
    const std::vector<const Tool*> toolOf = bindTools(plan, library, options.withToolPaths);
    if (!plan.ok() || !withinMoveBudget(plan, toolOf, options.path) || !options.withToolPaths) return plan;
    makePaths(plan, toolOf, options.path, machine, cache);
    addTimes(plan, library, options, machine);
    if (plan.mmJob.bar && machine && machine->layout.multiPath) plan.balance = turning::balancePlanRoughing(plan, *machine);
    return plan;
}

PostOptions postOptions(const Plan& plan, const std::string& dialect, std::optional<LengthUnit> units, int programNumber,
                        const std::string& fileStem)
{
    PostOptions post;
    post.dialect = dialect;
    post.units = units.value_or(plan.job.lengthUnit);
    post.programNumber = programNumber;
    post.programName = plan.job.name.empty() ? fileStem : plan.job.name;
    post.fileStem = fileStem;
    post.material = plan.mmJob.material;
    post.machine = plan.job.machine;
    post.workOffset = plan.job.workOffset;
    for (const auto& u : plan.job.units) post.unitNames.push_back(u.name);
    if (!plan.mmJob.bar) {
        const Stock& s = plan.mmJob.stock;
        post.hasStock = true;
        post.stockMin = {s.x, s.y, -s.height};
        post.stockMax = {s.x + s.width, s.y + s.length, 0.0};
    }
    if (plan.mmJob.bar) {
        // Clear of the bar for the turret to index: 25 mm above it and 50 mm in front of its face.
        post.latheChangeX = plan.mmJob.bar->diameter + 50.0;
        post.latheChangeZ = plan.mmJob.bar->face + 50.0;
        post.turningCycles = plan.mmJob.latheRoughingCycles;
    }
    return post;
}

Plan planJob(Job job, const TechnologyTable& table, const std::vector<Tool>& library, const PlanOptions& options)
{
    return planJob(checkedJob(std::move(job), table, library), library, options);
}

}  // namespace taiwa
