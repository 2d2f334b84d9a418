// The stock surface lit on the processor (viz/surface_light.h).
#include "viz/surface_light.h"

#include "picture/light.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace taiwa::viz {

namespace {

// The lighting's math is the core's (picture/light.h): the sheet's
// pictures are lit with the same function.
using Vec = picture::Vec3;
using picture::dot;
using picture::normalised;
using picture::ViewLight;

std::vector<ViewLight> viewLights(vtkRenderer* renderer, const vtkMatrix4x4* view)
{
    const auto rotate = [&](const Vec& v) {
        Vec r{};
        for (int i = 0; i < 3; ++i) r[i] = view->GetElement(i, 0) * v[0] + view->GetElement(i, 1) * v[1] + view->GetElement(i, 2) * v[2];
        return r;
    };
    std::vector<ViewLight> out;
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it)) {
        if (!light->GetSwitch()) continue;
        const double* c = light->GetDiffuseColor();
        const double k = light->GetIntensity();
        ViewLight v{{0, 0, -1}, {c[0] * k, c[1] * k, c[2] * k}};
        const double* p = light->GetPosition();
        const double* f = light->GetFocalPoint();
        const Vec along{f[0] - p[0], f[1] - p[1], f[2] - p[2]};
        if (light->LightTypeIsCameraLight())  // in the camera's frame: view coordinates' axes
            v.direction = normalised(along);
        else if (light->LightTypeIsSceneLight())
            v.direction = normalised(rotate(normalised(along)));
        out.push_back(v);  // a headlight shines along the view: (0, 0, -1)
    }
    return out;
}

// What the colours are lit for: the view's rotation, the projection, the
// camera's position in perspective, each light's state.
std::vector<double> lightingKey(vtkRenderer* renderer)
{
    vtkCamera* camera = renderer->GetActiveCamera();
    std::vector<double> key;
    const vtkMatrix4x4* view = camera->GetViewTransformMatrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) key.push_back(view->GetElement(i, j));
    const bool parallel = camera->GetParallelProjection() != 0;
    key.push_back(parallel ? 1 : 0);
    const double* eye = camera->GetPosition();
    key.insert(key.end(), {parallel ? 0 : eye[0], parallel ? 0 : eye[1], parallel ? 0 : eye[2]});
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it)) {
        key.push_back(light->GetSwitch());
        key.push_back(light->GetLightType());
        key.push_back(light->GetIntensity());
        for (const double* v : {light->GetDiffuseColor(), light->GetPosition(), light->GetFocalPoint()})
            key.insert(key.end(), v, v + 3);
    }
    return key;
}

}  // namespace

bool lightSurface(vtkPolyData* surface, vtkRenderer* renderer, double ambient, double diffuse)
{
    auto* base = vtkUnsignedCharArray::SafeDownCast(surface->GetPointData()->GetArray(kBaseColours));
    vtkDataArray* normals = surface->GetCellData()->GetArray(kQuadNormals);
    auto* shown = vtkUnsignedCharArray::SafeDownCast(surface->GetPointData()->GetScalars());
    vtkCellArray* polys = surface->GetPolys();
    if (!base || !normals || !shown || !polys || normals->GetNumberOfTuples() != polys->GetNumberOfCells() ||
        shown->GetNumberOfTuples() != base->GetNumberOfTuples() || base->GetNumberOfComponents() != 3 ||
        shown->GetNumberOfComponents() != 3)
        return false;
    vtkCamera* camera = renderer->GetActiveCamera();
    const vtkMatrix4x4* view = camera->GetViewTransformMatrix();
    const std::vector<ViewLight> lights = viewLights(renderer, view);
    const bool parallel = camera->GetParallelProjection() != 0;
    const unsigned char* from = base->GetPointer(0);
    unsigned char* to = shown->GetPointer(0);
    const vtkIdType nPoints = base->GetNumberOfTuples();
    vtkIdType cell = 0, n = 0;
    const vtkIdType* ids = nullptr;
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
        it->GetCurrentCell(n, ids);
        double w[3];
        normals->GetTuple(cell, w);
        Vec nv{};
        for (int i = 0; i < 3; ++i) nv[i] = view->GetElement(i, 0) * w[0] + view->GetElement(i, 1) * w[1] + view->GetElement(i, 2) * w[2];
        nv = normalised(nv);
        // Seen from behind (VTK's gl_FrontFacing false): lit on its back.
        bool front = nv[2] > 0;
        if (!parallel && n > 0) {
            double p[3];
            surface->GetPoint(ids[0], p);
            Vec pv{};
            for (int i = 0; i < 3; ++i)
                pv[i] = view->GetElement(i, 0) * p[0] + view->GetElement(i, 1) * p[1] + view->GetElement(i, 2) * p[2] + view->GetElement(i, 3);
            front = dot(nv, pv) < 0;
        }
        const Vec light = picture::lightFactor(nv, front, lights, ambient, diffuse);
        for (vtkIdType k = 0; k < n; ++k) {
            const vtkIdType id = ids[k];
            if (id < 0 || id >= nPoints) continue;
            for (int i = 0; i < 3; ++i)
                to[3 * id + i] = static_cast<unsigned char>(std::clamp(std::lround(from[3 * id + i] * light[i]), 0L, 255L));
        }
    }
    shown->Modified();
    return true;
}

void SurfaceLighting::set(vtkActor* actor, double ambient, double diffuse)
{
    actor_ = actor;
    ambient_ = ambient;
    diffuse_ = diffuse;
    litFor_.clear();
    if (!actor) return;
    // Unlit, VTK draws (ambient + diffuse) x the colour: the colour itself.
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    actor->GetProperty()->SetSpecular(0.0);
}

void SurfaceLighting::update(vtkRenderer* renderer)
{
    if (!actor_ || !actor_->GetVisibility() || !actor_->GetMapper()) return;
    auto* surface = vtkPolyData::SafeDownCast(actor_->GetMapper()->GetInputDataObject(0, 0));
    if (!surface) return;
    std::vector<double> key = lightingKey(renderer);
    if (key == litFor_) return;
    if (lightSurface(surface, renderer, ambient_, diffuse_)) litFor_ = std::move(key);
}

}  // namespace taiwa::viz
