// What the operator does to the 3-D view besides choosing a step: the tool
// paths and the part switched off and on, the wheel zooming about the
// pointer, and the camera framing the selected step (viz::Scene; docs/preview.md "Zoom,
// framing and the paths switch").
#include "viz/scene.h"

#include "model/turn_path.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace taiwa::viz {

void Scene::setPathsShown(bool shown)
{
    if (shown == pathsShown_) return;
    pathsShown_ = shown;
    if (!plan_) return;
    if (lathe_) updateLatheStep();
    else updateEmphasis();
    updateHighlight();
}

void Scene::setPartShown(bool shown)
{
    if (shown == partShown_) return;
    partShown_ = shown;
    if (partEdges_) partEdges_->SetVisibility(shown);
    if (lathe_ && plan_) updateLatheStep();
}

void Scene::zoomAt(double x, double y, int width, int height, double factor)
{
    if (!(factor > 0) || width <= 0 || height <= 0) return;
    vtkCamera* camera = renderer_->GetActiveCamera();
    // The pixel in normalised device coordinates, at the focal plane's depth.
    vtkMatrix4x4* toView = worldToView(width, height);
    double focal[3], position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    const double f[4] = {focal[0], focal[1], focal[2], 1.0};
    double clip[4];
    toView->MultiplyPoint(f, clip);
    const double depth = clip[3] != 0 ? clip[2] / clip[3] : 0.0;
    const double ndc[4] = {2.0 * x / width - 1.0, 1.0 - 2.0 * y / height, depth, 1.0};
    auto inverse = vtkSmartPointer<vtkMatrix4x4>::New();
    vtkMatrix4x4::Invert(toView, inverse);
    double w[4];
    inverse->MultiplyPoint(ndc, w);
    if (w[3] == 0) return;
    const double at[3] = {w[0] / w[3], w[1] / w[3], w[2] / w[3]};
    // Nearer by `factor`, the point under the pixel held where it is: in
    // perspective the camera scaled about it (the direction and the view
    // angle kept); in parallel projection a smaller scale and the camera
    // moved along the focal plane by what keeps the point in place.
    const double t = 1.0 - 1.0 / factor;
    double newFocal[3], newPosition[3];
    for (int i = 0; i < 3; ++i) {
        const double shift = (at[i] - focal[i]) * t;
        newFocal[i] = focal[i] + shift;
        newPosition[i] = camera->GetParallelProjection() ? position[i] + shift : position[i] + (at[i] - position[i]) * t;
    }
    if (camera->GetParallelProjection()) camera->SetParallelScale(camera->GetParallelScale() / factor);
    camera->SetFocalPoint(newFocal);
    camera->SetPosition(newPosition);
    renderer_->ResetCameraClippingRange();
}

void Scene::frameSelectedStep(double aspect)
{
    std::array<double, 6> b = bounds();
    if (plan_ && selected_ >= 0) {
        const Step& step = plan_->steps[static_cast<std::size_t>(selected_)];
        if (const auto* turn = turnOf(step); turn && !turn->path.moves.empty()) {
            // The section's upper half-plane: Z along the view's X, the radius up.
            double z0 = turn->path.start.z, z1 = z0, r0 = turn->path.start.r, r1 = r0;
            for (const auto& m : turn->path.moves) {
                z0 = std::min(z0, m.end.z), z1 = std::max(z1, m.end.z);
                r0 = std::min(r0, m.end.r), r1 = std::max(r1, m.end.r);
            }
            b = {z0, z1, -0.1, 0.1, r0, r1};
        } else if (selected_ < static_cast<int>(steps_.size()) && steps_[static_cast<std::size_t>(selected_)].geometry.points &&
                   steps_[static_cast<std::size_t>(selected_)].geometry.points->GetNumberOfPoints() > 0) {
            double pb[6];
            steps_[static_cast<std::size_t>(selected_)].geometry.points->GetBounds(pb);
            b = {pb[0], pb[1], pb[2], pb[3], pb[4], pb[5]};
        }
    }
    // A flat path (a floor's) framed with some depth around it.
    const double size = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4], 1.0});
    for (int i = 0; i < 6; i += 2) {
        const double grow = std::max(0.0, 0.05 * size - (b[i + 1] - b[i]) / 2);
        b[i] -= grow, b[i + 1] += grow;
    }
    vtkCamera* camera = renderer_->GetActiveCamera();
    renderer_->ResetCamera(b.data());  // the direction and the view-up kept
    if (camera->GetParallelProjection()) {
        // ResetCamera fits the bounding sphere in the height; a wide view
        // fits it in its width too.
        const double radius = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]) / 2;
        camera->SetParallelScale(std::max(radius, radius / std::max(aspect, 1e-6)) * 1.05);
    }
    renderer_->ResetCameraClippingRange();
}

}  // namespace taiwa::viz
