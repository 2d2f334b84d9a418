// A planned job: the pipeline's result (pipeline/pipeline.h makes it), read by
// the post-processors, the instruction sheet, the stock simulation and the
// station. Everything here is a value; nothing refers back into the stages.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/setup.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/turned.h"
#include "model/two_path.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct Plan {
    Job job;                         // as typed
    Job mmJob;                       // in mm
    TechnologyData technology;       // in force, mm
    Diagnostics diagnostics;         // input errors stop the plan: steps stay empty; warnings (tool life) do not
    std::vector<int> unitOrder;      // machining order of the units
    std::vector<WorkSetup> setups;   // probing units: measured centres and probing cycles, in unit order
    std::vector<TurnedPart> turned;  // turning units: profile and deformed profile, in unit order
    std::vector<Step> steps;         // job-wide machining order, tool/path/minutes filled
    std::vector<Tool> tools;         // the library tools the steps use, by first use
    // A two-path lathe job with a roughing step and tool paths: that step
    // balanced between the paths (model/two_path.h), once for every reader.
    std::optional<PlannedBalance> balance;
    double totalMinutes = 0.0;       // cutting + rapid + tool changes
    std::optional<double> totalMachineMinutes;  // the same as the machine moves (Step::machineMinutes), when known
    int toolChanges = 0;
    bool ok() const { return !hasErrors(diagnostics); }
    const Tool* tool(int id) const;
    // The warnings' messages (tool life and other notes for the sheet), in order.
    std::vector<std::string> notes() const;
};

}  // namespace taiwa
