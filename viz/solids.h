// Solid geometry of the preview: the stock as a block or as the simulated
// height-field surface, and the tool as a solid of revolution of its
// cutting profile.
#pragma once

#include "model/job.h"
#include "model/tool.h"
#include "sim/height_field.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace taiwa::viz {

// The closed surface of the simulated stock: the height field's top (one
// vertex per cell centre), its four side walls and the bottom, with point
// normals and RGB point colours: palette::kStock where the top is uncut,
// palette::kMachined where the simulation lowered it.
vtkSmartPointer<vtkPolyData> heightFieldSurface(const sim::HeightField& field);

// The uncut stock block.
vtkSmartPointer<vtkPolyData> stockBlock(const Stock& stock);

// The tool with its tip at the origin and its axis along +Z, up to its
// cutting length, with normals.
vtkSmartPointer<vtkPolyData> toolSolid(const Tool& tool);

}  // namespace taiwa::viz
