// The tool-path generators of the step kinds, one source file each:
// pocket.cpp (roughing, floor finishing), wall_finishing.cpp,
// inclined_face.cpp, pilot_hole.cpp; steps of contour units (Step::region)
// region_pocket.cpp and region_walls.cpp; face_milling.cpp, side_milling.cpp,
// area_clearing.cpp. makeToolPath dispatches to them.
#pragma once

#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "paths/cl.h"

namespace taiwa::paths {

ToolPath pocketRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath floorFinishing(const Step& step, const Tool& tool, const PathParameters& p);
ToolPath wallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath inclinedFace(const Step& step, const Tool& tool, const PathParameters& p);
ToolPath regionRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath regionFloorFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath regionWallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
// The depths a wall pass cuts at: the step's full depth, or (multiIncision,
// F2) equal incisions of at most gamma x D down to it (wall_finishing.cpp).
std::vector<double> incisionDepths(const Step& step, const Tool& tool, const TechnologyData& tech);
ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p);
ToolPath holeCycles(const Step& step, const Tool& tool, const PathParameters& p);  // holes.cpp: hole patterns
ToolPath faceMilling(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);   // face_milling.cpp
ToolPath sideMilling(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);   // side_milling.cpp
ToolPath areaClearing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);  // area_clearing.cpp

}  // namespace taiwa::paths
