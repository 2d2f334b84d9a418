// Tool choice for a pocket unit's steps and the pilot hole handed to roughing.
#include "modules/pocket_plan.h"

#include "tools/tool_choice.h"

#include <algorithm>

namespace taiwa {

void choosePocketTools(std::vector<Step>& steps, const ToolPins& pins, const UnitPlanContext& ctx, const char* module,
                       Diagnostics& out)
{
    for (auto& problem : chooseTools(steps, pins, ctx.library, ctx.material))
        out.push_back({Severity::Error, ctx.unit + 1, module, "tools", std::move(problem)});

    // The roughing tool plunges into the pilot hole: tell the CL stage where
    // the hole is and how wide it was drilled.
    const auto pilot =
        std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.kind == StepKind::PilotHole; });
    if (pilot == steps.end() || !pilot->tool) return;
    const Tool* drill = findTool(ctx.library, pilot->tool->toolId);
    if (!drill) return;
    for (auto& s : steps) {
        if (s.kind != StepKind::Roughing) continue;
        s.holeDiameter = drill->diameter;
        s.position = pilot->position;
    }
}

void setStepOver(std::vector<Step>& steps, std::optional<double> stepOver)
{
    if (!stepOver) return;
    for (Step& s : steps)
        if (s.kind == StepKind::Roughing) s.stepOver = stepOver;
}

}  // namespace taiwa
