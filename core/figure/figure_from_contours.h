// Contours turned into figure elements: the points, lines, circles and
// CONTOUR statements (core/figure/, docs/figure-elements.md) that evaluate
// back to the exact line/arc contours a DXF drawing gives (core/dxf/), so
// that an imported outline becomes text the operator reads and edits. See
// docs/dxf-import.md, "From contours to figure elements". The writing of
// one contour is contour_writer.h, the names contour_names.h.
#pragma once

#include "model/contour.h"

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa {

// How the new elements are named: P1, L1, C1, K1... (points, lines,
// circles, contours, numbered on through all contours), each number skipped
// whose name is in `taken` (compared without regard to case, as the figure
// language reads names); `prefix` goes before every name ("D": DP1, DL1,
// DC1, DK1). The prefix must be letters and digits starting with a letter,
// or empty (std::logic_error otherwise: the caller's prefix).
struct FigureNaming {
    std::set<std::string> taken;
    std::string prefix;
};

// The names a figure text defines (every `NAME =` at the start of a
// statement), upper case; read line by line, so also from a text that the
// parser refuses further on.
std::set<std::string> figureNames(std::string_view figureText);

// Numbers are written rounded to this (mm).
constexpr double kFigureGrid = 1e-6;
// A contour whose text evaluates back within this (mm) of it, segment by
// segment (ends and centres), is exact; farther, a note says by how much.
constexpr double kFigureRoundTrip = 1e-6;
// A contour that comes back farther than this (mm) is left out.
constexpr double kFigureUsable = 1e-3;

struct FigureFromContours {
    // The figure text: per contour a `$$` comment line, its points, circles,
    // lines and its CONTOUR statement; for a contour left out only the
    // comment, saying why.
    std::string text;
    // Per contour given, in order: its CONTOUR's name, or "" when left out.
    std::vector<std::string> names;
    // Per contour: the largest distance (mm) of an end or centre of the
    // evaluated text's contour from figureReady(contour); 0 when left out.
    std::vector<double> deviations;
    // "contour 3 is left out: ..." for every contour left out.
    std::vector<std::string> refusals;
    // "contour 2 comes back 0.0000031 mm from the drawing" for every
    // contour written but not within kFigureRoundTrip.
    std::vector<std::string> notes;
};

// The figure text of `contours` (mm), checked: each contour's statements
// are read back and evaluated, and compared with figureReady(contour).
FigureFromContours figureFromContours(const std::vector<Contour>& contours, const FigureNaming& naming = {});

// figureFromContours(...).text.
std::string figureTextFromContours(const std::vector<Contour>& contours, const FigureNaming& naming = {});

// The contour as its figure text gives it back: segments shorter than 1e-9
// mm left out, consecutive lines merged where their common end lies within
// 1e-7 mm of the line through their outer ends (running on the same way),
// consecutive arcs merged that turn the same way round the same circle
// (centres and radii within 1e-7 mm; a closed contour's last and first too,
// so that it may then start earlier), and a closed contour that is one
// full circle starting at its point at angle 0, as CONTOUR/CCLW, C1 does.
Contour figureReady(const Contour& c);

}  // namespace taiwa
