// The sheet pictures' rasteriser (canvas.h).
#include "picture/canvas.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::picture {

Image::Image(int w, int h, Colour fill) : width(w), height(h), rgba(4 * static_cast<std::size_t>(w) * h, 255)
{
    for (std::size_t k = 0; k < rgba.size(); k += 4) rgba[k] = fill.r, rgba[k + 1] = fill.g, rgba[k + 2] = fill.b;
}

void Image::blend(int x, int y, Colour c, double alpha)
{
    const std::size_t k = 4 * (static_cast<std::size_t>(y) * width + x);
    const auto mix = [&](std::uint8_t under, std::uint8_t over) {
        return static_cast<std::uint8_t>(std::lround(under + alpha * (over - under)));
    };
    rgba[k] = mix(rgba[k], c.r), rgba[k + 1] = mix(rgba[k + 1], c.g), rgba[k + 2] = mix(rgba[k + 2], c.b);
}

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

constexpr double kMargin = 1.08;  // viz/camera_presets.cpp

}  // namespace

Canvas::Canvas(int width, int height, Colour background, View view, const std::array<double, 6>& b)
    : image_(width, height, background),
      depth_(static_cast<std::size_t>(width) * height, -std::numeric_limits<float>::infinity()),
      lights_(sceneLights())
{
    // As viz::applyViewPreset: iso from (1, -1, 1) with Z up; front from -Y.
    Vec3 up{0, 0, 1};
    eye_ = view == View::Iso ? normalised({1, -1, 1}) : Vec3{0, -1, 0};
    right_ = normalised(cross(up, eye_));
    up_ = cross(eye_, right_);
    centre_ = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
    double halfW = 0, halfH = 0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 c{b[k & 1] - centre_[0], b[2 + ((k >> 1) & 1)] - centre_[1], b[4 + ((k >> 2) & 1)] - centre_[2]};
        halfW = std::max(halfW, std::abs(dot(c, right_)));
        halfH = std::max(halfH, std::abs(dot(c, up_)));
    }
    const double aspect = static_cast<double>(width) / height;
    const double parallelScale = kMargin * std::max({halfH, halfW / std::max(aspect, 1e-3), 1e-3});
    scale_ = height / (2 * parallelScale);
}

Projected Canvas::project(const Vec3& p) const
{
    const Vec3 d{p[0] - centre_[0], p[1] - centre_[1], p[2] - centre_[2]};
    return {image_.width / 2.0 + scale_ * dot(d, right_), image_.height / 2.0 - scale_ * dot(d, up_), dot(d, eye_)};
}

Colour Canvas::lit(Colour base, const Vec3& n) const
{
    const Vec3 v = normalised({dot(n, right_), dot(n, up_), dot(n, eye_)});
    const Vec3 f = lightFactor(v, v[2] >= 0, lights_, kAmbient, kDiffuse);
    const auto ch = [](std::uint8_t c, double k) { return static_cast<std::uint8_t>(std::clamp(std::lround(c * k), 0L, 255L)); };
    return {ch(base.r, f[0]), ch(base.g, f[1]), ch(base.b, f[2])};
}

void Canvas::plot(int x, int y, double depth, Colour c)
{
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    float& d = depth_[static_cast<std::size_t>(y) * image_.width + x];
    if (depth < d) return;
    d = static_cast<float>(depth);
    image_.set(x, y, c);
}

void Canvas::polygon(const Projected* p, int n, Colour c, double alpha)
{
    if (n < 3) return;
    double area = 0;
    for (int k = 0; k < n; ++k) {
        const Projected &a = p[k], &b = p[(k + 1) % n];
        area += a.x * b.y - b.x * a.y;
    }
    if (std::abs(area) < 1e-12) return;
    const double sign = area > 0 ? 1.0 : -1.0;
    // The depth's plane from the corners' centroid and the polygon's gradient (area-weighted).
    double gx = 0, gy = 0, cx = 0, cy = 0, cd = 0;
    for (int k = 0; k < n; ++k) cx += p[k].x, cy += p[k].y, cd += p[k].depth;
    cx /= n, cy /= n, cd /= n;
    {
        // Gradient from the first, a middle and the last corner.
        const Projected &a = p[0], &b = p[n / 2], &d = p[n - 1];
        const double det = (b.x - a.x) * (d.y - a.y) - (d.x - a.x) * (b.y - a.y);
        if (std::abs(det) > 1e-12) {
            gx = ((b.depth - a.depth) * (d.y - a.y) - (d.depth - a.depth) * (b.y - a.y)) / det;
            gy = ((d.depth - a.depth) * (b.x - a.x) - (b.depth - a.depth) * (d.x - a.x)) / det;
        }
    }
    double minX = p[0].x, maxX = p[0].x, minY = p[0].y, maxY = p[0].y;
    for (int k = 1; k < n; ++k)
        minX = std::min(minX, p[k].x), maxX = std::max(maxX, p[k].x), minY = std::min(minY, p[k].y), maxY = std::max(maxY, p[k].y);
    const int x0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5))), x1 = std::min(image_.width - 1, static_cast<int>(std::floor(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5))), y1 = std::min(image_.height - 1, static_cast<int>(std::floor(maxY - 0.5)));
    for (int y = y0; y <= y1; ++y) {
        const double py = y + 0.5;
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5;
            bool inside = true;
            for (int k = 0; k < n && inside; ++k) {
                const Projected &a = p[k], &b = p[(k + 1) % n];
                inside = sign * ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) >= 0;
            }
            if (!inside) continue;
            const double depth = cd + gx * (px - cx) + gy * (py - cy);
            float& d = depth_[static_cast<std::size_t>(y) * image_.width + x];
            if (depth < d - 1e-6) continue;
            if (alpha >= 1.0) {
                d = static_cast<float>(depth);
                image_.set(x, y, c);
            } else {
                image_.blend(x, y, c, alpha);
            }
        }
    }
}

void Canvas::parallelogram(const Projected& o, const Projected& u, const Projected& v, Colour c, double alpha)
{
    const double det = u.x * v.y - u.y * v.x;
    if (std::abs(det) < 1e-12) return;
    // (a, b) of a pixel centre: o + a u + b v; inside when both are in [0, 1].
    const double m00 = v.y / det, m01 = -v.x / det, m10 = -u.y / det, m11 = u.x / det;
    const double minX = std::min({o.x, o.x + u.x, o.x + v.x, o.x + u.x + v.x}), maxX = std::max({o.x, o.x + u.x, o.x + v.x, o.x + u.x + v.x});
    const double minY = std::min({o.y, o.y + u.y, o.y + v.y, o.y + u.y + v.y}), maxY = std::max({o.y, o.y + u.y, o.y + v.y, o.y + u.y + v.y});
    const int x0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5))), x1 = std::min(image_.width - 1, static_cast<int>(std::floor(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5))), y1 = std::min(image_.height - 1, static_cast<int>(std::floor(maxY - 0.5)));
    constexpr double e = 1e-9;
    for (int y = y0; y <= y1; ++y) {
        const double dy = y + 0.5 - o.y;
        float* depth = depth_.data() + static_cast<std::size_t>(y) * image_.width;
        std::uint8_t* rgba = image_.rgba.data() + 4 * static_cast<std::size_t>(y) * image_.width;
        for (int x = x0; x <= x1; ++x) {
            const double dx = x + 0.5 - o.x;
            const double a = m00 * dx + m01 * dy, b = m10 * dx + m11 * dy;
            if (a < -e || a > 1 + e || b < -e || b > 1 + e) continue;
            const auto d = static_cast<float>(o.depth + a * u.depth + b * v.depth);
            if (d < depth[x] - 1e-6f) continue;
            if (alpha < 1.0) {
                image_.blend(x, y, c, alpha);
                continue;
            }
            depth[x] = d;
            rgba[4 * x] = c.r, rgba[4 * x + 1] = c.g, rgba[4 * x + 2] = c.b;
        }
    }
}

void Canvas::face(const std::vector<Vec3>& corners, Colour base, double alpha, bool cull)
{
    const int n = static_cast<int>(std::min<std::size_t>(corners.size(), 8));
    if (n < 3) return;
    Projected p[8];
    for (int k = 0; k < n; ++k) p[k] = project(corners[static_cast<std::size_t>(k)]);
    const Vec3 u{corners[2][0] - corners[0][0], corners[2][1] - corners[0][1], corners[2][2] - corners[0][2]};
    const Vec3 v{corners[static_cast<std::size_t>(n - 1)][0] - corners[1][0], corners[static_cast<std::size_t>(n - 1)][1] - corners[1][1],
                 corners[static_cast<std::size_t>(n - 1)][2] - corners[1][2]};
    const Vec3 normal = normalised(cross(u, v));
    if (cull && dot(normal, eye_) < 0) return;
    const Colour c = lit(base, normal);
    // A rectangle in an orthographic view is a parallelogram: the quick fill.
    const auto edge = [&](int k) { return Projected{p[k].x - p[0].x, p[k].y - p[0].y, p[k].depth - p[0].depth}; };
    const Projected e1 = edge(1), e3 = edge(3), e2 = edge(2);
    if (n == 4 && std::abs(e1.x + e3.x - e2.x) < 1e-6 && std::abs(e1.y + e3.y - e2.y) < 1e-6) parallelogram(p[0], e1, e3, c, alpha);
    else polygon(p, n, c, alpha);
}

void Canvas::line(const Vec3& a, const Vec3& b, Colour c, int width, double bias)
{
    const Projected pa = project(a), pb = project(b);
    const double steps = std::max({std::abs(pb.x - pa.x), std::abs(pb.y - pa.y), 1.0});
    const int n = static_cast<int>(std::ceil(steps));
    for (int k = 0; k <= n; ++k) {
        const double t = static_cast<double>(k) / n;
        const double x = pa.x + t * (pb.x - pa.x), y = pa.y + t * (pb.y - pa.y), d = pa.depth + t * (pb.depth - pa.depth) + bias;
        for (int w = 0; w < width; ++w) plot(static_cast<int>(std::floor(x)) + (w % 2 ? w : 0), static_cast<int>(std::floor(y)) + (w % 2 ? 0 : w), d, c);
    }
}

void Canvas::line2d(double x0, double y0, double x1, double y1, Colour c, int width)
{
    const int n = static_cast<int>(std::ceil(std::max({std::abs(x1 - x0), std::abs(y1 - y0), 1.0})));
    for (int k = 0; k <= n; ++k) {
        const double t = static_cast<double>(k) / n;
        const int x = static_cast<int>(std::floor(x0 + t * (x1 - x0))), y = static_cast<int>(std::floor(y0 + t * (y1 - y0)));
        for (int dx = 0; dx < width; ++dx)
            for (int dy = 0; dy < width; ++dy)
                if (x + dx >= 0 && y + dy >= 0 && x + dx < image_.width && y + dy < image_.height) image_.set(x + dx, y + dy, c);
    }
}

}  // namespace taiwa::picture
