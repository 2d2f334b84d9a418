// The depth checks the pocket modules share (see unit_checks.h).
#include "check/messages.h"
#include "check/unit_checks.h"

#include <cmath>

namespace taiwa::check {

bool checkDepth(double depth, Reporter& r)
{
    constexpr double kTolerance = 1e-9;  // mm
    if (depth <= 0.0) {
        r.unit("depth", msg::depthNotPositive(r.len(depth)));
        return false;
    }
    if (r.ctx.stock && depth > r.ctx.stock->height + kTolerance)
        r.unit("depth", msg::deeperThanStock(r.len(depth), r.len(r.ctx.stock->height)));
    return true;
}

bool checkLength(double mm, const std::string& field, const std::string& what, Reporter& r)
{
    if (!std::isfinite(mm)) {
        r.unit(field, msg::notFinite(what));
        return false;
    }
    if (std::abs(mm) > kMaxLength) {
        r.unit(field, msg::beyondReach(what, r.len(mm), r.len(kMaxLength)));
        return false;
    }
    return true;
}

bool checkDepthAllowances(double depth, const TechnologyData& tech, bool drillsPilot, bool roughsToFloor, Reporter& r)
{
    bool ok = true;
    if (drillsPilot && tech.alpha1 >= depth) {
        r.job("technology.alpha1", msg::alpha1NotBelowDepth(r.unitNo, r.len(tech.alpha1), r.len(depth)));
        ok = false;
    }
    if (roughsToFloor && tech.beta2 >= depth) {
        r.job("technology.beta2", msg::beta2NotBelowDepth(r.unitNo, r.len(tech.beta2), r.len(depth)));
        ok = false;
    }
    return ok;
}

}  // namespace taiwa::check
