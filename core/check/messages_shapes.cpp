// The wording of the messages about a unit's shape (messages.h): contours
// and islands, the M4 and M2D pockets' corners, radii, taper and floor, and
// the side milling's contour, codes and channel.
#include "check/messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

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

std::string toolUseNotForContours(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "U {} is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 (walls "
                          "only) or 9 (roughing only)"),
        code);
}

std::string selfIntersecting()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "the outline crosses itself; enter the corners P1..P4 in order around the pocket");
}

std::string notConvex()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "the outline is not convex (a corner points inward or three corners are in line)");
}

std::string radiusOverHalfSide(Len r1, Len shortestSide)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius {} is larger than half the shortest side ({} long)"),
        quote(r1), quote(shortestSide));
}

std::string radiusOverInscribed(Len r1, Len inscribed)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the corner radius {} does not fit: the largest circle inside the outline has radius {}"),
        quote(r1), quote(inscribed));
}

std::string radiusOverHalfL2(Len r1, Len l2)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius {} is larger than half of L2 = {}"),
                       quote(r1), quote(l2));
}

std::string taperOutOfRange(double taper)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the taper {} per side is outside 0° to 30°"),
                       quoteDeg(taper));
}

std::string taperClosesPocket(double taper, Len meetDepth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "with a taper of {} per side the walls meet at depth {}, above the floor"),
        quoteDeg(taper), quote(meetDepth));
}

std::string thetaOutOfRange(const std::string& name, double theta)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} = {} is outside 0° to under 60° (measured from the vertical)"), name,
        quoteDeg(theta));
}

std::string floorVanishes(Len floorWidth, Len needed, Len shortBy)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the inclined walls leave a floor {} wide along L1; it must be wider than 2 × r1 = {} "
                             "(short by {}): reduce the angles or the depth, or lengthen L1"),
        quote(floorWidth), quote(needed), quote(shortBy));
}

std::string sideContourNotNamed()
{
    return TAIWA_TRANSLATE_NOOP(
        "taiwa::msg",
        "name the contour the side milling follows (a CONTOUR of the job's figure elements, open or closed)");
}

std::string sideCodeUnknown(const std::string& code, int value, const std::string& allowed)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {} is not a code of side milling; use {}"), code, value,
                       allowed);
}

std::string sideWidthNotAboveAllowance(Len width, Len alpha2)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the width W is {}; roughing leaves α2 = {} on the wall, so W must be larger than that"),
        quote(width), quote(alpha2));
}

std::string sidePinKeyUnknown(const std::string& key)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "\"{}\" is not a step of side milling; pin its end mill under \"side\" (roughing and finishing)"),
        key);
}

std::string sideNoTool(const std::string& step, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), step, why);
}

std::string sideChannelTooNarrow(const std::string& name, const std::string& tool, Len x, Len y)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP(
                           "taiwa::msg",
                           "{} does not fit where {} narrows near ({}, {}): the tool would cut into the contour there; "
                           "pin a smaller end mill or widen the channel"),
                       tool, name, quote(x), quote(y));
}

}  // namespace taiwa::msg
