// Module SURFACE's unit in the job file: read (unknown keys refused, every
// problem on its field) and written in canonical order, the curves as
// points or projections and the surface or boundary as paths of points.
// Called by its door (surface_kind.cpp).
#pragma once

#include "io/json_fields.h"
#include "modules/surface/surface.h"

#include <nlohmann/json.hpp>

namespace taiwa::surfacemod {

SurfaceUnit readSurfaceUnit(const io::ObjectFields& f);
void writeSurfaceUnit(const SurfaceUnit& u, nlohmann::ordered_json& j);

}  // namespace taiwa::surfacemod
