// The SURFACE steps' tool paths: the step's surface tessellated once and
// indexed, the tool-nose points by the drop-cutter (Z-level roughing leaving
// the allowance, or parallel finishing at the scallop height), each path
// stopped where it meets the boundary surface, and the paths linked at the
// safe height (occt/surface_paths.h does the geometry).
#include "modules/surface/surface.h"

#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"

#include <stdexcept>

namespace taiwa::surfacemod {

ToolPath surfacePath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    const SurfacePaths& sp = step.payload.as<SurfacePaths>();
    const surface::MeshIndex index(surface::meshFromPaths(sp.surface));
    if (index.mesh().triangles.empty()) throw std::logic_error("surface step " + step.label() + " has no surface");
    const surface::Cutter cutter{tool.diameter, tool.cornerRadius > 0.0 ? tool.cornerRadius : tool.radius()};
    const surface::Area area{index.minX(), index.minY(), index.maxX(), index.maxY()};
    std::vector<std::vector<Point3>> paths;
    if (step.kind == StepKind::SurfaceFinishing) {
        surface::DropCutter drop(index, cutter);
        paths = surface::finishingPaths(drop, area, sp.step, sp.scallop, sp.concaveRadius).paths;
    } else {
        surface::ZLevelOptions o;
        o.top = 0.0;
        o.depth = tech.gamma * tool.diameter;
        o.stepOver = tech.stepOver * tool.diameter;
        o.step = sp.step;
        o.allowance = sp.allowance;
        for (surface::RoughingPass& p : surface::zLevelRoughing(index, cutter, area, o))
            paths.push_back(std::move(p.points));
    }
    if (!sp.boundary.empty()) {
        const surface::MeshIndex boundary(surface::meshFromPaths(sp.boundary));
        for (auto& p : paths) p = surface::stopAtBoundary(p, boundary).points;
    }
    return surface::linkPaths(paths, params.safeZ, params.clearance);
}

}  // namespace taiwa::surfacemod
