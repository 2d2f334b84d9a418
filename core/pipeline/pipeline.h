// The whole pipeline of spec/milling-modules.md, headless: input processing,
// decomposition, tool choice and ordering, CL creation and time estimates.
// The command line and the station window both call planJob().
#pragma once

#include "check/diagnostic.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "paths/cl.h"

#include <string>
#include <vector>

namespace taiwa {

struct PlanOptions {
    bool withToolPaths = true;  // false: decomposition and tool choice only (fast preview of the step list)
    PathParameters path;
    double toolChangeSeconds = 8.0;  // added per tool change to the total time
};

struct Plan {
    Job job;                         // as typed
    Job mmJob;                       // in mm
    TechnologyData technology;       // in force, mm
    Diagnostics diagnostics;         // input errors stop the plan: steps stay empty
    std::vector<int> unitOrder;      // machining order of the units
    std::vector<Step> steps;         // job-wide machining order, tool/path/minutes filled
    std::vector<Tool> tools;         // the library tools the steps use, by first use
    std::vector<std::string> notes;  // tool life and other notes for the sheet
    double totalMinutes = 0.0;       // cutting + rapid + tool changes
    int toolChanges = 0;
    bool ok() const { return !hasErrors(diagnostics); }
    const Tool* tool(int id) const;
};

Plan planJob(const Job& job, const TechnologyTable& table, const std::vector<Tool>& library,
             const PlanOptions& options = {});

}  // namespace taiwa
