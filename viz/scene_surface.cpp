// The machined free-form surfaces as one VTK actor (viz/scene_surface.h):
// the steps' surfaces as point paths from their modules, tessellated once
// by the core (two triangles per quad of neighbouring points), lit, in a
// colour of their own, pulled in front of the coincident finished stock.
#include "viz/scene_surface.h"

#include "modules/registry.h"
#include "occt/surface_mesh.h"
#include "viz/actors.h"

#include <vtkCellArray.h>
#include <vtkMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>

namespace taiwa::viz {

namespace {
// A pale violet: apart from the stock's grey, the feeds' blue and the
// colour map's green, red and blue.
constexpr Rgb kSurface{190, 160, 230};
}  // namespace

vtkSmartPointer<vtkActor> machinedSurfaces(const std::vector<Step>& steps, std::size_t* triangles)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    std::size_t count = 0;
    for (const Step& step : steps) {
        // A step of no known module (a scene of hand-made steps) has no surface to show.
        const ModuleKind* kind = step.path ? findModuleKind(step.module) : nullptr;
        if (!kind) continue;
        const auto paths = kind->machinedSurface(step);
        if (paths.empty()) continue;
        const surface::TriangleMesh mesh = surface::meshFromPaths(paths);
        const vtkIdType first = points->GetNumberOfPoints();
        for (const Point3& v : mesh.vertices) points->InsertNextPoint(v.x, v.y, v.z);
        for (const auto& t : mesh.triangles) {
            const vtkIdType ids[3] = {first + t[0], first + t[1], first + t[2]};
            polys->InsertNextCell(3, ids);
        }
        count += mesh.triangles.size();
    }
    if (triangles) *triangles = count;
    if (count == 0) return nullptr;
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    // Smooth shading over the tessellation (the facets' own normals would
    // show every ruling's crease as much as the surface's shape).
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputData(pd);
    normals->SetFeatureAngle(60.0);
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOff();
    normals->SplittingOff();
    normals->Update();
    vtkSmartPointer<vtkActor> actor = actorFor(normals->GetOutput(), kSurface);
    // Where it coincides with the simulated finished part, the surface wins.
    vtkMapper* mapper = actor->GetMapper();
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2.0, -4.0);
    actor->GetProperty()->BackfaceCullingOff();
    return actor;
}

}  // namespace taiwa::viz
