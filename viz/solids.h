// Solid geometry of the preview: the stock as a block or as the simulated
// height-field surface, the tool as a solid of revolution of its cutting
// profile, and the finished pockets' outlines as lines.
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/turned.h"
#include "model/tool.h"
#include "model/turn_path.h"
#include "sim/height_field.h"
#include "verify/deviation.h"
#include "viz/render.h"

#include <vtkAxesActor.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <map>
#include <vector>

namespace taiwa::viz {

// The closed surface of the simulated stock: the height field's top (a
// vertex per cell centre; rectangles of vertices at one height merged into
// one quad), its four side walls and the bottom. Each quad has four points
// of its own, its outward normal in the cell array kQuadNormals and its
// corners' RGB colours in kBaseColours and, until it is lit
// (viz/surface_light.h), in the point scalars: palette::kStock where the
// top is uncut, palette::kMachined where the simulation lowered it; given
// the stock `before` a step (the same grid), palette::kRemoved where the
// step lowered it further.
// The top is made in kSurfaceBands bands of rows at once when the field
// has kSurfaceBandRows rows per band or more (a quad never spans two
// bands: an uncut top is a quad per band).
vtkSmartPointer<vtkPolyData> heightFieldSurface(const sim::HeightField& field, const sim::HeightField* before = nullptr);
inline constexpr int kSurfaceBands = 2;
inline constexpr int kSurfaceBandRows = 64;

// The verification's colour map on the finished part: the map's stock
// surface (as heightFieldSurface) coloured by band: palette::kGouge,
// kAtSize, kRestThin, kRestMedium, kRestThick, and kStock where the job
// leaves the stock as it is.
vtkSmartPointer<vtkPolyData> deviationSurface(const verify::DeviationMap& map);

// The face a section plane cuts through the stock the height field holds:
// the plane sampled at the field's cell size (coarser when that takes more
// than `maxSamples`), a quad for each run of samples inside the material.
vtkSmartPointer<vtkPolyData> sectionCap(const sim::HeightField& field, const SectionPlane& plane,
                                        std::size_t maxSamples = 1'000'000);

// Axes at the origin, `length` long each, drawn as lines, labelled x, y, z
// (the machine's names of the view's X, Y, Z) in captions of `fontSize`
// pixels that keep their size however the camera zooms.
vtkSmartPointer<vtkAxesActor> labelledAxes(double length, int fontSize, const char* x = "X", const char* y = "Y",
                                           const char* z = "Z");

// The uncut stock block.
vtkSmartPointer<vtkPolyData> stockBlock(const Stock& stock);

// The tool with its tip at the origin and its axis along +Z, up to its
// cutting length, with normals.
vtkSmartPointer<vtkPolyData> toolSolid(const Tool& tool);

// The finished pockets as closed lines: for each unit, the outline of its
// last wall step (the one leaving the least wall allowance, then the
// deepest) with its rounded corners sampled every 5 degrees, once at the
// top face (Z 0) and once at the floor (Z -cutDepth; for a tapered wall the
// outline moved inward by cutDepth x tan(taper)).
// `cache` (kept by the caller from one plan to the next) keeps each unit's
// sampled outlines while its outline, depth and taper stay: an edit of one
// unit of 200 samples one (the 200 took 9 ms).
struct OutlineCache {
    struct Entry {
        Quad top;
        double depth = 0, taper = 0;
        std::vector<Point2> topPoints, floorPoints;
    };
    std::map<int, Entry> units;
};
vtkSmartPointer<vtkPolyData> pocketOutlines(const std::vector<Step>& steps, OutlineCache* cache = nullptr);

// A lathe job's chain of half-section edges (turned profile, deformed
// profile, bar outline) revolved about the spindle axis: the surface of
// revolution with the spindle along VTK's X (Z of the lathe to the right),
// the radius in Y and Z; arcs sampled every 3° and the turn in 72 steps,
// for display only, with normals.
// `half`: only the half turn behind the section through the axis that
// faces the front view (y >= 0), so that the section and a path drawn in
// it (at (z, 0, r)) stay in sight.
vtkSmartPointer<vtkPolyData> revolvedChain(const std::vector<turning::Segment>& chain, bool half = false);

// A lathe tool as it stands in the section through the axis, a flat face in
// the (z, r) plane with its programmed point at the origin: an insert's
// nose and both cutting edges (turn_tools' insertShape, shifted from the
// nose centre to the programmed point), a blade's width and reach from its
// front corner, a drill's point and body above the axis. Empty for a tool
// the section cannot show.
std::vector<turning::ZR> latheToolOutline(const Tool& tool, const TurnStep& step);
vtkSmartPointer<vtkPolyData> sectionFace(const std::vector<turning::ZR>& outline, double y);

}  // namespace taiwa::viz
