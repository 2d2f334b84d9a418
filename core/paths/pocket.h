// Pocket clearing (roughing and floor finishing): Z layers, entry by plunge
// into the pilot hole or a helical ramp, contour-parallel rings from the
// inside out, and cleanup of whatever the rings leave (proved with Clipper).
#pragma once

#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "paths/cl.h"

namespace taiwa::paths {

ToolPath pocketRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);
ToolPath floorFinishing(const Step& step, const Tool& tool, const PathParameters& p);

}  // namespace taiwa::paths
