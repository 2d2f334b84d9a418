// A picture drawn by the core on the processor (no OpenGL, no display): a
// plain RGBA buffer, and the few words written on it (axis names, the work
// offset) that whoever encodes it paints with its own fonts
// (core/export/picture_png.h), so that the core needs no font engine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace taiwa::picture {

struct Colour {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Colour&, const Colour&) = default;
};

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, top row first, 4 bytes a pixel, opaque
    Image() = default;
    Image(int w, int h, Colour fill);
    Colour at(int x, int y) const
    {
        const std::size_t k = 4 * (static_cast<std::size_t>(y) * width + x);
        return {rgba[k], rgba[k + 1], rgba[k + 2]};
    }
    void set(int x, int y, Colour c)
    {
        const std::size_t k = 4 * (static_cast<std::size_t>(y) * width + x);
        rgba[k] = c.r, rgba[k + 1] = c.g, rgba[k + 2] = c.b;
    }
    // `c` over the pixel with opacity `alpha` (0..1).
    void blend(int x, int y, Colour c, double alpha);
};

// A word on the picture: its anchor in pixels, left-aligned from there, or
// right-aligned to it (`right`); its baseline at y.
struct Label {
    double x = 0, y = 0;
    std::string text;
    Colour colour;
    int pixelSize = 13;
    bool bold = false;
    bool right = false;
    friend bool operator==(const Label&, const Label&) = default;
};

struct Picture {
    Image image;
    std::vector<Label> labels;
};

// The sheet's colours: dark on light, so that a printed sheet shows them.
namespace colours {
inline constexpr Colour kBackground{255, 255, 255};
inline constexpr Colour kStock{205, 209, 216};     // uncut stock
inline constexpr Colour kMachined{150, 178, 168};  // cut by the steps before
inline constexpr Colour kRemoved{235, 150, 60};    // cut by this step
inline constexpr Colour kPath{20, 50, 150};        // the step's feed moves
inline constexpr Colour kClamp{40, 90, 200};       // the vice's or chuck's jaws, translucent
inline constexpr Colour kChuck{90, 96, 108};       // the chuck's body
inline constexpr Colour kAxisX{190, 20, 20};
inline constexpr Colour kAxisY{20, 130, 40};
inline constexpr Colour kAxisZ{20, 50, 190};
inline constexpr Colour kText{20, 24, 32};
inline constexpr Colour kCentreLine{60, 60, 60};
}  // namespace colours

}  // namespace taiwa::picture
