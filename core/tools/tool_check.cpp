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
    if (t.id < 1 || t.id > kMaxToolNumber)
        bad("id", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T number {} must be 1 to {}"), t.id, kMaxToolNumber));
    if (t.name.empty() || t.name.find_first_not_of(' ') == std::string::npos) bad("name", "the name must not be empty");
    if (!(t.diameter > 0) || !finite(t.diameter))
        bad("diameter", "diameter " + fmt::format("{:g}", t.diameter) + " mm must be greater than zero");
    else if (t.diameter > 500)
        bad("diameter",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "diameter {:g} mm is more than 500 mm"), t.diameter));
    if (!(t.cornerRadius >= 0) || !finite(t.cornerRadius))
        bad("cornerRadius",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "corner radius {:g} mm must not be negative"),
                        t.cornerRadius));
    else if (t.diameter > 0 && t.cornerRadius > t.diameter / 2 + 1e-9 && t.type != ToolType::TurningInsert &&
             t.type != ToolType::Grooving && t.type != ToolType::Threading)
        bad("cornerRadius",
            fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "corner radius {:g} mm is more than half the diameter ({:g} mm)"),
                t.cornerRadius, t.diameter / 2));
    if (!(t.taperAngle >= 0 && t.taperAngle < 45) || !finite(t.taperAngle))
        bad("taperAngle",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "taper {:g}° per side must be 0 to less than 45°"),
                        t.taperAngle));
    if (!(t.fluteLength >= 0) || !finite(t.fluteLength))
        bad("fluteLength", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "flute length {:g} mm must not be negative"),
                                       t.fluteLength));
    if (!(t.holderDiameter >= 0) || !finite(t.holderDiameter))
        bad("holderDiameter",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder Ø {:g} mm must not be negative"), t.holderDiameter));
    else if (t.holderDiameter > 0 && t.holderDiameter + 1e-9 < t.diameter)
        bad("holderDiameter",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder Ø {:g} mm is narrower than the tool (Ø {:g} mm)"),
                        t.holderDiameter, t.diameter));
    if (!(t.holderLength >= 0) || !finite(t.holderLength))
        bad("holderLength",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder length {:g} mm must not be negative"),
                        t.holderLength));
    if (!(t.stickout >= 0) || !finite(t.stickout))
        bad("stickout",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "stick-out {:g} mm must not be negative"), t.stickout));
    else if (t.stickout > 0 && t.stickout + 1e-9 < t.fluteLength)
        bad("stickout",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "stick-out {:g} mm is shorter than the flutes ({:g} mm)"),
                        t.stickout, t.fluteLength));
    if (t.flutes < 1 && t.type != ToolType::Probe)  // a probe cuts nothing
        bad("flutes", "flutes " + std::to_string(t.flutes) + " must be at least 1");
    if (t.type == ToolType::Tap && (!(t.turning.pitchMin > 0) || !finite(t.turning.pitchMin) || t.turning.pitchMin > 10 ||
                                    t.turning.pitchMax != t.turning.pitchMin))
        bad("pitch",
            fmt::format(TAIWA_TRANSLATE_NOOP(
                            "taiwa::msg", "a tap's pitch {:g} mm must be greater than zero, at most 10 mm (one pitch)"),
                        t.turning.pitchMin));
    if (!(t.lifeMinutes >= 0) || !finite(t.lifeMinutes))
        bad("lifeMinutes",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "life {:g} min must not be negative"), t.lifeMinutes));
    if (!(t.usedMinutes >= 0) || !finite(t.usedMinutes))
        bad("usedMinutes",
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "used {:g} min must not be negative"), t.usedMinutes));
    for (const auto& cd : t.cutting) {
        const std::string at = "cutting[" + cd.material + "].";
        if (!(cd.surfaceSpeed > 0) || !finite(cd.surfaceSpeed))
            bad(at + "surfaceSpeed", "cutting speed for " + cd.material + " " + fmt::format("{:g}", cd.surfaceSpeed) +
                                         " m/min must be greater than zero");
        if (!(cd.feedPerTooth > 0) || !finite(cd.feedPerTooth))
            bad(at + "feedPerTooth", "feed per tooth for " + cd.material + " " + fmt::format("{:g}", cd.feedPerTooth) +
                                         " mm must be greater than zero");
        if (!(cd.plungeFactor > 0) || !finite(cd.plungeFactor))
            bad(at + "plungeFactor", "plunge factor for " + cd.material + " " + fmt::format("{:g}", cd.plungeFactor) +
                                         " must be greater than zero");
    }
    return out;
}

}  // namespace taiwa
