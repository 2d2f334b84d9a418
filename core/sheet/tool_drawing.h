// The instruction sheet's drawing of a milling tool in its holder: a side
// view of the holder's nose, the shank and the flutes with the stick-out
// dimensioned, as one list of shapes, lines and texts on a fixed canvas.
// The HTML sheet writes it as SVG (toolDrawingSvg), the PDF paints the same
// list with QPainter, so the two never disagree.
#pragma once

#include "model/geometry.h"
#include "model/tool.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::sheet {

struct ToolDrawing {
    enum class Part { Holder, Shank, Flutes, Arrow };
    struct Shape {
        Part part;
        std::vector<Point2> points;  // a closed polygon, canvas units
        std::string fill;            // "#rrggbb"
    };
    struct Line {
        Point2 from, to;
        bool dashed = false;  // the tool's axis
    };
    struct Text {
        Point2 at;  // the middle of its baseline
        std::string text;
    };
    // The canvas, in units of a CSS pixel at 1:1 (y down, origin top left);
    // the text size in the same units.
    static constexpr double kWidth = 160.0, kHeight = 64.0, kTextSize = 9.0;
    double scale = 0.0;  // canvas units per mm (one scale per tool: the largest that fits)
    std::vector<Shape> shapes;
    std::vector<Line> lines;
    std::vector<Text> texts;
};

// The drawing of `tool`: its axis horizontal, the holder at the left and
// the tip at the right; the holder's nose from tools::holderShape (the
// library's holder diameter and length, else read from its name), the
// shank from the holder's face to the flutes, the flutes their flute length
// at the tool's diameter (a drill's point drawn), and under them the
// stick-out from the holder's face to the tip with its value as `length`
// formats it. None for lathe tools (inserts and blades: the turret table
// describes them) and for a tool without a stick-out.
std::optional<ToolDrawing> toolDrawing(const Tool& tool, const std::function<std::string(double)>& length);

// The drawing as an SVG element (no XML prolog), to inline in HTML.
std::string toolDrawingSvg(const ToolDrawing& drawing);

}  // namespace taiwa::sheet
