// Tool choice for a pocket unit's steps, the pilot hole handed to roughing,
// and the step hooks of the pocket modules' doors.
#include "modules/pocket_plan.h"

#include "paths/generators.h"

#include "modules/inclined_face.h"
#include "modules/pocket_tools.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
    const Point2 at = millingOf(*pilot).position;
    for (auto& s : steps) {
        if (s.kind != StepKind::Roughing) continue;
        MillingGeometry& g = editMilling(s);
        g.holeDiameter = drill->diameter;
        g.position = at;
    }
}

void setStepOver(std::vector<Step>& steps, std::optional<double> stepOver)
{
    if (!stepOver) return;
    for (Step& s : steps)
        if (s.kind == StepKind::Roughing) editMilling(s).stepOver = stepOver;
}

namespace {

void requirePositiveGamma(const TechnologyData& tech)
{
    if (!(tech.gamma > 0.0)) throw std::logic_error("gamma must be positive");
}

// Rank of a step within its unit: the pilot hole, then roughing, then the
// finishing steps.
int rank(const Step& s)
{
    switch (s.kind) {
    case StepKind::PilotHole: return 0;
    case StepKind::Roughing: return 1;
    default: return 2;
    }
}

}  // namespace

ToolPath pocketToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    if (millingOf(step).region) {
        switch (step.kind) {
        case StepKind::Roughing: requirePositiveGamma(tech); return paths::regionRoughing(step, tool, tech, params);
        case StepKind::FloorFinishing: return paths::regionFloorFinishing(step, tool, tech, params);
        case StepKind::WallFinishing: return paths::regionWallFinishing(step, tool, tech, params);
        default: break;
        }
    }
    switch (step.kind) {
    case StepKind::PilotHole: return paths::pilotHole(step, tool, params);
    case StepKind::Roughing: requirePositiveGamma(tech); return paths::pocketRoughing(step, tool, tech, params);
    case StepKind::FloorFinishing: return paths::floorFinishing(step, tool, params);
    case StepKind::WallFinishing: return paths::wallFinishing(step, tool, tech, params);
    case StepKind::InclinedFaceFinishing: return inclinedFacePath(step, tool, params);
    default: break;
    }
    throw std::logic_error("no pocket tool path for step " + step.label());
}

double pocketEstimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    const MillingGeometry& g = millingOf(step);
    const double layers = estimatedLayers(step, tool, tech);
    const double rings = estimatedRings(step, tool, tech, params);
    if (g.region) {  // a ring of a contour has about as many moves as the flattened region has points
        double points = static_cast<double>(flatten(g.region->outer, 1e-4).size());
        for (const auto& i : g.region->islands) points += static_cast<double>(flatten(i, 1e-4).size());
        if (step.kind == StepKind::Roughing) return layers * rings * points;
        if (step.kind == StepKind::FloorFinishing) return rings * points;
        if (step.kind == StepKind::WallFinishing) {  // exact lines and arcs: about two moves a segment, a lead each loop
            double segments = static_cast<double>(g.region->outer.segments.size());
            for (const auto& i : g.region->islands) segments += static_cast<double>(i.segments.size()) + 6;
            return (g.multiIncision ? layers : 1) * (2 * segments + 10);
        }
    }
    constexpr double kMovesPerRing = 12;  // four sides, four corners, links
    switch (step.kind) {
    case StepKind::PilotHole: return 10;
    case StepKind::Roughing: return layers * rings * kMovesPerRing;
    case StepKind::FloorFinishing: return rings * kMovesPerRing * 2;
    case StepKind::WallFinishing: return (g.multiIncision ? layers : 1) * kMovesPerRing + 10;
    case StepKind::InclinedFaceFinishing: return inclinedFaceMoves(step, tool);
    default: return 10;
    }
}

bool pocketStepWaitsFor(const Step& later, const Step& earlier)
{
    if (rank(earlier) < rank(later)) return true;
    // Roughing layers in order; wall passes (semi-finish, middle, final) in order.
    return later.kind == earlier.kind && (later.kind == StepKind::Roughing || later.kind == StepKind::WallFinishing) &&
           earlier.number < later.number;
}

}  // namespace taiwa
