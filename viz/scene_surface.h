// The free-form surfaces a plan machines (a SURFACE unit's finishing
// surface), drawn in the 3-D view under their paths: each step's surface
// from its module's door (ModuleKind::machinedSurface), tessellated by the
// core's surface mesh (occt/surface_mesh.h), one lit actor for all.
#pragma once

#include "model/step.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace taiwa::viz {

// The machined surfaces of `steps` as one actor, drawn in front of the
// simulated stock where the two coincide (the finished part); nullptr when
// no step machines a free-form surface. `triangles`, if given, receives
// their number.
vtkSmartPointer<vtkActor> machinedSurfaces(const std::vector<Step>& steps, std::size_t* triangles = nullptr);

}  // namespace taiwa::viz
