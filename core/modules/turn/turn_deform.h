// TURN's deformed profile (turning/allowance.h) with the nose radius of the
// insert its finishing step takes: the one computation of the unit's check,
// its plan's turned part and the station's profile editor.
#pragma once

#include "model/job.h"
#include "model/tool.h"
#include "turning/allowance.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::turning {

struct TurnDeformation {
    Deformation deformation;
    // The insert whose nose radius a tangent joint's adjustment took (the
    // sheet names it); empty when no joint took one.
    std::string noseRadiusTool;
};

// `resolved` (`profile` resolved) with its allowance rows applied. Where a
// tangent joint takes the finishing insert's nose radius as its adjustment,
// the insert is the one the finishing step takes (`pins`, reach:
// modules/turn/turn_plan.h finishingInsert), not merely the smallest: the
// profile is deformed with the smallest first, the finishing insert chosen
// on it, and deformed again with that insert's radius when it differs.
// Without `bar` (refused, or not known yet) the smallest insert's radius.
// `skip`: the unit's steps turned off (a finishing step turned off takes
// no insert: the smallest one's radius then).
TurnDeformation deformTurned(const TurnedProfile& profile, const ResolvedProfile& resolved, const ToolPins& pins,
                             const std::vector<std::string>& skip, const std::vector<Tool>& library, const BarStock* bar,
                             LengthUnit shown);

}  // namespace taiwa::turning
