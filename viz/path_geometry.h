// Tool paths as VTK line geometry: the flattened pieces of one path (arcs
// sampled, drill cycles unrolled) as one shared point list with two line
// sets, feeds and rapids, and for each piece the move it belongs to (for
// highlighting and picking).
#pragma once

#include "model/toolpath.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace taiwa::viz {

struct PathGeometry {
    // Point k is where piece k starts, point k + 1 where it ends.
    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkPolyData> feeds;   // one line cell per feed, arc or drilling piece
    vtkSmartPointer<vtkPolyData> rapids;  // one line cell per rapid piece
    std::vector<int> moveOfPiece;         // index into ToolPath::moves
};

// Arcs sampled within `chordTolerance` mm.
PathGeometry makePathGeometry(const ToolPath& path, double chordTolerance = 0.01);

// The paths of many steps in one point list and two line sets (a large
// plan's scene draws each block of units as two actors and makes no VTK
// object per step).
// Step k's points are [first[k], first[k] + count[k]); the piece from point
// i to point i + 1 belongs to move moveOfPiece[i] of its step's path.
struct MergedPaths {
    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkPolyData> feeds, rapids;
    std::vector<vtkIdType> first, count;  // per step; count 0 for a step without a path
    std::vector<int> moveOfPiece;         // per point
};
MergedPaths makeMergedPaths(const std::vector<const ToolPath*>& paths, double chordTolerance = 0.01);

// A cheap key for a tool path (its start, move count and three of its
// moves); equal paths have equal keys.
std::size_t pathKey(const ToolPath& p);

// The pieces of one move only, as lines (the highlight).
vtkSmartPointer<vtkPolyData> movePieces(const PathGeometry& g, int move);

}  // namespace taiwa::viz
