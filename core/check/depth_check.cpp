// The depth check both modules share (see unit_checks.h).
#include "check/messages.h"
#include "check/unit_checks.h"

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

}  // namespace taiwa::check
