// Pilot-hole drilling: one canned cycle at the hole position, pecking when
// the hole is deep for the drill.
#include "paths/generators.h"

#include "paths/path_builder.h"

namespace taiwa::paths {

ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    // The cycle returns to the level it started from (safe Z, G98), so the
    // path both starts and ends at safe height.
    PathBuilder b({g.position.x, g.position.y, p.safeZ});
    Move m{MoveKind::DrillCycle, {g.position.x, g.position.y, -g.cutDepth}};
    m.retractZ = -g.startDepth + p.clearance;
    m.peck = g.cutDepth > p.peckWhenDeeperThan * tool.diameter ? p.peckDepth * tool.diameter : 0.0;
    b.add(m);
    return b.take();
}

}  // namespace taiwa::paths
