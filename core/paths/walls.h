// Wall finishing (vertical and tapered walls, one or several Z incisions,
// tangent lead-in and lead-out arcs), inclined-face finishing of module M2D
// with a ball end mill at a set scallop height, and the pilot-hole drilling
// cycle.
#pragma once

#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "paths/cl.h"

namespace taiwa::paths {

ToolPath wallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath inclinedFace(const Step& step, const Tool& tool, const PathParameters& p);
ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p);

}  // namespace taiwa::paths
