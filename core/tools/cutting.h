// Spindle speed and feed of a tool in a material, from its cutting data.
#pragma once

#include "model/technology.h"
#include "model/tool.h"

#include <optional>
#include <string>

namespace taiwa {

// n = 1000 vc / (pi D), rounded to whole rpm; feed = n * fz * flutes (drills,
// reamers, boring bars: n * f; taps: n * pitch exactly, n lowered to keep
// the feed within its limit). Clamped to the machine limits. nullopt when the tool has no cutting
// data for the material.
std::optional<SpeedsFeeds> speedsFeeds(const Tool& tool, const std::string& material, double maxRpm = 12000.0,
                                       double maxFeed = 10000.0);

// A milling step's speeds and feeds: the tool's, with the operator's S and
// F in their place where the step has them (Step::cutting); the plunge feed
// follows F in proportion. nullopt as speedsFeeds, unless both are set.
struct Step;
// The automatic S and F are clamped to the machine's limits `maxRpm` and
// `maxFeed` (the operator's typed ones are checked against them by the job
// check instead).
std::optional<SpeedsFeeds> stepSpeedsFeeds(const Step& step, const Tool& tool, const std::string& material,
                                           double maxRpm = 12000.0, double maxFeed = 10000.0);

}  // namespace taiwa
