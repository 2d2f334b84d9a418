// The SURFACE steps' tool paths: the step's surface tessellated once and
// indexed, the tool-nose points by the drop-cutter (Z-level roughing leaving
// the allowance, or parallel finishing at the scallop height), each path
// stopped where it meets the boundary surface, and the paths linked at the
// safe height (occt/surface_paths.h does the geometry). And the unit's
// cavity for the verification: the material under the finishing surface.
#include "modules/surface/surface.h"

#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace taiwa::surfacemod {

namespace {
constexpr double kChordTolerance = 0.25e-3;  // mm: a move under the cutter's positions at its middle
}  // namespace

ToolPath surfacePath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    const SurfacePaths& sp = step.payload.as<SurfacePaths>();
    // Roughing stays off both surfaces: the drop takes the highest touch, so
    // the two meshes in one are their upper envelope.
    surface::TriangleMesh mesh = surface::meshFromPaths(sp.surface);
    if (!sp.finished.empty()) {
        const surface::TriangleMesh f = surface::meshFromPaths(sp.finished);
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), f.vertices.begin(), f.vertices.end());
        for (const auto& t : f.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    const surface::MeshIndex index(std::move(mesh));
    if (index.mesh().triangles.empty()) throw std::logic_error("surface step " + step.label() + " has no surface");
    const surface::Cutter cutter{tool.diameter, tool.cornerRadius > 0.0 ? tool.cornerRadius : tool.radius()};
    const surface::Area area{index.minX(), index.minY(), index.maxX(), index.maxY()};
    std::vector<std::vector<Point3>> paths;
    if (step.kind == StepKind::SurfaceFinishing) {
        surface::DropCutter drop(index, cutter);
        drop.keepAxisOverSurface(true);  // never hanging over the edge (docs/surfaces.md)
        paths = surface::finishingPaths(drop, area, sp.step, sp.scallop, sp.concaveRadius).paths;
        for (auto& p : paths) surface::refineMoves(drop, p, kChordTolerance);
    } else {
        surface::ZLevelOptions o;
        o.top = 0.0;
        o.depth = tech.gamma * tool.diameter;
        o.stepOver = tech.stepOver * tool.diameter;
        o.step = sp.step;
        o.allowance = sp.allowance;
        o.axisOverSurface = true;
        // The passes' moves refined as the finishing's, on the cutter grown
        // by the allowance (its nose raised by it), never under the level.
        surface::DropCutter grown(index, surface::Cutter{cutter.diameter + 2 * o.allowance, cutter.cornerRadius + o.allowance});
        grown.keepAxisOverSurface(true);
        for (surface::RoughingPass& p : surface::zLevelRoughing(index, cutter, area, o)) {
            surface::refineMoves(grown, p.points, kChordTolerance, p.level, o.allowance);
            paths.push_back(std::move(p.points));
        }
    }
    if (!sp.boundary.empty()) {
        const surface::MeshIndex boundary(surface::meshFromPaths(sp.boundary));
        for (auto& p : paths) p = surface::stopAtBoundary(p, boundary).points;
    }
    // The Z-level passes start in what the level above left, the finishing
    // paths in roughing's stairs: down to the clearance over the stock top.
    return surface::linkPaths(paths, params.safeZ, params.clearance, -millingOf(step).startDepth);
}

std::optional<Cavity> surfaceCavity(const SurfaceUnit& u)
{
    const Built b = buildSurfaces(u, LengthUnit::Millimetre);
    if (!b.problem.empty()) return std::nullopt;
    auto index = std::make_shared<const surface::MeshIndex>(surface::meshFromPaths(b.finishing));
    if (index->mesh().triangles.empty()) return std::nullopt;
    // The steepest facet's slope: the surface within `slack` of a point is
    // no more than slack times it above or below the point's own height.
    double slope = 0.0;
    for (std::size_t t = 0; t < index->mesh().triangles.size(); ++t) {
        const auto& f = index->facet(static_cast<int>(t));
        if (f.nz > 1e-9) slope = std::max(slope, std::hypot(f.nx, f.ny) / f.nz);
    }
    slope = std::min(slope, 100.0);  // an undercut is refused by the checks; a wall this steep is one
    static std::atomic<unsigned long long> made{0};
    const unsigned long long id = ++made;
    Cavity c;
    // The unit defines the part under its surface only: past the surface's
    // edges (where the ball, hanging over an edge, may go below it) it makes
    // no claim, and the depth there is the deepest, which judges nothing.
    constexpr double kPastEdges = 100.0;  // the tool's disc reaches past the edges (the grid keeps to the stock)
    c.min = {index->minX() - kPastEdges, index->minY() - kPastEdges};
    c.max = {index->maxX() + kPastEdges, index->maxY() + kPastEdges};
    c.depth = std::max(0.0, -index->minZ());
    const double deepest = c.depth;
    c.wallAngle = std::atan(slope) * 180.0 / std::numbers::pi;
    c.surfaceTolerance = u.scallop;
    c.depthAt = [index, id, slope, deepest](Point2 p, double slack) {
        // One drop per thread and surface (a DropCutter keeps scratch space).
        struct Mine {
            unsigned long long id = 0;
            std::unique_ptr<surface::DropCutter> drop;
        };
        thread_local Mine mine;
        if (mine.id != id) {
            mine.drop = std::make_unique<surface::DropCutter>(*index, surface::Cutter{});
            mine.id = id;
        }
        // Past the edges (grown by the slack), or over a hole in the mesh:
        // nothing claimed (the deepest for a gouge's limit, none for rest).
        const bool past = p.x < index->minX() - slack || p.x > index->maxX() + slack || p.y < index->minY() - slack ||
                          p.y > index->maxY() + slack;
        const std::optional<double> z = past ? std::nullopt : mine.drop->surfaceZ(p.x, p.y);
        if (!z) return slack > 0.0 ? deepest : 0.0;
        return std::max(0.0, -*z + slack * slope);
    };
    return c;
}

}  // namespace taiwa::surfacemod
