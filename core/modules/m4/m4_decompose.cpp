// Process decomposition of module M4 (2.5-D pocket, optionally with tapered
// walls): pilot hole, one roughing step, floor finishing and the wall
// finishing steps of code F, as spec/milling-modules.md and
// docs/decomposition.md describe them.
#include "modules/m4/m4.h"
#include "decompose/make_step.h"

#include "model/codes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

using decompose::makeStep;



// The outline moved inward by d; the final outline itself when d is zero, so
// that the last wall pass runs exactly on the typed corners.
Quad inset(const Quad& q, double d) { return d == 0.0 ? q : offsetInward(q, d); }

// Cross-section of the finished pocket at depth z: a tapered wall leans
// inward by z * tan(S); a corner whose radius the taper uses up is sharp.
Quad section(const Quad& top, double taper, double z)
{
    if (taper == 0.0) return top;
    Quad q = offsetInward(top, z * tanDeg(taper));
    q.cornerRadius = std::max(q.cornerRadius, 0.0);
    return q;
}

// One wall-finishing pass: the allowance it leaves and its machining type.
struct WallPass {
    double leaves;
    MachiningType type;
};

std::vector<WallPass> wallPasses(WallFinish f, bool tapered, const TechnologyData& tech)
{
    if (f != WallFinish::TwoStage) return {{0.0, MachiningType::WallFinishing}};
    if (!tapered) return {{tech.alpha3, MachiningType::WallSemiFinishing}, {0.0, MachiningType::WallFinishing}};
    return {{tech.alpha3, MachiningType::WallSemiFinishing},
            {tech.alpha3 / 2.0, MachiningType::WallMiddlePass},
            {0.0, MachiningType::WallFinishing}};
}

}  // namespace

Quad m4RoughOutline(const M4Pocket& pocket, const TechnologyData& tech)
{
    const Quad top{counterClockwise(pocket.corners), pocket.cornerRadius};
    return offsetInward(section(top, pocket.taper, pocket.depth - tech.beta2), tech.alpha2);
}

std::vector<Step> decomposeM4(const M4Pocket& pocket, const TechnologyData& tech, int unit)
{
    const ToolUse use = toolUseFromCode(pocket.toolUse).value();
    const WallFinish finish = wallFinishFromCode(pocket.wallFinish).value();
    const PilotHole pilot = pilotHoleFromCode(pocket.pilotHole).value();
    const double T = pocket.depth;
    const Quad top{counterClockwise(pocket.corners), pocket.cornerRadius};
    const bool tapered = pocket.taper > 0.0;
    std::vector<Step> steps;

    if (pilot == PilotHole::Drill) {
        Step s = makeStep(unit, "M4", StepKind::PilotHole, 1, MachiningType::PilotHole);
        s.payload = MillingGeometry{
            .position = centroid(pocket.corners), .startDepth = 0.0, .cutDepth = T - tech.alpha1, .floorAllowance = tech.alpha1};
        steps.push_back(s);
    }

    const double roughDepth = T - tech.beta2;
    const Quad roughOutline = m4RoughOutline(pocket, tech);
    if (hasRoughing(use)) {
        Step s = makeStep(unit, "M4", StepKind::Roughing, 1, MachiningType::Roughing);
        s.payload = MillingGeometry{.outline = roughOutline,
                                    .position = centroid(roughOutline.corners),
                                    .startDepth = 0.0,
                                    .cutDepth = roughDepth,
                                    .wallAllowance = tech.alpha2,
                                    .floorAllowance = tech.beta2};
        steps.push_back(s);
    }
    if (hasFloorFinishing(use)) {
        Step s = makeStep(unit, "M4", StepKind::FloorFinishing, 1, MachiningType::FloorFinishing);
        s.payload = MillingGeometry{.outline = roughOutline,
                                    .position = centroid(roughOutline.corners),
                                    .startDepth = roughDepth,
                                    .cutDepth = T,
                                    .wallAllowance = tech.alpha2,
                                    .floorAllowance = 0.0};
        steps.push_back(s);
    }

    // Wall passes: the outline is the one at the top surface; a tapered pass
    // (wallTaper = S) narrows by z * tan(S) at depth z.
    if (hasWallFinishing(use)) {
        int number = 0;
        for (const WallPass& pass : wallPasses(finish, tapered, tech)) {
            Step s = makeStep(unit, "M4", StepKind::WallFinishing, ++number, pass.type);
            const Quad outline = inset(top, pass.leaves);
            s.payload = MillingGeometry{.outline = outline,
                                        .position = centroid(outline.corners),
                                        .startDepth = 0.0,
                                        .cutDepth = T,
                                        .wallTaper = pocket.taper,
                                        .wallAllowance = pass.leaves,
                                        .floorAllowance = 0.0,
                                        .multiIncision = finish == WallFinish::MultiIncision};
            steps.push_back(s);
        }
    }
    return steps;
}

}  // namespace taiwa
