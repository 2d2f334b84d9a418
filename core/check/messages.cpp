// The wording of every input-processing message (see messages.h): the
// quoting of lengths and tools, job-level, drawn-pass, diameter and overlap
// messages. Shapes: messages_shapes.cpp; codes and tools: messages_codes.cpp.
#include "check/messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace taiwa::msg {

namespace {
// Fixed decimals with trailing zeros trimmed and no "-0"; a number of a
// billion or more with 6 significant digits ("1e+308", not 309 digits).
std::string trimmed(double v, int decimals)
{
    if (!(std::abs(v) < 1e9)) return fmt::format("{:.6g}", v);
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}
}  // namespace

std::string quote(Len v)
{
    const double shown = fromMm(v.mm, v.unit);
    std::string text = trimmed(shown, v.unit == LengthUnit::Inch ? 4 : 3);
    // A value too small for the usual decimals is not "0": its significant digits.
    if (shown != 0.0 && (text == "0" || text == "-0")) text = fmt::format("{:g}", shown);
    return text + " " + unitSymbol(v.unit);
}

std::string quoteDeg(double deg)
{
    // An angle just past a whole one ("-360.0000001") is not shown as the
    // whole one the message names as its bound: its own digits then.
    std::string text = trimmed(deg, 3);
    if (std::abs(deg) < 1e9 && deg != std::round(deg) && text.find('.') == std::string::npos) text = fmt::format("{:.10g}", deg);
    return text + "°";
}

std::string toolName(const Tool& t)
{
    if (t.type == ToolType::TurningInsert && !t.turning.insertCode.empty())  // inserts by their code and nose
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} {}, nose R{} mm)"), t.id, toString(t.type),
                           t.turning.insertCode, trimmed(t.cornerRadius, 3));
    if (t.type == ToolType::TaperEndMill)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} Ø{} mm, {} per side)"), t.id, toString(t.type),
                           trimmed(t.diameter, 3), quoteDeg(t.taperAngle));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} Ø{} mm)"), t.id, toString(t.type),
                       trimmed(t.diameter, 3));
}

std::string notFinite(const std::string& what)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a finite number; type a number"), what);
}

std::string unknownMaterial(const std::string& id, const std::vector<std::string>& known)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "material \"{}\" is not in the technology table; known materials: {}"), id,
        fmt::join(known, ", "));
}

std::string stockNotPositive(const std::string& what, Len v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the stock {} is {}; it must be greater than zero"), what,
                       quote(v));
}

std::string technologyNotPositive(const std::string& name, double shownValue, const std::string& unitText)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} = {}{} must be greater than zero"), name,
                       trimmed(shownValue, 4), unitText);
}

std::string alpha3NotBelowAlpha2(Len a3, Len a2)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the final wall allowance α3 = {} must be smaller than the roughing wall allowance α2 = {}"),
        quote(a3), quote(a2));
}

std::string alpha1NotBelowDepth(int unitNo, Len a1, Len depth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the pilot-hole remainder α1 = {} is not smaller than the depth {} of unit {}: "
                             "the pilot hole would have no depth; use H = 9 or a smaller α1"),
        quote(a1), quote(depth), unitNo);
}

std::string beta2NotBelowDepth(int unitNo, Len b2, Len depth)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "the floor allowance β2 = {} is not smaller than the depth {} of unit {}: "
                                            "roughing would not cut at all"),
                       quote(b2), quote(depth), unitNo);
}

std::string beyondReach(const std::string& what, Len value, Len limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} is {}; every length and coordinate must lie within ±{} of the origin (beyond it a "
                             "micrometre is no longer exact on the tape)"),
        what, quote(value), quote(limit));
}

std::string technologyOutOfRange(const std::string& name, double shownValue, double low, double high,
                                 const std::string& unitText, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is {:g}{}; it must lie between {:g} and {:g}{} ({})"),
                       name, shownValue, unitText, low, high, unitText, why);
}

std::string scallopTooSmall(Len scallop, Len smallest)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "the scallop height is {}; it must be at least {} (a smaller one multiplies the passes of the "
            "inclined faces without a finer surface any machine holds)"),
        quote(scallop), quote(smallest));
}

std::string stockTooLarge(const std::string& key, Len value, Len limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the stock {} is {}; a stock of more than {} a side is not a part for this station"),
        key, quote(value), quote(limit));
}

std::string depthNotPositive(Len depth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the depth is {}; it must be greater than zero (measured down from the top face)"),
        quote(depth));
}

std::string deeperThanStock(Len depth, Len stockHeight)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth {} is deeper than the stock, which is {} high"),
                       quote(depth), quote(stockHeight));
}

std::string lengthNotPositive(const std::string& name, Len v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is {}; it must be greater than zero"), name, quote(v));
}

std::string radiusNegative(Len r1)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius is {}; it cannot be negative"), quote(r1));
}

std::string outsideStock(const std::string& figure)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} reaches outside the stock; move it or enlarge the stock"), figure);
}

std::string duplicateCorner(int first, int second, Len x, Len y)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "P{} and P{} are the same point ({}, {}); the outline needs four distinct corners"),
        first, second, quote(x), quote(y));
}

std::string pointsUnreadable(const std::string& typed)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "'{}' is not a list of points; type each point as X, Y and separate the points with ';' "
                             "(10, 20; 60, 20), or draw the passes in the Figure tab"),
        typed);
}

std::string tooFewPoints(std::size_t count)
{
    if (count == 0)
        return TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "no point is drawn; a pass runs from a start point to an end point: draw at least two points");
    return TAIWA_TRANSLATE_NOOP(
        "taiwa::msg",
        "only one point is drawn; a pass runs from a start point to an end point: draw at least two points");
}

std::string pointOutsideStock(std::size_t index, Len x, Len y)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {} ({}, {}) lies outside the stock"), index, quote(x),
                       quote(y));
}

std::string passSamePoint(int pass)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pass {} ends where it starts; remove the repeated point"),
                       pass);
}

std::string passLeavesArea(int pass, Len x, Len y, Len by, const std::string& outline)
{
    if (pass == 0)
        return fmt::format(
            TAIWA_TRANSLATE_NOOP(
                "taiwa::msg", "the start point ({}, {}) puts the tool's edge {} outside the area {} or into an island; "
                              "start at least a tool radius inside"),
            quote(x), quote(y), quote(by), outline);
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "pass {} takes the tool's edge {} outside the area {} (or into an island) with the tool's centre "
            "at ({}, {}); keep each pass a tool radius from the walls"),
        pass, quote(by), outline, quote(x), quote(y));
}

std::string diameterNotPositive(Len d)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the tool diameter is {}; it must be positive: the passes are strips one tool wide"),
        quote(d));
}

std::string noToolOfDiameter(Len d, const std::vector<double>& diametersMm, LengthUnit unit)
{
    std::vector<std::string> shown;
    for (const double v : diametersMm) shown.push_back(quote({v, unit}));
    if (shown.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP(
                "taiwa::msg",
                "the library has no centre-cutting flat end mill of {} (nor of any diameter) for the drawn "
                "passes"),
            quote(d));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the library has no centre-cutting flat end mill of {}, the width the passes were drawn for; "
                          "its flat end mills: {}"),
        quote(d), fmt::join(shown, ", "));
}

std::string pinnedDiameterDiffers(const Tool& pinned, Len d)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} is pinned, but the passes were drawn for a tool of {}; pin a tool of that diameter or "
                             "change the diameter and redraw"),
        toolName(pinned), quote(d));
}

std::string unswept(double areaMm2, int pieces, double largestMm2, Len x, Len y, LengthUnit unit)
{
    const double f = unit == LengthUnit::Inch ? 1.0 / (25.4 * 25.4) : 1.0;
    const char* u = unit == LengthUnit::Inch ? "in²" : "mm²";
    const int decimals = unit == LengthUnit::Inch ? 4 : 1;
    const std::string area = fmt::format("{:.{}f} {}", areaMm2 * f, decimals, u);
    const std::string largest = fmt::format("{:.{}f} {}", largestMm2 * f, decimals, u);
    if (pieces == 1)
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                 "the passes leave {} of the area unswept in {} place; the largest, {}, near ({}, {})"),
            area, pieces, largest, quote(x), quote(y));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the passes leave {} of the area unswept in {} places; the largest, {}, near ({}, {})"),
        area, pieces, largest, quote(x), quote(y));
}

std::string overlap(int unitNo, int otherUnitNo, double areaMm2, LengthUnit unit)
{
    const double shown = unit == LengthUnit::Inch ? areaMm2 / (kMillimetresPerInch * kMillimetresPerInch) : areaMm2;
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the figure of unit {} overlaps the figure of unit {} by {} {}²; figures of one job may "
                             "touch but not overlap"),
        unitNo, otherUnitNo, trimmed(shown, unit == LengthUnit::Inch ? 6 : 4), unitSymbol(unit));
}

}  // namespace taiwa::msg
