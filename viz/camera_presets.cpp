// Camera presets: direction and up vector per preset; the parallel scale is
// the box's projected extent with a margin.
#include "viz/camera_presets.h"

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>

namespace taiwa::viz {

namespace {
struct Vec {
    double x, y, z;
};
double dotV(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec crossV(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec unit(Vec a)
{
    const double n = std::sqrt(dotV(a, a));
    return {a.x / n, a.y / n, a.z / n};
}
constexpr double kMargin = 1.08;
}  // namespace

void applyViewPreset(vtkCamera* camera, ViewPreset preset, const std::array<double, 6>& b, double aspect)
{
    // Direction from the focal point towards the eye, and the screen's up.
    Vec eye{0, 0, 1}, up{0, 1, 0};
    if (preset == ViewPreset::Front) eye = {0, -1, 0}, up = {0, 0, 1};
    if (preset == ViewPreset::Iso) eye = unit({1, -1, 1}), up = {0, 0, 1};
    const Vec right = unit(crossV(up, eye));
    const Vec screenUp = crossV(eye, right);
    const Vec centre{(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
    double halfW = 0, halfH = 0, depth = 0;
    for (int k = 0; k < 8; ++k) {
        const Vec c{b[k & 1] - centre.x, b[2 + ((k >> 1) & 1)] - centre.y, b[4 + ((k >> 2) & 1)] - centre.z};
        halfW = std::max(halfW, std::abs(dotV(c, right)));
        halfH = std::max(halfH, std::abs(dotV(c, screenUp)));
        depth = std::max(depth, std::abs(dotV(c, eye)));
    }
    const double distance = 4.0 * std::max({halfW, halfH, depth, 1.0});
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(centre.x, centre.y, centre.z);
    camera->SetPosition(centre.x + distance * eye.x, centre.y + distance * eye.y, centre.z + distance * eye.z);
    camera->SetViewUp(screenUp.x, screenUp.y, screenUp.z);
    camera->SetParallelScale(kMargin * std::max({halfH, halfW / std::max(aspect, 1e-3), 1e-3}));
}

}  // namespace taiwa::viz
