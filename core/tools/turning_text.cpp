// The tool library's `turning` column (turning_text.h).
#include "tools/turning_text.h"

#include <nlohmann/json.hpp>

namespace taiwa {

std::string turningText(const TurningSpec& t)
{
    if (t.empty()) return "";
    return nlohmann::json{{"insertCode", t.insertCode}, {"approachAngle", t.approachAngle}, {"hand", t.hand},
                          {"inside", t.inside},         {"minBore", t.minBore},             {"width", t.width},
                          {"maxDepth", t.maxDepth},     {"maxDiameter", t.maxDiameter},     {"pitchMin", t.pitchMin},
                          {"pitchMax", t.pitchMax},     {"threadAngle", t.threadAngle}}
        .dump();
}

std::optional<TurningSpec> turningFrom(const std::string& text)
{
    TurningSpec t;
    if (text.empty()) return t;
    const auto j = nlohmann::json::parse(text, nullptr, false);
    if (!j.is_object()) return std::nullopt;
    try {
        t.insertCode = j.value("insertCode", "");
        t.approachAngle = j.value("approachAngle", 0.0);
        t.hand = j.value("hand", "");
        t.inside = j.value("inside", false);
        t.minBore = j.value("minBore", 0.0);
        t.width = j.value("width", 0.0);
        t.maxDepth = j.value("maxDepth", 0.0);
        t.maxDiameter = j.value("maxDiameter", 0.0);
        t.pitchMin = j.value("pitchMin", 0.0);
        t.pitchMax = j.value("pitchMax", 0.0);
        t.threadAngle = j.value("threadAngle", 0.0);
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
    return t;
}

}  // namespace taiwa
