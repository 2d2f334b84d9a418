// Input processing of a whole job (pipeline stage 1): the job-level checks,
// every unit's checks through its module's door, the interference check
// between the figures of one job, and the order in which units are
// machined. Pure functions; they never throw.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/turned.h"

#include <optional>
#include <vector>

namespace taiwa {

// A job converted to mm once and checked once: what planning starts from.
struct CheckedJob {
    Job job;                                   // as typed
    Job mmJob;                                 // every length in mm
    Diagnostics diagnostics;                   // capped at 100 (the last line says how many more)
    std::optional<TechnologyData> technology;  // in force, mm; absent when the material or an override is refused
    // Each turning unit's deformed profile, made by its check (one per unit
    // of mmJob, nullopt for the others; empty when no unit is turned): the
    // plan cuts it, not a second one.
    std::vector<std::optional<TurnedPart>> turned;
    bool ok() const { return !hasErrors(diagnostics); }
};
// `job` is taken by value: a job passed as a temporary is moved in, not copied.
CheckedJob checkedJob(Job job, const TechnologyTable& table, const std::vector<Tool>& library);

// All diagnostics of the job (every unit checked, not only the first error).
// `job` is as the operator typed it (any length unit); messages quote values
// in the job's unit. `library` is the shop's tool library: pinned tool ids
// must exist in it, and r1 - alpha2 / r1 - alpha3 must leave room for a tool
// of it (the message names a tool that would fit, or says none does).
// The same as checkedJob(...).diagnostics.
Diagnostics checkJob(const Job& job, const TechnologyTable& table, const std::vector<Tool>& library);

// The technology data in force for the job, in mm (material table value with
// the job's overrides); nullopt when the material is unknown.
std::optional<TechnologyData> jobTechnology(const Job& mmJob, const TechnologyTable& table);

// Machining order of the units (0-based indices into job.units, every unit
// with a top outline): see docs/input-checks.md ("Unit order").
std::vector<int> machiningOrder(const Job& mmJob);

}  // namespace taiwa
