// Pixel helpers for the rendering tests (header only: the support library
// does not link Qt Gui, the tests that render do).
#pragma once

#include <QImage>

namespace taiwa::test {

// How many pixels differ between two images of the same size.
inline int differingPixels(const QImage& a, const QImage& b)
{
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    return n;
}

}  // namespace taiwa::test
