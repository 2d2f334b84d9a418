// Hole patterns (module HOLES): one canned cycle at every hole of the step,
// in the step's order, from the R plane `clearance` above the top down to
// the step's depth; drilling pecks when the hole is deep for the drill (as
// the pilot hole does), tapping carries the thread's pitch.
#include "modules/holes/holes.h"

#include "paths/path_builder.h"

#include <stdexcept>

namespace taiwa::holes {

using namespace paths;  // the shared path builders

ToolPath cyclesPath(const Step& step, const Tool& tool, const TechnologyData&, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    const HoleCentres& holes = step.payload.as<HoleCentres>();
    if (holes.centres.empty()) throw std::logic_error("hole step " + step.label() + " has no holes");
    // Each cycle returns to the level it started from (safe Z, G98): the
    // path starts over the first hole and ends over the last, at safe height.
    PathBuilder b({holes.centres.front().x, holes.centres.front().y, p.safeZ});
    CycleKind cycle = CycleKind::Drill;
    if (step.kind == StepKind::Tapping) cycle = CycleKind::Tap;
    if (step.kind == StepKind::Reaming) cycle = CycleKind::Ream;
    if (step.kind == StepKind::Boring) cycle = CycleKind::Bore;
    const bool peck = step.kind == StepKind::Drilling && g.cutDepth > p.peckWhenDeeperThan * tool.diameter;
    for (const Point2& h : holes.centres) {
        Move m{MoveKind::DrillCycle, {h.x, h.y, -g.cutDepth}};
        m.retractZ = -g.startDepth + p.clearance;
        m.cycle = cycle;
        m.peck = peck ? p.peckDepth * tool.diameter : 0.0;
        m.pitch = cycle == CycleKind::Tap ? holes.threadPitch : 0.0;
        b.add(m);
    }
    return b.take();
}

}  // namespace taiwa::holes
