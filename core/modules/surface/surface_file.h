// Module SURFACE's unit in the job file: its job-file table (io/unit_keys.h;
// unknown keys refused, every problem on its field, canonical order on
// writing), the curves as points or projections and the surface or boundary
// as paths of points. Given to its door (surface_kind.cpp).
#pragma once

#include "io/unit_keys.h"
#include "modules/surface/surface.h"

#include <nlohmann/json.hpp>

namespace taiwa::surfacemod {

const io::UnitKeys<SurfaceUnit>& surfaceKeys();

}  // namespace taiwa::surfacemod
