// The figure language (figure_text.h): element kinds and keywords,
// parseFigure and the writer. The lexer is figure_lexer.h, the parser
// figure_parser.h and figure_parse_elements.cpp. The parser also checks what text alone can check: names
// defined once and before use, each argument of the kind its place needs,
// positive radii and distances; for contours, a direction before every circle,
// modifiers only where two elements may meet twice, corners only between two
// elements. Geometry is figure_eval.cpp's and figure_contour.cpp's.
#include "figure/figure_text.h"
#include "figure/figure_parser.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <system_error>

namespace taiwa::figure {

Kind kindOf(Method m)
{
    switch (m) {
    case Method::PointXY:
    case Method::PointIntof:
    case Method::PointCenter: return Kind::Point;
    case Method::LineTwoPoints:
    case Method::LineAtAngle:
    case Method::LineParallel:
    case Method::LinePointTangent:
    case Method::LineTwoCircles: return Kind::Line;
    case Method::CircleCenterRadius:
    case Method::CircleThreePoints:
    case Method::CircleTwoLines:
    case Method::CircleLineCircle: return Kind::Circle;
    case Method::Contour: return Kind::Contour;
    }
    throw std::logic_error("figure: unknown method");
}

namespace {

// Each kind's keyword and noun, in the order of Kind.
struct KindWords {
    const char* keyword;
    const char* noun;
};
constexpr std::array<KindWords, 4> kKindWords{{
    {"POINT", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point")},
    {"LINE", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line")},
    {"CIRCLE", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle")},
    {"CONTOUR", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a contour")},
}};
static_assert(kKindWords.size() == static_cast<std::size_t>(Kind::Contour) + 1, "a word for every kind");

// The modifiers' words, in the order of Modifier; the parser reads them
// back through this table (text::modifierWords).
constexpr std::array<const char*, 8> kModifierWords{"XLARGE", "XSMALL", "YLARGE", "YSMALL",
                                                    "LEFT",   "RIGHT",  "OUT",    "IN"};
static_assert(kModifierWords.size() == static_cast<std::size_t>(Modifier::In) + 1, "a word for every modifier");

// The entry of `value` in a table in the enumeration's order.
template <class Table, class Enum>
const auto& entryOf(const Table& table, Enum value, const char* what)
{
    const auto i = static_cast<std::size_t>(value);
    if (i >= table.size()) throw std::logic_error(std::string("figure: unknown ") + what);
    return table[i];
}

}  // namespace

const char* keyword(Kind k) { return entryOf(kKindWords, k, "kind").keyword; }

const char* noun(Kind k) { return entryOf(kKindWords, k, "kind").noun; }

const char* keyword(Modifier m) { return entryOf(kModifierWords, m, "modifier"); }

std::string FigureError::text() const
{
    return std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

using text::Parser;

ParseResult parseFigure(std::string_view text)
{
    ParseResult r;
    try {
        Parser p(text);
        r.definitions = p.statements();
    } catch (const Refusal& refusal) {
        r.definitions.clear();
        r.error = FigureError{refusal.place().line, refusal.place().column, refusal.message()};
    }
    return r;
}

// ---------------------------------------------------------------- writer

std::string formatNumber(double v)
{
    if (v == 0) return "0";  // also -0
    // Fixed notation (the language has no exponent), shortest that reads back
    // to the same double; |v| <= kMaxNumber keeps it short enough.
    std::array<char, 400> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed);
    if (r.ec != std::errc()) throw std::logic_error("figure: number too long to write");
    return std::string(buf.data(), r.ptr);
}

std::string writeDefinition(const Definition& d)
{
    // Indexed, not through counting lambdas: the operands of + are not
    // evaluated in a guaranteed order.
    const auto r = [&](std::size_t i) { return d.refs.at(i); };
    const auto m = [&](std::size_t i) { return std::string(keyword(d.modifiers.at(i))); };
    const auto n = [&](std::size_t i) { return formatNumber(d.numbers.at(i)); };
    std::string s = d.name + " = " + keyword(d.kind()) + "/";
    switch (d.method) {
    case Method::PointXY: s += n(0) + ", " + n(1); break;
    case Method::PointIntof:
        if (!d.modifiers.empty()) s += m(0) + ", ";
        s += "INTOF, " + r(0) + ", " + r(1);
        break;
    case Method::PointCenter: s += "CENTER, " + r(0); break;
    case Method::LineTwoPoints: s += r(0) + ", " + r(1); break;
    case Method::LineAtAngle: s += r(0) + ", ATANGL, " + n(0); break;
    case Method::LineParallel: s += "PARLEL, " + r(0) + ", " + m(0) + ", " + n(0); break;
    case Method::LinePointTangent: s += r(0) + ", " + m(0) + ", TANTO, " + r(1); break;
    case Method::LineTwoCircles: s += m(0) + ", TANTO, " + r(0) + ", " + m(1) + ", TANTO, " + r(1); break;
    case Method::CircleCenterRadius: s += "CENTER, " + r(0) + ", RADIUS, " + n(0); break;
    case Method::CircleThreePoints: s += r(0) + ", " + r(1) + ", " + r(2); break;
    case Method::CircleTwoLines: s += m(0) + ", " + r(0) + ", " + m(1) + ", " + r(1) + ", RADIUS, " + n(0); break;
    case Method::CircleLineCircle:
        s += m(0) + ", " + r(0) + ", " + m(1) + ", " + m(2) + ", " + r(1) + ", RADIUS, " + n(0);
        break;
    case Method::Contour: {
        const ContourText& c = d.contour;
        std::string items = c.start.empty() ? "" : c.start + ", ";
        for (const auto& st : c.steps) {
            if (st.junction) items += std::string(keyword(*st.junction)) + ", ";
            if (st.turn != Turn::None) items += st.turn == Turn::Clockwise ? "CLW, " : "CCLW, ";
            items += st.element + ", ";
            if (st.corner != CornerKind::None)
                items += (st.corner == CornerKind::Round ? "ROUND, " : "CHAMF, ") + formatNumber(st.value) + ", ";
        }
        if (!c.end.empty()) items += c.end + ", ";
        s += items.substr(0, items.size() >= 2 ? items.size() - 2 : 0);
        break;
    }
    }
    return s;
}

std::string writeFigure(const std::vector<Definition>& definitions)
{
    std::string s;
    for (const auto& d : definitions) s += writeDefinition(d) + "\n";
    return s;
}

}  // namespace taiwa::figure
