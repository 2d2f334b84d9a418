// The check of a unit's own roughing step-over (unit_checks.h): the same
// range as the technology data's, said in the same words.
#include "check/messages.h"
#include "check/unit_checks.h"
#include "model/translate_noop.h"

#include <cmath>

namespace taiwa::check {

bool checkStepOver(const std::optional<double>& stepOver, Reporter& r)
{
    if (!stepOver) return true;
    const double v = *stepOver;
    if (!std::isfinite(v))
        r.unit("stepOver", msg::notFinite(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over")));
    else if (v <= 0.0)
        r.unit("stepOver", msg::technologyNotPositive(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over"), v, ""));
    else if (v < kStepOverLow || v > kStepOverHigh)
        r.unit("stepOver", msg::technologyOutOfRange(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over"), v,
                                                     kStepOverLow, kStepOverHigh, "", kStepOverWhy));
    else return true;
    return false;
}

}  // namespace taiwa::check
