// Spindle speed and feed from a tool's cutting data.
#include "tools/cutting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

std::optional<SpeedsFeeds> speedsFeeds(const Tool& tool, const std::string& material, double maxRpm, double maxFeed)
{
    const CuttingData* c = tool.cuttingFor(material);
    if (!c || tool.diameter <= 0) return std::nullopt;
    SpeedsFeeds sf;
    sf.rpm = std::min(std::round(1000.0 * c->surfaceSpeed / (std::numbers::pi * tool.diameter)), maxRpm);
    const bool drill = tool.type == ToolType::Drill || tool.type == ToolType::CentreDrill;
    sf.feed = std::min(std::round(sf.rpm * c->feedPerTooth * (drill ? 1 : tool.flutes)), maxFeed);
    sf.plungeFeed = std::round(sf.feed * c->plungeFactor);
    return sf;
}

}  // namespace taiwa
