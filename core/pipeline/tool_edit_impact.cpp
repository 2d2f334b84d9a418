// The steps a tool library edit changes (tool_edit_impact.h).
#include "pipeline/tool_edit_impact.h"

#include "pipeline/pipeline.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace taiwa {

namespace {

auto keyOf(const Step& s) { return std::tuple{s.unit, s.kind, s.number}; }

std::optional<int> toolOf(const Step& s)
{
    return s.tool ? std::optional<int>(s.tool->toolId) : std::nullopt;
}

}  // namespace

ToolEditImpact toolEditImpact(const Job& job, const std::vector<Tool>& before, const std::vector<Tool>& after)
{
    PlanOptions stepsOnly;
    stepsOnly.withToolPaths = false;
    const Plan was = planJob(job, TechnologyTable::builtIn(), before, stepsOnly);
    const Plan will = planJob(job, TechnologyTable::builtIn(), after, stepsOnly);
    ToolEditImpact impact;
    for (const Diagnostic& d : will.diagnostics)
        if (d.severity == Severity::Error && std::find(was.diagnostics.begin(), was.diagnostics.end(), d) == was.diagnostics.end())
            impact.refusals.push_back(d);
    std::map<decltype(keyOf(Step{})), std::size_t> wasAt;
    for (std::size_t k = 0; k < was.steps.size(); ++k) wasAt.emplace(keyOf(was.steps[k]), k);
    std::vector<bool> matched(was.steps.size(), false);
    for (const Step& s : will.steps) {
        StepToolChange c{s, std::nullopt, toolOf(s)};
        if (const auto it = wasAt.find(keyOf(s)); it != wasAt.end()) {
            matched[it->second] = true;
            c.before = toolOf(was.steps[it->second]);
        }
        if (c.before == c.after) {
            // The tool entries each plan bound (Plan::tool), compared whole.
            const Tool* a = c.before ? was.tool(*c.before) : nullptr;
            const Tool* b = c.after ? will.tool(*c.after) : nullptr;
            c.toolEdited = (a == nullptr) != (b == nullptr) || (a && b && !(*a == *b));
            if (!c.toolEdited) continue;
        }
        impact.steps.push_back(std::move(c));
    }
    // Steps the edit leaves out (a step whose only tool was retired).
    for (std::size_t k = 0; k < was.steps.size(); ++k)
        if (!matched[k]) impact.steps.push_back({was.steps[k], toolOf(was.steps[k]), std::nullopt});
    return impact;
}

}  // namespace taiwa
