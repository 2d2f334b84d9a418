// Pixel helpers for the rendering tests: colours near a palette colour,
// lines found around a point, differing pixels (header only: the support library
// does not link Qt Gui, the tests that render do).
#pragma once

#include <QImage>

#include "viz/palette.h"

#include <algorithm>
#include <cmath>

namespace taiwa::test {

// How many pixels differ between two images of the same size.
inline int differingPixels(const QImage& a, const QImage& b)
{
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    return n;
}

inline bool near(QRgb c, viz::Rgb want, int tol) { return std::abs(qRed(c) - want.r) <= tol && std::abs(qGreen(c) - want.g) <= tol && std::abs(qBlue(c) - want.b) <= tol; }

inline double colourDistance(QRgb c, viz::Rgb want) { return std::hypot(qRed(c) - want.r, qGreen(c) - want.g, qBlue(c) - want.b); }

// A line of that colour passes within `radius` pixels of (x, y): the pixel
// there nearest to the colour is within `tol` of it, or (thin lines are
// multisampled into their backdrop) at least twice as near to it as the
// backdrop is, the backdrop being the window's pixel farthest from it.
inline bool colourNear(const QImage& img, std::array<double, 2> at, viz::Rgb want, int radius = 2, int tol = 12)
{
    double nearest = 1e9, backdrop = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = static_cast<int>(at[0]) + dx, y = static_cast<int>(at[1]) + dy;
            if (!img.valid(x, y)) continue;
            const double d = colourDistance(img.pixel(x, y), want);
            nearest = std::min(nearest, d);
            backdrop = std::max(backdrop, d);
        }
    return nearest <= tol || nearest <= 0.5 * backdrop;
}

inline bool goldish(QRgb c) { return qRed(c) > 150 && qGreen(c) > 100 && qBlue(c) < 90 && qRed(c) > qBlue(c) + 100; }

}  // namespace taiwa::test
