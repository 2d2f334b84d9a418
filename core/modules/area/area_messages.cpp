// The wording of area_messages.h: the messages of AREA, area clearing by drawn
// passes: its points, passes, end mill and the area left unswept.
#include "modules/area/area_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

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

}  // namespace taiwa::msg
