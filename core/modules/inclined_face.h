// Module M2D's inclined faces: an inclined-face finishing step's own data
// (Step::payload, made by modules/m2d/m2d_decompose.cpp) and its tool path
// (inclined_face.cpp). Kept beside the pocket modules' shared code, not in
// modules/m2d/, because their shared tool choice and step hooks
// (pocket_tools.cpp, pocket_plan.cpp) read it too.
#pragma once

#include "model/geometry.h"
#include "model/step.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "paths/cl.h"

#include <array>

namespace taiwa {

// An inclined face of module M2D: a plane strip between its edge at the top
// surface and its edge at the floor, finished by a ball end mill that
// leaves at most `scallop` between its passes.
struct InclinedFace {
    static constexpr const char* kName = "M2D inclined face";
    std::array<Point2, 2> topEdge{};    // at depth 0
    std::array<Point2, 2> floorEdge{};  // at depth T
    double angle = 0.0;                 // from the vertical [deg]
    double scallop = 0.0;               // the unit's scallop height [mm]
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const InclinedFace&, const InclinedFace&) = default;
};

// The finishing passes of an inclined-face step: a ball end mill in passes
// parallel to the face's top edge, zig-zag down the slope. Throws
// std::logic_error for a step without its face or a tool that is no ball.
ToolPath inclinedFacePath(const Step& step, const Tool& tool, const PathParameters& p);
// About how many moves inclinedFacePath makes (10 for a step without its face).
double inclinedFaceMoves(const Step& step, const Tool& tool);

}  // namespace taiwa
