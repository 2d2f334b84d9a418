// STEP files of 3-D surfaces (docs/surfaces.md): the finished surface
// written as one B-spline face through its point-sequence paths, and a
// STEP file's faces (a face set, an alternative to building the surface from
// curves) read and tessellated once into the triangles the drop-cutter
// works on. OpenCASCADE's reader and writer behind this header.
#pragma once

#include "model/result.h"
#include "model/toolpath.h"
#include "occt/surface_mesh.h"

#include <string>
#include <vector>

namespace taiwa::surface {

// How the face passes through the paths' points: a B-spline interpolating
// every point (a sampled smooth surface), or flat between them: each cell
// the bilinear patch of its four corners, exactly (a B-spline of degree
// 1 × 1, the points its poles; the SURFACE unit's finishing surface, whose
// paths' cells are pieces of its bilinear patches between the rulings).
enum class SurfaceFit { Smooth, Bilinear };

// The surface through the paths (paths[i][j], all of one length, at least
// 2 × 2) as one face in a STEP file at `file`, in mm. Refused naming the
// file or the paths.
Result<bool> exportSurfaceStep(const std::vector<std::vector<Point3>>& paths, const std::string& file,
                               SurfaceFit fit = SurfaceFit::Smooth);

// The same STEP file's text (for an export's set of files).
Result<std::string> surfaceStepText(const std::vector<std::vector<Point3>>& paths, SurfaceFit fit);

// Every face of the STEP file at `file`, tessellated so that no triangle
// strays more than about `deflection` mm from its face (a grid over the
// face's parameters from its second derivatives), as one mesh (the normals'
// side as the faces have it; a trimmed face loses the grid cells its trim
// crosses). Refused: a file that
// cannot be read, holds no face, or whose faces give no triangles.
Result<TriangleMesh> importStepFaces(const std::string& file, double deflection);

// A STEP file's face set as the SURFACE unit's surface (surface_faces.cpp):
// point-sequence paths along X, `spacing` apart in Y, their points `spacing`
// apart in X, each the faces' highest point there (importStepFaces at
// 0.1 µm). Refused as importStepFaces, and naming the point: where no face
// lies under a point of the faces' XY rectangle (the faces leave a hole or
// are not a rectangle seen from above), and where a face lies under
// another (an undercut: the verifying simulation is a height field). The
// paths stray from the faces by `deviation` at most (Z, the faces at the
// middle of every grid cell against its corners' mean), which grows with
// the spacing.
struct SampledFaces {
    std::vector<std::vector<Point3>> paths;
    double deviation = 0.0;
};
Result<SampledFaces> sampleStepFaces(const std::string& file, double spacing);

}  // namespace taiwa::surface
