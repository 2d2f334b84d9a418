// The wording of m2d_messages.h: the messages of M2D, the pocket with inclined
// faces: its radius, face angles, floor, scallop and tool use.
#include "modules/m2d/m2d_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

std::string scallopTooSmall(Len scallop, Len smallest)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "the scallop height is {}; it must be at least {} (a smaller one multiplies the passes of the "
            "inclined faces without a finer surface any machine holds)"),
        quote(scallop), quote(smallest));
}

std::string radiusOverHalfL2(Len r1, Len l2)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius {} is larger than half of L2 = {}"),
                       quote(r1), quote(l2));
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

std::string scallopNotPositive(Len scallop)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the scallop height is {}; it must be greater than zero (usual 0.01 mm)"),
        quote(scallop));
}

std::string toolUseNotForM2D(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "tool-use code U = {} is not allowed for M2D; use 1 (rough and finish) or 9 (rough only)"),
        code);
}

}  // namespace taiwa::msg
