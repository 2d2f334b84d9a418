// The whole pipeline of spec/milling-modules.md, headless: input processing,
// each unit planned through its module's door, step ordering, CL creation
// and time estimates. The command line and the station window both call
// planJob(), and build their post-processor options with postOptions().
#pragma once

#include "job/job_check.h"
#include "model/job.h"
#include "model/plan.h"
#include "model/technology.h"
#include "model/tool.h"
#include "paths/cl.h"
#include "post/post.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct PlanOptions {
    bool withToolPaths = true;  // false: decomposition and tool choice only (fast preview of the step list)
    PathParameters path;
    double toolChangeSeconds = 8.0;  // added per tool change to the total time
};

// Tool paths are computed on every core, at most this many threads.
constexpr std::size_t kMaxPathThreads = 8;
// The most moves a plan's paths may hold (about 1 GB of moves, a 250 MB tape):
// a job beyond it is refused before any path is computed.
constexpr double kMaxPlanMoves = 10'000'000;

// Plans a job already converted and checked (job/job_check.h): input errors
// in it stop the plan with its steps empty. A checked job passed as a
// temporary is moved into the plan, not copied.
Plan planJob(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options = {});
// Converts, checks and plans the job (a job passed as a temporary is moved
// into the plan, not copied).
Plan planJob(Job job, const TechnologyTable& table, const std::vector<Tool>& library,
             const PlanOptions& options = {});

// The post-processor's options for a plan: the one place where the command
// line's export and the station's NC view build them, so that both print the
// same tape. `units` defaults to the job's; an unnamed job's program is named
// after `fileStem` (the job file's or the export's stem).
PostOptions postOptions(const Plan& plan, const std::string& dialect, std::optional<LengthUnit> units = std::nullopt,
                        int programNumber = 1000, const std::string& fileStem = {});

}  // namespace taiwa
