// Process decomposition of module CP (contour pocket with islands): roughing,
// floor finishing and the wall passes of code F, as M4 makes them for a
// vertical-walled pocket (docs/decomposition.md), over the unit's region.
#include "modules/cp/cp.h"

#include "decompose/make_step.h"
#include "model/codes.h"

namespace taiwa {

std::vector<Step> decomposeContourPocket(const ContourPocket& pocket, const TechnologyData& tech, int unit)
{
    using decompose::makeStep;
    const ToolUse use = toolUseFromCode(pocket.toolUse).value();
    const WallFinish finish = wallFinishFromCode(pocket.wallFinish).value();
    const Region region = normalised(pocket.contours.region.value());
    const double reach = pocket.reach, inscribed = pocket.inscribed;
    const Box2 box = bounds(region.outer);
    const Point2 middle = 0.5 * (box.min + box.max);
    const double T = pocket.depth, roughDepth = T - tech.beta2;
    std::vector<Step> steps;
    const auto step = [&](StepKind kind, int number, MachiningType type, double from, double to, double wall,
                          double floor) {
        Step s = makeStep(unit, ContourPocket::kName, kind, number, type);
        s.payload = MillingGeometry{.region = region,
                                    .reach = std::max(reach - wall, 0.0),
                                    .inscribed = std::max(inscribed - wall, 0.0),
                                    .position = middle,
                                    .startDepth = from,
                                    .cutDepth = to,
                                    .wallAllowance = wall,
                                    .floorAllowance = floor};
        return s;
    };
    if (hasRoughing(use))
        steps.push_back(step(StepKind::Roughing, 1, MachiningType::Roughing, 0.0, roughDepth, tech.alpha2, tech.beta2));
    if (hasFloorFinishing(use))
        steps.push_back(step(StepKind::FloorFinishing, 1, MachiningType::FloorFinishing, roughDepth, T, tech.alpha2, 0.0));
    if (hasWallFinishing(use)) {
        int number = 0;
        if (finish == WallFinish::TwoStage)
            steps.push_back(step(StepKind::WallFinishing, ++number, MachiningType::WallSemiFinishing, 0.0, T, tech.alpha3, 0.0));
        Step last = step(StepKind::WallFinishing, ++number, MachiningType::WallFinishing, 0.0, T, 0.0, 0.0);
        editMilling(last).multiIncision = finish == WallFinish::MultiIncision;
        steps.push_back(last);
    }
    return steps;
}

}  // namespace taiwa
