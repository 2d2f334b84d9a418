// Spindle speed and feed from a tool's cutting data.
#include "tools/cutting.h"

#include "model/step.h"

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
    const bool perRevolution = tool.type == ToolType::Drill || tool.type == ToolType::CentreDrill ||
                               tool.type == ToolType::Reamer || tool.type == ToolType::BoringBar;
    if (tool.type == ToolType::Tap && tool.turning.pitchMin > 0) {
        // A tap advances its pitch a revolution, exactly: F = pitch x S,
        // S lowered where F would pass the machine's limit.
        const double pitch = tool.turning.pitchMin;
        sf.rpm = std::min(sf.rpm, std::floor(maxFeed / pitch));
        sf.feed = sf.rpm * pitch;
        sf.plungeFeed = sf.feed;
        return sf;
    }
    sf.feed = std::min(std::round(sf.rpm * c->feedPerTooth * (perRevolution ? 1 : tool.flutes)), maxFeed);
    sf.plungeFeed = std::round(sf.feed * c->plungeFactor);
    return sf;
}

std::optional<SpeedsFeeds> stepSpeedsFeeds(const Step& step, const Tool& tool, const std::string& material, double maxRpm,
                                           double maxFeed)
{
    auto sf = speedsFeeds(tool, material, maxRpm, maxFeed);
    const CuttingOverride& o = step.cutting;
    if (!sf) {
        if (!o.speed || !o.feed) return std::nullopt;
        // The operator's numbers alone: plunging at half the feed.
        return SpeedsFeeds{*o.speed, *o.feed, std::round(*o.feed / 2)};
    }
    if (o.speed) sf->rpm = *o.speed;
    if (tool.type == ToolType::Tap && tool.turning.pitchMin > 0) {
        // Tapping: the feed follows S at the pitch; the operator's F has no say.
        sf->feed = sf->plungeFeed = sf->rpm * tool.turning.pitchMin;
        return sf;
    }
    if (o.feed) {
        if (sf->feed > 0) sf->plungeFeed = std::round(sf->plungeFeed * *o.feed / sf->feed);
        sf->feed = *o.feed;
    }
    return sf;
}

}  // namespace taiwa
