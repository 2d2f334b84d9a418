// Process decomposition of module M2D (geometric 3-D pocket with two inclined
// walls): pilot hole in the floor, roughing in layers that follow the wall
// slope, floor finishing of the flat part, the vertical walls, and the two
// inclined faces (see docs/decomposition.md).
#include "modules/m2d/m2d.h"
#include "modules/inclined_face.h"
#include "decompose/make_step.h"

#include "model/codes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

using decompose::makeStep;



// round-half-up of a positive ratio, robust to the ratio landing a few ulps
// below an exact .5 (2.5 computed as 2.4999999999999996 still gives 3).
int roundHalfUp(double x) { return static_cast<int>(std::floor(x + 0.5 + 1e-9)); }

// The inclined face at x = xTop on the top surface, reaching x = xFloor at the floor.
InclinedFace face(const M2DPocket& p, double xTop, double xFloor, double angle)
{
    const double y0 = p.corner.y, y1 = p.corner.y + p.lengthY;
    return {{{{xTop, y0}, {xTop, y1}}}, {{{xFloor, y0}, {xFloor, y1}}}, angle, p.scallop};
}

}  // namespace

Quad m2dCrossSection(const M2DPocket& p, double depth)
{
    const double left = p.corner.x + depth * tanDeg(p.theta1);
    const double right = p.corner.x + p.lengthX - depth * tanDeg(p.rightAngle());
    const double y0 = p.corner.y, y1 = p.corner.y + p.lengthY;
    return Quad{{{{left, y0}, {right, y0}, {right, y1}, {left, y1}}}, p.cornerRadius};
}

std::vector<Step> decomposeM2D(const M2DPocket& p, const TechnologyData& tech, double roughingToolDiameter, int unit)
{
    const ToolUse use = toolUseFromCode(p.toolUse).value();
    const PilotHole pilot = pilotHoleFromCode(p.pilotHole).value();
    const double T = p.depth;
    const Quad floor = m2dCrossSection(p, T);
    std::vector<Step> steps;

    if (pilot == PilotHole::Drill) {
        Step s = makeStep(unit, "M2D", StepKind::PilotHole, 1, MachiningType::PilotHole);
        s.payload = MillingGeometry{.position = centroid(floor.corners), .cutDepth = T - tech.alpha1, .floorAllowance = tech.alpha1};
        steps.push_back(s);
    }

    // Roughing in n equal layers; each layer's outline is the section at its
    // bottom less alpha2, so the stairs follow the inclined walls.
    const double roughDepth = T - tech.beta2;
    const int n = std::max(1, roundHalfUp(roughDepth / (tech.gamma * roughingToolDiameter)));
    const double layer = roughDepth / n;
    for (int k = 1; k <= n; ++k) {
        Step s = makeStep(unit, "M2D", StepKind::Roughing, k, MachiningType::Roughing);
        const double depth = k == n ? roughDepth : k * layer;
        const Quad outline = offsetInward(m2dCrossSection(p, depth), tech.alpha2);
        s.payload = MillingGeometry{.outline = outline,
                                    .position = centroid(outline.corners),
                                    .startDepth = (k - 1) * layer,
                                    .cutDepth = depth,
                                    .wallAllowance = tech.alpha2,
                                    .floorAllowance = T - depth};
        steps.push_back(s);
    }
    if (use != ToolUse::Standard) return steps;

    Step floorStep = makeStep(unit, "M2D", StepKind::FloorFinishing, 1, MachiningType::FloorFinishing);
    const Quad floorOutline = offsetInward(floor, tech.alpha2);
    floorStep.payload = MillingGeometry{.outline = floorOutline,
                                        .position = centroid(floorOutline.corners),
                                        .startDepth = roughDepth,
                                        .cutDepth = T,
                                        .wallAllowance = tech.alpha2};
    steps.push_back(floorStep);

    // The vertical walls are finished full depth on the floor's outline: at
    // every depth that outline lies inside the pocket, so the pass is safe.
    Step wall = makeStep(unit, "M2D", StepKind::WallFinishing, 1, MachiningType::WallFinishing);
    wall.payload = MillingGeometry{.outline = floor, .position = centroid(floor.corners), .cutDepth = T};
    steps.push_back(wall);

    // A face at 0 degrees is vertical: the wall step above already runs on it.
    const double x0 = p.corner.x, x1 = p.corner.x + p.lengthX;
    const InclinedFace faces[] = {face(p, x0, floor.corners[0].x, p.theta1),
                                  face(p, x1, floor.corners[1].x, p.rightAngle())};
    int number = 0;
    for (const InclinedFace& f : faces) {
        if (f.angle <= 0.0) continue;
        Step s = makeStep(unit, "M2D", StepKind::InclinedFaceFinishing, ++number, MachiningType::InclinedFaceFinishing);
        InclinedFace own = f;
        own.milling = {.position = 0.25 * (f.topEdge[0] + f.topEdge[1] + f.floorEdge[0] + f.floorEdge[1]),
                       .cutDepth = T,
                       .wallTaper = f.angle};
        s.payload = own;
        steps.push_back(s);
    }
    return steps;
}

}  // namespace taiwa
