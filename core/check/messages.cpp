// The wording of the shared input-processing messages (see messages.h): the
// quoting of lengths and tools, job-level, depth and overlap messages. Pins,
// cutting data and tools: messages_codes.cpp; a module's own: its folder.
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
