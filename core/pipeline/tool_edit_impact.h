// What an edit of the tool library would change in a job, before it is
// applied (the tool library dialog asks with it): the steps whose tool
// changes — another tool chosen, or the same T number with other data —
// and what the job's check refuses with the edit that it took before.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/step.h"
#include "model/tool.h"

#include <optional>
#include <vector>

namespace taiwa {

struct StepToolChange {
    Step step;                  // as planned with the edit (before it when the edit leaves it out)
    std::optional<int> before;  // its tool's T number before the edit; none: the step had no tool or was not there
    std::optional<int> after;   // and with it
    bool toolEdited = false;    // the same T number, its data changed (its paths change)
};

struct ToolEditImpact {
    std::vector<StepToolChange> steps;  // in machining order
    Diagnostics refusals;               // errors with the edit that the job did not have before it
    bool empty() const { return steps.empty() && refusals.empty(); }
};

// Plans `job` (decomposition and tool choice, no paths) with both libraries
// and compares the steps by unit, kind and number.
ToolEditImpact toolEditImpact(const Job& job, const std::vector<Tool>& before, const std::vector<Tool>& after);

}  // namespace taiwa
