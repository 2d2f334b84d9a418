// The checks of one tool (tool_check.h).
#include "tools/tool_check.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa {

std::vector<ToolProblem> toolProblems(const Tool& t)
{
    std::vector<ToolProblem> out;
    const auto bad = [&](std::string field, std::string message) { out.push_back({std::move(field), std::move(message)}); };
    const auto finite = [](double v) { return std::isfinite(v); };
    // A figure that must not be negative (nor be NaN or infinite): refused on
    // `field` in the words of `text`; whether it passed.
    const auto notNegative = [&](const char* field, const double v, fmt::format_string<const double&> text) {
        if (v >= 0 && finite(v)) return true;
        bad(field, fmt::format(text, v));
        return false;
    };
    // A figure that, when given (above zero), must not fall short of `least`:
    // refused on `field` in the words of `text` (the figure, then `least`).
    const auto notShortOf = [&](const char* field, const double v, const double least,
                                fmt::format_string<const double&, const double&> text) {
        if (v > 0 && v + 1e-9 < least) bad(field, fmt::format(text, v, least));
    };
    // A figure that must be greater than zero (and finite): refused on
    // `field` as "<what> <v><unit> must be greater than zero"; whether it passed.
    const auto positive = [&](std::string field, double v, const std::string& what, const char* unit) {
        if (v > 0 && finite(v)) return true;
        bad(std::move(field), what + " " + fmt::format("{:g}", v) + unit + " must be greater than zero");
        return false;
    };
    if (t.id < 1 || t.id > kMaxToolNumber)
        bad("id", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T number {} must be 1 to {}"), t.id, kMaxToolNumber));
    if (t.name.empty() || t.name.find_first_not_of(' ') == std::string::npos) bad("name", "the name must not be empty");
    if (positive("diameter", t.diameter, "diameter", " mm") && t.diameter > 500)
        bad("diameter",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "diameter {:g} mm is more than 500 mm"), t.diameter));
    if (notNegative("cornerRadius", t.cornerRadius,
                    TAIWA_TRANSLATE_NOOP("taiwa::msg", "corner radius {:g} mm must not be negative")) &&
        t.diameter > 0 && t.cornerRadius > t.diameter / 2 + 1e-9 && t.type != ToolType::TurningInsert &&
        t.type != ToolType::Grooving && t.type != ToolType::Threading)
        bad("cornerRadius",
            fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "corner radius {:g} mm is more than half the diameter ({:g} mm)"),
                t.cornerRadius, t.diameter / 2));
    if (!(t.taperAngle >= 0 && t.taperAngle < 45) || !finite(t.taperAngle))
        bad("taperAngle",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "taper {:g}° per side must be 0 to less than 45°"),
                        t.taperAngle));
    notNegative("fluteLength", t.fluteLength,
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "flute length {:g} mm must not be negative"));
    if (notNegative("holderDiameter", t.holderDiameter,
                    TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder Ø {:g} mm must not be negative")))
        notShortOf("holderDiameter", t.holderDiameter, t.diameter,
                   TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder Ø {:g} mm is narrower than the tool (Ø {:g} mm)"));
    notNegative("holderLength", t.holderLength,
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder length {:g} mm must not be negative"));
    if (notNegative("stickout", t.stickout, TAIWA_TRANSLATE_NOOP("taiwa::msg", "stick-out {:g} mm must not be negative")))
        notShortOf("stickout", t.stickout, t.fluteLength,
                   TAIWA_TRANSLATE_NOOP("taiwa::msg", "stick-out {:g} mm is shorter than the flutes ({:g} mm)"));
    if (t.flutes < 1 && t.type != ToolType::Probe)  // a probe cuts nothing
        bad("flutes", "flutes " + std::to_string(t.flutes) + " must be at least 1");
    if (t.type == ToolType::Tap && (!(t.turning.pitchMin > 0) || !finite(t.turning.pitchMin) || t.turning.pitchMin > 10 ||
                                    t.turning.pitchMax != t.turning.pitchMin))
        bad("pitch",
            fmt::format(TAIWA_TRANSLATE_NOOP(
                            "taiwa::msg", "a tap's pitch {:g} mm must be greater than zero, at most 10 mm (one pitch)"),
                        t.turning.pitchMin));
    notNegative("lifeMinutes", t.lifeMinutes, TAIWA_TRANSLATE_NOOP("taiwa::msg", "life {:g} min must not be negative"));
    notNegative("usedMinutes", t.usedMinutes, TAIWA_TRANSLATE_NOOP("taiwa::msg", "used {:g} min must not be negative"));
    for (const auto& cd : t.cutting) {
        const std::string at = "cutting[" + cd.material + "].";
        positive(at + "surfaceSpeed", cd.surfaceSpeed, "cutting speed for " + cd.material, " m/min");
        positive(at + "feedPerTooth", cd.feedPerTooth, "feed per tooth for " + cd.material, " mm");
        positive(at + "plungeFactor", cd.plungeFactor, "plunge factor for " + cd.material, "");
    }
    return out;
}

}  // namespace taiwa
