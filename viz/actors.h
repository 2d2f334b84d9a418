// Small helpers the scene's files share: an actor for fixed poly data (lit,
// or as unlit lines of a width), and the length of the axes for a size.
#pragma once

#include "viz/palette.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace taiwa::viz {

// An actor drawing `pd` (which never changes) in `colour`.
vtkSmartPointer<vtkActor> actorFor(vtkPolyData* pd, Rgb colour);
// The same, unlit (lines show their colour exactly), lines `width` pixels wide.
vtkSmartPointer<vtkActor> lineActor(vtkPolyData* pd, Rgb colour, double width);
// 1, 2 or 5 times a power of ten, near a fifth of the size.
double niceLength(double size);

}  // namespace taiwa::viz
