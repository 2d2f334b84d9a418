// planJob: the pipeline of spec/milling-modules.md end to end, headless.
// Input processing stops it; otherwise every unit is decomposed, its tools
// chosen, the steps of the whole job ordered, and each step given its path
// and time.
#include "pipeline/pipeline.h"

#include "check/input_check.h"
#include "decompose/decompose.h"
#include "tools/cutting.h"
#include "tools/tool_choice.h"

#include <algorithm>
#include <future>
#include <string>
#include <thread>

namespace taiwa {

const Tool* Plan::tool(int id) const
{
    const auto it = std::find_if(tools.begin(), tools.end(), [id](const Tool& t) { return t.id == id; });
    return it == tools.end() ? nullptr : &*it;
}

namespace {

const Tool* findTool(const std::vector<Tool>& library, int id)
{
    const auto it = std::find_if(library.begin(), library.end(), [id](const Tool& t) { return t.id == id; });
    return it == library.end() ? nullptr : &*it;
}

Diagnostic unitError(const Job& job, int unit, std::string field, std::string message)
{
    return {Severity::Error, unit + 1, moduleName(job.units[static_cast<std::size_t>(unit)].module), std::move(field),
            std::move(message)};
}

// Decomposes one unit and chooses its tools; problems become diagnostics.
std::vector<Step> planUnit(const Job& mmJob, int u, const TechnologyData& tech, const std::vector<Tool>& library,
                           Diagnostics& diagnostics)
{
    const auto& unit = mmJob.units[static_cast<std::size_t>(u)];
    std::vector<Step> steps;
    const ToolPins* pins = nullptr;
    if (const auto* m4 = std::get_if<M4Pocket>(&unit.module)) {
        steps = decomposeM4(*m4, tech, u);
        pins = &m4->tools;
    } else if (const auto* m2d = std::get_if<M2DPocket>(&unit.module)) {
        pins = &m2d->tools;
        double diameter = 0.0;
        if (const auto pin = m2d->tools.find(toKey(StepKind::Roughing)); pin != m2d->tools.end()) {
            if (const Tool* t = findTool(library, pin->second)) diameter = t->diameter;
        } else {
            const ToolPick pick = chooseM2DRoughingTool(*m2d, tech, library, mmJob.material);
            if (!pick.choice) {
                diagnostics.push_back(unitError(mmJob, u, "tools.roughing", pick.problem));
                return {};
            }
            diameter = findTool(library, pick.choice->toolId)->diameter;
        }
        steps = decomposeM2D(*m2d, tech, diameter, u);
    }
    for (const auto& problem : chooseTools(steps, *pins, library, mmJob.material))
        diagnostics.push_back(unitError(mmJob, u, "tools", problem));
    // The inclined-face passes must stop short of the vertical end walls'
    // corner rounding: give those steps the floor section (radius r1).
    if (const auto* m2d = std::get_if<M2DPocket>(&unit.module))
        for (auto& s : steps)
            if (s.kind == StepKind::InclinedFaceFinishing) s.outline = m2dCrossSection(*m2d, m2d->depth);

    // The roughing tool plunges into the pilot hole: tell the CL stage where
    // the hole is and how wide it was drilled.
    const auto pilot = std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.kind == StepKind::PilotHole; });
    if (pilot != steps.end() && pilot->tool) {
        const double drilled = findTool(library, pilot->tool->toolId)->diameter;
        for (auto& s : steps) {
            if (s.kind != StepKind::Roughing) continue;
            s.holeDiameter = drilled;
            s.position = pilot->position;
        }
    }
    return steps;
}

}  // namespace

Plan planJob(const Job& job, const TechnologyTable& table, const std::vector<Tool>& library, const PlanOptions& options)
{
    Plan plan;
    plan.job = job;
    plan.mmJob = toMillimetres(job);
    plan.diagnostics = checkJob(job, table, library);
    if (!plan.ok()) return plan;
    plan.technology = *jobTechnology(plan.mmJob, table);
    plan.unitOrder = machiningOrder(plan.mmJob);

    std::vector<Step> unordered;
    for (const int u : plan.unitOrder) {
        auto steps = planUnit(plan.mmJob, u, plan.technology, library, plan.diagnostics);
        unordered.insert(unordered.end(), std::make_move_iterator(steps.begin()), std::make_move_iterator(steps.end()));
    }
    if (!plan.ok()) return plan;

    for (const int i : orderSteps(unordered)) plan.steps.push_back(std::move(unordered[static_cast<std::size_t>(i)]));

    int currentTool = 0;
    for (const auto& step : plan.steps) {
        const Tool& tool = *findTool(library, step.tool->toolId);
        if (!plan.tool(tool.id)) plan.tools.push_back(tool);
        if (tool.id != currentTool) ++plan.toolChanges;
        currentTool = tool.id;
        if (options.withToolPaths && !speedsFeeds(tool, plan.mmJob.material))
            plan.diagnostics.push_back(unitError(plan.mmJob, step.unit, "tools." + std::string(toKey(step.kind)),
                "tool T" + std::to_string(tool.id) + " (" + tool.name + ") has no cutting data for material " +
                    plan.mmJob.material + "; add it in the tool library"));
    }
    if (!plan.ok() || !options.withToolPaths) return plan;

    // The paths of the steps are independent of each other: compute them on
    // every core.
    const auto work = [&](std::size_t first, std::size_t stride) {
        for (std::size_t i = first; i < plan.steps.size(); i += stride) {
            Step& step = plan.steps[i];
            const Tool& tool = *findTool(library, step.tool->toolId);
            step.path = makeToolPath(step, tool, plan.technology, options.path);
            step.minutes = estimateMinutes(*step.path, *speedsFeeds(tool, plan.mmJob.material));
        }
    };
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    std::vector<std::future<void>> running;
    for (std::size_t t = 1; t < threads; ++t) running.push_back(std::async(std::launch::async, work, t, threads));
    work(0, threads);
    for (auto& r : running) r.get();  // rethrows a worker's exception here
    for (const auto& step : plan.steps) plan.totalMinutes += *step.minutes;
    plan.totalMinutes += plan.toolChanges * options.toolChangeSeconds / 60.0;
    for (const auto& note : planToolLife(plan.steps, library)) plan.notes.push_back(note.message);
    return plan;
}

}  // namespace taiwa
