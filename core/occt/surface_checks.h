// What the surface unit checks before it plans (docs/surfaces.md): a
// surface given as point-sequence paths must not turn under itself (the
// verifying simulation is a height field and cannot see undercuts), its
// smallest concave radius bounds the tool's corner radius, and a cutting
// boundary surface must meet it somewhere. Each refusal names the paths and
// points where it is, positions in mm.
#pragma once

#include "model/toolpath.h"
#include "occt/surface_mesh.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::surface {

// Where the surface turns under itself: a quad of the paths whose normal
// points the other way in Z from the surface's (the wrong way by more than
// 1 µm over the quad, so that a vertical wall is no undercut). Nothing when
// there is none.
std::optional<std::string> findUndercut(const std::vector<std::vector<Point3>>& paths);

// The smallest radius of the surface's concave (upward) bends, along the
// paths and across them: the circle through three neighbouring points whose
// middle one lies below the chord of the others; +infinity on a surface
// without concave bends. `where` names the place.
struct ConcaveRadius {
    double radius = 0.0;
    std::string where;
};
ConcaveRadius smallestConcaveRadius(const std::vector<std::vector<Point3>>& paths);

// Whether the boundary surface meets the surface anywhere: some segment of
// the paths, along or across them, crosses one of its triangles.
bool boundaryMeetsSurface(const std::vector<std::vector<Point3>>& paths, const MeshIndex& boundary);

}  // namespace taiwa::surface
