// Planning steps shared by the pocket modules (M4, M2D, CP): the tools of
// one unit's steps with the operator's pins, the pilot hole handed to the
// roughing that plunges into it, and the door's step hooks they share (tool
// paths by step kind, move estimates, the order of a unit's steps). Called
// from a module's door, never from the pipeline.
#pragma once

#include "modules/module_kind.h"

namespace taiwa {

// Chooses the tools of `steps` (one unit, decomposition order) in place;
// problems become diagnostics of the unit (field "tools"). Then tells every
// roughing step where the pilot hole is and how wide it was drilled.
void choosePocketTools(std::vector<Step>& steps, const ToolPins& pins, const UnitPlanContext& ctx, const char* module,
                       Diagnostics& out);

// The unit's own step-over (a fraction of D) to its roughing steps; the
// technology data's stays in force when the unit has none.
void setStepOver(std::vector<Step>& steps, std::optional<double> stepOver);

// A pocket step's tool path by its kind, from the shared generators
// (paths/generators.h): a contour unit's steps (with a region) by the region
// ones. Throws std::logic_error for a kind pockets do not have.
ToolPath pocketToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);
// About how many moves pocketToolPath makes: layers x rings, or as many as
// the flattened region has points a ring.
double pocketEstimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);
// A pocket unit's order: the pilot hole, then roughing, then the finishing
// steps (which wait for all roughing, not for each other, except wall
// passes that follow their number); roughing layers in their order.
bool pocketStepWaitsFor(const Step& later, const Step& earlier);

// The door of a pocket module: the step hooks above, the pocket paths its
// path function.
template <class T>
class PocketKindOf : public ModuleKindOf<T> {
public:
    PocketKindOf(const io::UnitKeys<T>* keys, typename ModuleKindOf<T>::CheckFunction checks)
        : ModuleKindOf<T>(keys, checks, pocketToolPath)
    {
    }
    double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech,
                         const PathParameters& params) const final
    {
        return pocketEstimateMoves(step, tool, tech, params);
    }
    bool stepWaitsFor(const Step& later, const Step& earlier) const final { return pocketStepWaitsFor(later, earlier); }
};

}  // namespace taiwa
