// Tool types by name (sources of the station's translation) and key; a tool's cutting data for a material.
#include "model/tool.h"
#include "model/translate_noop.h"

#include <array>
#include <utility>

namespace taiwa {

namespace {
constexpr std::array<std::pair<const char*, const char*>, 13> kToolTypeNames{{
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "centre drill"), "centre_drill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "drill"), "drill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "flat end mill"), "flat_end_mill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "ball end mill"), "ball_end_mill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "taper end mill"), "taper_end_mill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "face mill"), "face_mill"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "turning insert"), "turning_insert"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "grooving tool"), "grooving"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "threading tool"), "threading"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "probe"), "probe"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "tap"), "tap"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "reamer"), "reamer"},
    {TAIWA_TRANSLATE_NOOP("taiwa::msg", "boring bar"), "boring_bar"},
}};
}  // namespace

const char* toString(ToolType t) { return kToolTypeNames[static_cast<std::size_t>(t)].first; }
const char* toKey(ToolType t) { return kToolTypeNames[static_cast<std::size_t>(t)].second; }

std::optional<ToolType> toolTypeFromKey(const std::string& key)
{
    for (std::size_t i = 0; i < kToolTypeNames.size(); ++i)
        if (key == kToolTypeNames[i].second) return static_cast<ToolType>(i);
    return std::nullopt;
}

const CuttingData* Tool::cuttingFor(const std::string& material) const
{
    for (const auto& c : cutting)
        if (c.material == material) return &c;
    return nullptr;
}

const Tool* findTool(const std::vector<Tool>& library, int id)
{
    for (const auto& t : library)
        if (t.id == id) return &t;
    return nullptr;
}

}  // namespace taiwa
