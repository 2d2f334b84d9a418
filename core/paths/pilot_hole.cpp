// Pilot-hole drilling: one canned cycle at the hole position, pecking when
// the hole is deep for the drill.
#include "paths/generators.h"

#include "paths/path_builder.h"

namespace taiwa::paths {

ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p)
{
    // The cycle returns to the level it started from (safe Z, G98), so the
    // path both starts and ends at safe height.
    PathBuilder b({step.position.x, step.position.y, p.safeZ});
    Move m{MoveKind::DrillCycle, {step.position.x, step.position.y, -step.cutDepth}};
    m.retractZ = -step.startDepth + p.clearance;
    m.peck = step.cutDepth > p.peckWhenDeeperThan * tool.diameter ? p.peckDepth * tool.diameter : 0.0;
    b.add(m);
    return b.take();
}

}  // namespace taiwa::paths
