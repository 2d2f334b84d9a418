// Camera presets of the preview: iso, top and front, parallel projection,
// fitted to a box (the stock and the paths) for a given viewport aspect.
// The caller resets the clipping range (vtkRenderer::ResetCameraClippingRange).
#pragma once

#include "viz/render.h"

#include <array>

class vtkCamera;

namespace taiwa::viz {

// bounds: xmin, xmax, ymin, ymax, zmin, zmax. aspect: width / height.
void applyViewPreset(vtkCamera* camera, ViewPreset preset, const std::array<double, 6>& bounds, double aspect);

}  // namespace taiwa::viz
