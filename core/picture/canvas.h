// A small rasteriser for the sheet's pictures: an orthographic camera
// (the preview's iso or front view, fitted to a box as viz's view presets
// fit it), a depth buffer, convex polygons in flat colours lit by
// picture/light.h, lines, and the 2-D fills of a lathe's section. Plain
// loops over an RGBA buffer: a 320 x 240 picture of a few tens of
// thousands of faces in a few milliseconds on one core.
#pragma once

#include "picture/image.h"
#include "picture/light.h"

#include <array>
#include <vector>

namespace taiwa::picture {

// Where a point lands: pixels from the top left, and its depth toward the
// viewer (larger is nearer).
struct Projected {
    double x = 0, y = 0, depth = 0;
};

class Canvas {
public:
    enum class View { Iso, Front };
    // A width x height canvas in `background`; the view shows the box
    // `bounds` (xmin, xmax, ymin, ymax, zmin, zmax) whole, with the view
    // presets' margin.
    Canvas(int width, int height, Colour background, View view, const std::array<double, 6>& bounds);

    Projected project(const Vec3& p) const;
    // The colour of a face of world normal `n` lit by the scene's lights.
    Colour lit(Colour base, const Vec3& n) const;
    // The pixels per mm of the view.
    double scale() const { return scale_; }

    // A convex polygon (3..8 corners, either winding), depth-tested; drawn
    // with opacity `alpha` when below 1 (its depth then not written).
    void polygon(const Projected* corners, int n, Colour c, double alpha = 1.0);
    // The parallelogram from corner `o` along the edges `u` and `v` (screen
    // offsets with their depth change), depth-tested: the quick case of the
    // height field's faces.
    void parallelogram(const Projected& o, const Projected& u, const Projected& v, Colour c, double alpha = 1.0);
    // A face in world coordinates, lit by its normal; back faces are skipped
    // when `cull`.
    void face(const std::vector<Vec3>& corners, Colour base, double alpha = 1.0, bool cull = true);
    // A line `width` pixels wide, depth-tested with its depth moved toward
    // the viewer by `bias` mm (a path on the floor it cut stays seen).
    void line(const Vec3& a, const Vec3& b, Colour c, int width = 1, double bias = 0.0);
    // The same in pixels, not tested.
    void line2d(double x0, double y0, double x1, double y1, Colour c, int width = 1);

    Image& image() { return image_; }
    Image take() { return std::move(image_); }

private:
    Image image_;
    std::vector<float> depth_;
    Vec3 right_{}, up_{}, eye_{}, centre_{};
    double scale_ = 1;
    std::vector<ViewLight> lights_;
    void plot(int x, int y, double depth, Colour c);
};

}  // namespace taiwa::picture
