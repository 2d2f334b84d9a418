// The tool library's `turning` column (turning_text.h).
#include "tools/turning_text.h"

#include <nlohmann/json.hpp>

#include <type_traits>

namespace taiwa {

namespace {

// Each field of the column: its JSON key and the spec's member, for writing
// and reading alike (Spec: TurningSpec, const or not).
template <class Spec, class Visit>
void eachField(Spec& t, Visit&& visit)
{
    visit("insertCode", t.insertCode);
    visit("approachAngle", t.approachAngle);
    visit("hand", t.hand);
    visit("inside", t.inside);
    visit("minBore", t.minBore);
    visit("width", t.width);
    visit("maxDepth", t.maxDepth);
    visit("maxDiameter", t.maxDiameter);
    visit("pitchMin", t.pitchMin);
    visit("pitchMax", t.pitchMax);
    visit("threadAngle", t.threadAngle);
}

}  // namespace

std::string turningText(const TurningSpec& t)
{
    if (t.empty()) return "";
    nlohmann::json j = nlohmann::json::object();  // its keys sorted, as the column has always held them
    eachField(t, [&](const char* key, const auto& value) { j[key] = value; });
    return j.dump();
}

std::optional<TurningSpec> turningFrom(const std::string& text)
{
    TurningSpec t;
    if (text.empty()) return t;
    const auto j = nlohmann::json::parse(text, nullptr, false);
    if (!j.is_object()) return std::nullopt;
    try {
        // A missing key: the member's zero ("", 0, false).
        eachField(t, [&](const char* key, auto& value) { value = j.value(key, std::decay_t<decltype(value)>{}); });
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
    return t;
}

}  // namespace taiwa
