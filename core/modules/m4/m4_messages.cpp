// The wording of m4_messages.h: the messages of M4, the four-cornered pocket:
// its corners, radius, taper and allowances.
#include "modules/m4/m4_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

std::string alpha3NotBelowAlpha2(Len a3, Len a2)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the final wall allowance α3 = {} must be smaller than the roughing wall allowance α2 = {}"),
        quote(a3), quote(a2));
}

std::string duplicateCorner(int first, int second, Len x, Len y)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "P{} and P{} are the same point ({}, {}); the outline needs four distinct corners"),
        first, second, quote(x), quote(y));
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

}  // namespace taiwa::msg
