// The colours of the 3-D preview, in one place (also used by the tests to
// find things in rendered images).
#pragma once

namespace taiwa::viz {

struct Rgb {
    unsigned char r = 0, g = 0, b = 0;
    double red() const { return r / 255.0; }
    double green() const { return g / 255.0; }
    double blue() const { return b / 255.0; }
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

namespace palette {
inline constexpr Rgb kBackground{38, 44, 56};    // solid, so a pixel off the stock is exactly this
inline constexpr Rgb kFeed{64, 160, 255};        // feed and arc moves
inline constexpr Rgb kRapid{255, 110, 64};       // rapids, drawn thin
inline constexpr Rgb kDimmed{96, 104, 118};      // paths of the steps not selected
inline constexpr Rgb kHighlight{255, 0, 220};    // the move picked in the NC view or the 3-D view
inline constexpr Rgb kTool{235, 190, 40};        // the tool glyph
// A two-path lathe's other turrets' tools (path 2's, path 3's); path 1's is kTool.
inline constexpr Rgb kTool2{140, 235, 60};
inline constexpr Rgb kTool3{200, 130, 255};
inline constexpr Rgb kStock{176, 182, 194};      // uncut stock faces
inline constexpr Rgb kMachined{120, 200, 160};   // faces the simulation has cut
inline constexpr Rgb kRemoved{245, 160, 60};     // faces the selected step (or the blocks played) cut
inline constexpr Rgb kStockEdges{150, 158, 172}; // the stock's box when the stock is hidden
inline constexpr Rgb kPartEdges{236, 238, 244};  // the finished pockets' outlines, top and floor
inline constexpr Rgb kText{220, 224, 232};
inline constexpr Rgb kClamp{70, 130, 235};       // the setup picture's vice or chuck jaws, translucent
inline constexpr Rgb kChuck{84, 92, 106};        // the setup picture's chuck body
inline constexpr Rgb kProbe{60, 230, 230};       // probing touches (the stylus ball) and the fitted centre
// The face a section plane cuts through the stock.
inline constexpr Rgb kSection{180, 120, 200};
// The verification's colour map of the finished part (verify::DeviationBand).
inline constexpr Rgb kGouge{230, 40, 40};        // cut below the part
inline constexpr Rgb kAtSize{70, 190, 90};       // within the tolerance
inline constexpr Rgb kRestThin{150, 210, 255};   // material left up to 0.1 mm
inline constexpr Rgb kRestMedium{60, 130, 240};  // up to 0.5 mm
inline constexpr Rgb kRestThick{40, 50, 170};    // more
}  // namespace palette

}  // namespace taiwa::viz
