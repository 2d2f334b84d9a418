// The level of detail of tool paths while the operator turns the camera:
// line geometry decimated within a tolerance (consecutive pieces joined
// into runs, each run thinned to the points where it leaves a strip of the
// tolerance's width around its direction). A million-segment path becomes
// a few thousand segments and still covers the same region of the picture.
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>

namespace taiwa::viz {

// Segments drawn for a line data set (a cell of n points is n - 1 segments).
std::size_t lineSegmentCount(vtkPolyData* lines);

// The lines thinned: every run of cells that continue each other (a cell
// starting at the point the previous one ended on) becomes one polyline
// through a subset of its points, first and last kept. Every dropped point
// lies within 3 x `tolerance` of the polyline that replaces it. The result
// has points of its own (only those kept). `tolerance` <= 0 keeps every
// point.
vtkSmartPointer<vtkPolyData> decimateLines(vtkPolyData* lines, double tolerance);

// decimateLines with the tolerance doubled (up to 10 times) until the
// result has at most `maxSegments` segments.
vtkSmartPointer<vtkPolyData> decimateLinesWithin(vtkPolyData* lines, double tolerance, std::size_t maxSegments);

}  // namespace taiwa::viz
