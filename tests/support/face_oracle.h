// Geometry oracle of module FACE (face milling of the stock top), written
// from the definitions (docs/face-milling.md), not from the path code: the
// finished part is the stock below Z = -depth; the face is the stock's top
// grown by the margin. The first three are the module's branch of
// pocket_geometry.h (which knows no stock: everything below -depth counts
// as the part there); the rest judge a tape against the stock.
#pragma once

#include "model/job.h"
#include "model/tool.h"
#include "model/toolpath.h"

#include <vector>

namespace taiwa {
struct FaceUnit;
}

namespace taiwa::test {

// How far a tool with its tip at `tip` cuts below the faced top (<= 0: not).
double faceGouge(const FaceUnit& face, const Tool& tool, Point3 tip);
// The depth taken off the top.
double faceDepth(const FaceUnit& face);
// A face has no walls: -infinity.
double faceWallDistance(const FaceUnit& face, Point3 tip);

// Distance from a point to the stock's footprint (0 on or inside it).
double distanceToStock(const Stock& stock, Point2 p);
// The face: the stock's top grown by `margin` on every side, as
// [min, max] corners.
std::pair<Point2, Point2> faceBox(const Stock& stock, double margin);
// Points covering the face no more than `spacing` apart, its edges and
// corners included.
std::vector<Point2> faceGrid(const Stock& stock, double margin, double spacing);
// Distance from p to the segment ab.
double distanceToSegment(Point2 p, Point2 a, Point2 b);

}  // namespace taiwa::test
