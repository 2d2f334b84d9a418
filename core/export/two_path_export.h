// The tapes of a job whose machine is a two-path lathe (docs/two-path-lathe.md
// "The export"): the job's first roughing step balanced between the paths
// (meeting before the first cut and after the last) and written as one whole
// program per path, STEM.p1.nc and STEM.p2.nc in the chosen dialect, the
// tape image listing both, and for LinuxCNC each path's tool table
// (STEM.p1.tbl, STEM.p2.tbl). Called by exportPlan in place of STEM.nc.
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "post/posted_job.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace taiwa {

// A file of an export: its suffix after the stem (".p1.nc") and its bytes.
using ExportFile = std::pair<std::string, std::string>;

// Nothing when the job's machine has one path (the ordinary tape). Else the
// two-path files, or why they cannot be written (a job with no roughing
// step, a balancing refusal: the dwell, the wait codes).
std::optional<Result<std::vector<ExportFile>>> twoPathTapes(const Plan& plan, const std::string& dialect,
                                                            std::optional<LengthUnit> units, int programNumber,
                                                            const std::string& stem);

// The same of the programs already posted (post/posted_job.h postTwoPath,
// with the dialect and stem given here): written as they are.
std::optional<Result<std::vector<ExportFile>>> twoPathTapes(const Plan& plan, const std::optional<Result<PostedTwoPath>>& posted,
                                                            const std::string& dialect, const std::string& stem);

}  // namespace taiwa
