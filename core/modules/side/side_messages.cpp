// The wording of side_messages.h: the messages of SIDE, side milling along a
// contour: its contour, codes, width, pins and room.
#include "modules/side/side_messages.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

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
