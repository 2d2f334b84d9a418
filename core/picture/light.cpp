// The project's lighting as pure math (light.h).
#include "picture/light.h"

#include <algorithm>
#include <cmath>

namespace taiwa::picture {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 normalised(Vec3 v)
{
    const double len = std::sqrt(dot(v, v));
    if (len > 0)
        for (double& k : v) k /= len;
    return v;
}

std::vector<ViewLight> sceneLights()
{
    return {ViewLight{{0, 0, -1}, {0.45, 0.45, 0.45}}, ViewLight{normalised({0.5, -0.8, -1.0}), {0.6, 0.6, 0.6}}};
}

Vec3 lightFactor(Vec3 n, bool front, const std::vector<ViewLight>& lights, double ambient, double diffuse)
{
    if (!front)
        for (double& k : n) k = -k;
    Vec3 light{ambient, ambient, ambient};
    for (const ViewLight& l : lights) {
        const double df = std::max(0.0, -dot(n, l.direction));
        for (int i = 0; i < 3; ++i) light[i] += diffuse * df * l.colour[i];
    }
    return light;
}

}  // namespace taiwa::picture
