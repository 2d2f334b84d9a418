// The wording of region_messages.h: the messages of units on contours of the
// figure (CP, AREA, SIDE, and the pockets' outline in the stock): naming,
// closing and crossing contours, islands, sharp corners.
#include "modules/region_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

std::string outsideStock(const std::string& figure)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} reaches outside the stock; move it or enlarge the stock"), figure);
}

std::string contourNotNamed(const std::string& role)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "name the contour of the pocket's {} (a CONTOUR of the job's figure elements)"),
        role);
}

std::string contourUnknown(const std::string& name, const std::vector<std::string>& known)
{
    if (known.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                 "{} is not a contour of the job's figure elements, which define no contour"),
            name);
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a contour of the job's figure elements (its contours: {})"), name,
        fmt::join(known, ", "));
}

std::string contourOpen(const std::string& name, const std::string& what, const std::string& role)
{
    if (what.starts_with("a"))
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} is an open contour; an {}'s {} must be closed (a contour "
                                                "without a start and end point)"),
                           name, what, role);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is an open contour; a {}'s {} must be closed (a contour "
                                                          "without a start and end point)"),
                       name, what, role);
}

std::string contourCrossesItself(const std::string& name)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} crosses itself; check the order of its elements and the side chosen at each junction"),
        name);
}

std::string islandOutside(const std::string& island, const std::string& what, const std::string& outline)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the island {} reaches outside the {}'s outline {}"), island,
                       what, outline);
}

std::string islandsOverlap(const std::string& a, const std::string& b)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the islands {} and {} overlap; make them one contour"), a,
                       b);
}

std::string sharpInsideCorner(const std::string& name, Len x, Len y)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "{} has a sharp inside corner at ({}, {}): an end mill cannot cut it and leaves its own radius "
            "there; round the corner (ROUND) in the contour"),
        name, quote(x), quote(y));
}

}  // namespace taiwa::msg
