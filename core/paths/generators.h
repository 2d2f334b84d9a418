// The tool-path generators the pocket modules share (M4, M2D, CP; their
// doors choose among them by step kind, modules/pocket_plan.cpp), one source
// file each: pocket.cpp (roughing, floor finishing), wall_finishing.cpp,
// pilot_hole.cpp; steps of contour units (a region) region_pocket.cpp
// and region_walls.cpp. A module with paths of its own keeps them in its
// folder (FACE, SIDE, AREA, HOLES); M2D's inclined faces are in
// modules/inclined_face.cpp, beside the pocket modules' shared code.
#pragma once

#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "paths/cl.h"

namespace taiwa::paths {

// Roughing in Z layers of at most γ·D. A step whose geometry's holeDiameter
// > 0 tells that a pilot hole that wide was drilled at its position: the tool
// plunges into it when the hole is at least as wide as the tool and lies
// where the tool centre may go; otherwise (and always without a hole) it
// ramps in.
ToolPath pocketRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath floorFinishing(const Step& step, const Tool& tool, const PathParameters& p);
ToolPath wallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath regionRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath regionFloorFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath regionWallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
// The depths a wall pass cuts at: the step's full depth, or (multiIncision,
// F2) equal incisions of at most gamma x D down to it (wall_finishing.cpp).
std::vector<double> incisionDepths(const Step& step, const Tool& tool, const TechnologyData& tech);
ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p);

}  // namespace taiwa::paths
