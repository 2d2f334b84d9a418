// The scene's marker of a point of interest (a verification finding): a red
// ball a little larger than a tool's tip, and the camera moved to it.
#include "viz/scene.h"

#include <vtkCamera.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>

namespace taiwa::viz {

void Scene::markPoint(std::optional<Point3> p)
{
    marked_ = p;
    if (marker_) renderer_->RemoveActor(marker_);
    marker_ = nullptr;
    if (!p) return;
    const auto b = bounds();
    const double size = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4], 1.0});
    auto ball = vtkSmartPointer<vtkSphereSource>::New();
    ball->SetCenter(p->x, p->y, p->z);
    ball->SetRadius(size * 0.02);
    ball->SetThetaResolution(24);
    ball->SetPhiResolution(16);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(ball->GetOutputPort());
    marker_ = vtkSmartPointer<vtkActor>::New();
    marker_->SetMapper(mapper);
    marker_->GetProperty()->SetColor(0.85, 0.0, 0.0);
    renderer_->AddActor(marker_);
    vtkCamera* camera = renderer_->GetActiveCamera();
    double focal[3], position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    const double to[3] = {p->x, p->y, p->z};
    for (int k = 0; k < 3; ++k) position[k] += to[k] - focal[k];
    camera->SetFocalPoint(to);
    camera->SetPosition(position);
    renderer_->ResetCameraClippingRange();
}

}  // namespace taiwa::viz
