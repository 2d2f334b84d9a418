// Tool types by name and key; a tool's cutting data for a material.
#include "model/tool.h"

#include <array>
#include <utility>

namespace taiwa {

namespace {
constexpr std::array<std::pair<const char*, const char*>, 13> kToolTypeNames{{
    {"centre drill", "centre_drill"},
    {"drill", "drill"},
    {"flat end mill", "flat_end_mill"},
    {"ball end mill", "ball_end_mill"},
    {"taper end mill", "taper_end_mill"},
    {"face mill", "face_mill"},
    {"turning insert", "turning_insert"},
    {"grooving tool", "grooving"},
    {"threading tool", "threading"},
    {"probe", "probe"},
    {"tap", "tap"},
    {"reamer", "reamer"},
    {"boring bar", "boring_bar"},
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
