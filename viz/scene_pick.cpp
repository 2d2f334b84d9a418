// Where the scene's world points appear on screen (viz::Scene::toPixel) and
// which move of the emphasised steps passes nearest a pixel (pickMove),
// through the camera's composite matrix.
#include "viz/scene.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>

namespace taiwa::viz {

namespace {

// World point to pixel through the camera's composite matrix.
std::array<double, 2> project(vtkMatrix4x4* m, double x, double y, double z, int width, int height)
{
    const double in[4] = {x, y, z, 1.0};
    double out[4];
    m->MultiplyPoint(in, out);
    const double w = out[3] != 0 ? out[3] : 1.0;
    return {(out[0] / w + 1.0) / 2.0 * width, (1.0 - out[1] / w) / 2.0 * height};
}

double segmentDistance(double px, double py, const double a[2], const double b[2])
{
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(px - a[0] - t * dx, py - a[1] - t * dy);
}

}  // namespace

vtkMatrix4x4* Scene::worldToView(int width, int height) const
{
    const double aspect = static_cast<double>(width) / std::max(height, 1);
    return renderer_->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
}

std::array<double, 2> Scene::toPixel(const Point3& p, int width, int height) const
{
    return project(worldToView(width, height), p.x, p.y, p.z, width, height);
}

std::optional<MoveRef> Scene::pickMove(double x, double y, int width, int height, double tolerance) const
{
    std::optional<MoveRef> best;
    double bestDistance = tolerance;
    vtkMatrix4x4* m = worldToView(width, height);
    // Step k's points and the move of the piece starting at each.
    const auto pick = [&](int k, vtkPoints* points, vtkIdType first, vtkIdType count, const int* moveOfPiece) {
        double prev[2] = {0, 0};
        for (vtkIdType i = 0; i < count; ++i) {
            double p[3];
            points->GetPoint(first + i, p);
            const auto px = project(m, p[0], p[1], p[2], width, height);
            const double cur[2] = {px[0], px[1]};
            if (i > 0) {
                const double d = segmentDistance(x, y, prev, cur);
                if (d <= bestDistance) {
                    bestDistance = d;
                    best = MoveRef{k, moveOfPiece[i - 1]};
                }
            }
            prev[0] = cur[0];
            prev[1] = cur[1];
        }
    };
    for (int k = 0; k < static_cast<int>(steps_.size()); ++k) {
        if (selected_ >= 0 && selected_ != k) continue;
        const StepActors& a = steps_[static_cast<std::size_t>(k)];
        if (a.geometry.points)
            pick(k, a.geometry.points, 0, a.geometry.points->GetNumberOfPoints(), a.geometry.moveOfPiece.data());
        else if (blockOf_[static_cast<std::size_t>(k)].first >= 0) {
            const auto [b, i] = blockOf_[static_cast<std::size_t>(k)];
            const MergedPaths& mp = blocks_[static_cast<std::size_t>(b)].paths;
            const vtkIdType first = mp.first[static_cast<std::size_t>(i)], count = mp.count[static_cast<std::size_t>(i)];
            if (count > 0) pick(k, mp.points, first, count, mp.moveOfPiece.data() + first);
        }
    }
    return best;
}

}  // namespace taiwa::viz
