// The verification of a lathe job (verify.h): the bar's exact half-section
// cut by every move of every turning step with its tool's outline, and the
// same checks as for milling (docs/verification.md, "Turning jobs").
// Internal to core/verify: verifyPlan calls it for a job with a bar.
#pragma once

#include "verify/verify.h"

namespace taiwa::verify {

// Verifies a lathe job (plan.mmJob.bar set) at the options' resolution.
Report verifyTurning(const Plan& plan, const Options& options);

}  // namespace taiwa::verify
