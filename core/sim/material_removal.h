// Material removal on the height field: the tool swept along a path lowers
// every cell its cutting surface passes over. Rapids cut too (a rapid
// through material shows up as the crash it would be).
#pragma once

#include "model/tool.h"
#include "model/toolpath.h"
#include "sim/height_field.h"

namespace taiwa::sim {

// Sweeps `tool` along `path` (the tool tip, as in CL data) over `field`.
// Horizontal pieces are swept exactly (distance of each cell to the piece);
// sloped pieces are split so that Z errs by at most 0.02 mm, towards
// leaving material.
void cut(HeightField& field, const ToolPath& path, const Tool& tool);

}  // namespace taiwa::sim
