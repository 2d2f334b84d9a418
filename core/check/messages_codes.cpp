// The wording of the messages about pins, cutting data and tools
// (messages.h): unknown pin and cutting keys, cutting values out of range,
// tools missing from the library or too large.
#include "check/messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

std::string unknownStepKey(const std::string& key, const std::string& module, const std::vector<std::string>& keys)
{
    std::string list;
    for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "\"{}\" is not a step of module {}; its steps are {}"), key,
                       module, list);
}

std::string noCuttingSteps(const std::string& module)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "module {} has no cutting steps to set a speed or feed for"),
                       module);
}

std::string cuttingValueOutOfRange(const std::string& what, double value, const std::string& unit, double low,
                                   double high, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {:g} {} is out of range: give {:g} to {:g} {}{}"), what,
                       value, unit, low, high, unit, why);
}

std::string toolNotInLibrary(int id)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool T{} is not in the tool library"), id);
}

std::string noToolOfType(const std::string& typeName)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no {}; add one to machine this pocket"),
                       typeName);
}

std::string noTaperTool(double taper, const std::vector<double>& anglesInLibrary)
{
    std::vector<std::string> shown;
    for (const double a : anglesInLibrary) shown.push_back(quoteDeg(a));
    if (shown.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "no taper end mill of {} per side in the tool library (it has none)"),
            quoteDeg(taper));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "no taper end mill of {} per side in the tool library (it has {})"),
        quoteDeg(taper), fmt::join(shown, ", "));
}

std::string noRoomForTool(const std::string& label, Len available, const Tool& smallest, Len neededR1)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} = {} is smaller than the radius of the smallest suitable tool, {}; "
                             "no tool of the library fits: a corner radius of at least {} would let it fit"),
        label, quote(available), toolName(smallest), quote(neededR1));
}

std::string pinnedToolTooBig(const std::string& step, const Tool& pinned, const std::string& label, Len available,
                             const Tool* fitting)
{
    const std::string hint =
        fitting ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} would fit"), toolName(*fitting))
                : std::string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no tool of that kind in the library fits"));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} tool {} is too big for {} = {}; {}"), step,
                       toolName(pinned), label, quote(available), hint);
}

}  // namespace taiwa::msg
