// STEP import of a turned part: a solid of revolution read with
// OpenCASCADE, its turning axis found from its faces of revolution, cut with
// the half-plane through the axis, and its outline returned as exact
// turned profiles (lines and arcs, X as diameters, stable edge ids, Z0 on
// the front face, the part toward -Z, as lathe jobs have it). A file
// that cannot be read, holds no solid (or several), or whose solid is not a
// body of revolution is refused saying which.
#pragma once

#include "model/result.h"
#include "model/turned.h"

#include <array>
#include <optional>
#include <string>

namespace taiwa::turning {

struct ImportedProfiles {
    std::optional<TurnedProfile> outer;  // front face, outside, back face (solid parts: from the axis)
    std::optional<TurnedProfile> inner;  // the bore of a hollow part, front to back
    std::array<double, 3> axisPoint{};   // the turning axis in the model: a point on it and its direction
    std::array<double, 3> axisDirection{};
    double frontZ = 0.0;  // where along the axis (from axisPoint) the profiles' Z0 lies: the front face
};

Result<ImportedProfiles> importStepProfiles(const std::string& path);

}  // namespace taiwa::turning
