// The wording of pocket_messages.h: the messages of the pockets (M4, M2D, CP):
// their codes (tool use, wall finish, pilot hole) and corner radius.
#include "modules/pocket_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

std::string toolUseUnknown(int code)
{
    if (code >= 2 && code <= 5)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool-use code U = {} is not defined (codes 2 to 5 are "
                                                              "reserved); use 1, 6, 7, 8 or 9"),
                           code);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool-use code U = {} does not exist; use 1, 6, 7, 8 or 9"), code);
}

std::string wallFinishUnknown(int code)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "finishing code F = {} does not exist; use 1, 2 or 3"), code);
}

std::string pilotHoleUnknown(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "pilot-hole code H = {} does not exist; use 0 (drill a pilot hole) or 9 (none)"),
        code);
}

std::string radiusNegative(Len r1)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius is {}; it cannot be negative"), quote(r1));
}

std::string toolUseNotForContours(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "U {} is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 (walls "
                          "only) or 9 (roughing only)"),
        code);
}

}  // namespace taiwa::msg
