// TURN's deformed profile with the finishing insert's nose radius (turn_deform.h).
#include "modules/turn/turn_deform.h"

#include "check/messages.h"
#include "modules/turn/turn_plan.h"

#include <cmath>

namespace taiwa::turning {

namespace {

bool tookNoseRadius(const DeformedProfile& d)
{
    for (const auto& r : d.rows)
        for (const EndOutcome* e : {&r.start, &r.end})
            if (e->adjustmentFrom.starts_with("nose radius")) return true;
    return false;
}

}  // namespace

TurnDeformation deformTurned(const TurnedProfile& profile, const ResolvedProfile& resolved, const ToolPins& pins,
                             const std::vector<std::string>& skip, const std::vector<Tool>& library, const BarStock* bar,
                             LengthUnit shown)
{
    AllowanceOptions o = allowanceOptions(profile, library, shown);
    TurnDeformation out{applyAllowances(resolved, profile.allowances, o), {}};
    if (!tookNoseRadius(out.deformation.profile)) return out;
    out.noseRadiusTool = o.toolName;
    if (!bar || !out.deformation.ok() || !o.noseRadius) return out;
    TurnPlanRequest q;
    q.deformed = &out.deformation.profile;
    q.bar = *bar;
    q.library = &library;
    q.pins = pins;
    q.skip = {skip.begin(), skip.end()};
    q.shown = shown;
    const Tool* finishing = finishingInsert(q);
    if (!finishing || std::abs(finishing->cornerRadius - *o.noseRadius) < 1e-9) return out;
    o.noseRadius = finishing->cornerRadius;
    o.toolName = msg::toolName(*finishing);
    return {applyAllowances(resolved, profile.allowances, o), o.toolName};
}

}  // namespace taiwa::turning
