// The project's lighting as pure math: the preview's two lights (a weaker
// headlight and a key light from above left of the viewer, viz/scene.cpp)
// and the factor a flat face is lit by (ambient plus diffuse from every
// light, both sides lit as VTK lights them). The preview's stock surface
// (viz/surface_light.h) and the sheet's pictures (core/picture) light with
// this one function.
#pragma once

#include <array>
#include <vector>

namespace taiwa::picture {

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b);
Vec3 normalised(Vec3 v);

// A light as the shader sees it: the direction it shines in, in view
// coordinates (x right, y up, z toward the viewer), and its colour times
// its intensity.
struct ViewLight {
    Vec3 direction{0, 0, -1};
    Vec3 colour{1, 1, 1};
};

// The preview's lights (viz::Scene): a headlight of 0.45, a key light of
// 0.6 from (-0.5, 0.8, 1) in the camera's frame.
std::vector<ViewLight> sceneLights();
// The stock's material in the preview (viz/scene_stock.cpp).
inline constexpr double kAmbient = 0.25, kDiffuse = 0.75;

// The light a face of view-space normal `n` gets, per channel: ambient +
// diffuse x each light's share; a face seen from behind (`front` false) is
// lit on its back.
Vec3 lightFactor(Vec3 n, bool front, const std::vector<ViewLight>& lights, double ambient, double diffuse);

}  // namespace taiwa::picture
