// Figure elements as APT-like text: the statements an operator reads and
// edits (`P1 = POINT/10, 20`, `L1 = LINE/P1, P2`, `C1 = CIRCLE/CENTER, P3,
// RADIUS, 5`), their definitions as values, the parser that reads them back
// with line and column in every refusal, and the writer of canonical text.
// Contours (`K1 = CONTOUR/L1, ROUND, 2, XLARGE, CCLW, C1, L2`) are chains of
// lines and circles in tool-motion order. The language is described in
// docs/figure-elements.md; evaluation into coordinates is figure_eval.h (the
// contours' figure_contour.h).
#pragma once

#include "model/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::figure {

enum class Kind { Point, Line, Circle, Contour };

// Every way an element can be defined; the comment shows the statement.
enum class Method {
    PointXY,             // POINT/x, y
    PointIntof,          // POINT/INTOF, L1, L2   or   POINT/XLARGE, INTOF, L1, C1 (a circle involved)
    PointCenter,         // POINT/CENTER, C1
    LineTwoPoints,       // LINE/P1, P2
    LineAtAngle,         // LINE/P1, ATANGL, 30          (degrees from +X)
    LineParallel,        // LINE/PARLEL, L1, XLARGE, 5    (the side by modifier)
    LinePointTangent,    // LINE/P1, LEFT, TANTO, C1
    LineTwoCircles,      // LINE/LEFT, TANTO, C1, RIGHT, TANTO, C2
    CircleCenterRadius,  // CIRCLE/CENTER, P1, RADIUS, 5
    CircleThreePoints,   // CIRCLE/P1, P2, P3
    CircleTwoLines,      // CIRCLE/XLARGE, L1, YSMALL, L2, RADIUS, 5
    CircleLineCircle,    // CIRCLE/XLARGE, L1, YLARGE, OUT, C1, RADIUS, 5
    Contour,             // CONTOUR/L1, ROUND, 2, XLARGE, CCLW, C1, L2   (Definition::contour)
};

enum class Modifier { XLarge, XSmall, YLarge, YSmall, Left, Right, Out, In };

Kind kindOf(Method m);
const char* keyword(Kind k);      // "POINT", "LINE", "CIRCLE", "CONTOUR"
const char* keyword(Modifier m);  // "XLARGE", ..., "IN"
const char* noun(Kind k);         // "a point", "a line", "a circle", "a contour"

// Where something is written: 1-based line and column, length in bytes.
struct Place {
    int line = 0;
    int column = 0;
    int length = 0;
};
// The span's line and column as the place of a refusal (model/result.h).
inline taiwa::Place placeOf(const Place& at) { return taiwa::Place::inText(at.line, at.column); }

// A circle's direction in a contour (CLW, CCLW); None for a line.
enum class Turn { None, Clockwise, CounterClockwise };
enum class CornerKind { None, Round, Chamfer };

// One element of a contour as written: `[XLARGE,] [CLW|CCLW,] NAME [, ROUND|CHAMF, value]`.
struct ContourStep {
    std::string element;              // a line or a circle
    std::optional<Modifier> junction; // XLARGE...: which junction with the element before it
    Turn turn = Turn::None;           // circles: CLW or CCLW
    CornerKind corner = CornerKind::None;  // the corner with the next element (closed: the last's with the first)
    double value = 0;                 // the corner's radius (ROUND) or distance (CHAMF)
    // Where the name and the corner's value are written; not part of equality.
    Place at;
    Place valueAt;
    friend bool operator==(const ContourStep& a, const ContourStep& b)
    {
        return a.element == b.element && a.junction == b.junction && a.turn == b.turn && a.corner == b.corner &&
               a.value == b.value;
    }
};

// A contour statement's items. Open: from `start` (a point on the first
// element) to `end` (a point on the last); closed (no points): the last
// element joins the first.
struct ContourText {
    std::string start;
    std::string end;
    std::vector<ContourStep> steps;
    Place startAt;  // not part of equality
    Place endAt;
    bool closed() const { return start.empty(); }
    friend bool operator==(const ContourText& a, const ContourText& b)
    {
        return a.start == b.start && a.end == b.end && a.steps == b.steps;
    }
};

// One statement: `name = KIND/args`. The referenced elements, modifiers and
// numbers are kept in the order they are written, so the method and these
// three lists say everything the text says (a contour's items: `contour`).
struct Definition {
    std::string name;
    Method method = Method::PointXY;
    std::vector<std::string> refs;
    std::vector<Modifier> modifiers;
    std::vector<double> numbers;
    // Method::Contour only: its items (refs then lists every name it uses, in
    // order, for definedFrom; modifiers and numbers stay empty).
    ContourText contour;
    // Where the statement starts (its name), 1-based; not part of equality:
    // the same definitions written elsewhere are the same definitions.
    int line = 0;
    int column = 0;

    Kind kind() const { return kindOf(method); }
    friend bool operator==(const Definition& a, const Definition& b)
    {
        return a.name == b.name && a.method == b.method && a.refs == b.refs && a.modifiers == b.modifiers &&
               a.numbers == b.numbers && a.contour == b.contour;
    }
};

// A refusal of the text or of a definition: 1-based line and column (in
// bytes) and one plain sentence.
struct FigureError {
    int line = 0;
    int column = 0;
    std::string message;
    std::string text() const;  // "3:12: message"
    friend bool operator==(const FigureError&, const FigureError&) = default;
};

// The definitions read, or the first refusal. Reading stops at the first
// error: what follows it could only be misread.
struct ParseResult {
    std::vector<Definition> definitions;
    std::optional<FigureError> error;
    bool ok() const { return !error; }
};

// Largest magnitude a number may have (mm or degrees): keeps every coordinate
// finite and every written number short.
constexpr double kMaxNumber = 1.0e6;

ParseResult parseFigure(std::string_view text);

// Canonical text: one statement a line, upper case, ", " between arguments,
// numbers in their shortest form that reads back to the same double.
std::string writeFigure(const std::vector<Definition>& definitions);
std::string writeDefinition(const Definition& d);
std::string formatNumber(double v);

}  // namespace taiwa::figure
