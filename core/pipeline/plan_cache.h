// Incremental planning for the station (issue 11): PlanCache::plan gives
// exactly what planJob gives (step by step, move by move) but reuses what an
// earlier plan of the same job computed:
//   - each unit's module result (its steps before ordering, its messages,
//     its work setup and turned part), keyed by everything the module reads:
//     the unit's index and values (in mm, contours resolved), the
//     technology data, the tool library, the material, the machine, the
//     length unit messages quote, the stock, the work offset, and on a lathe
//     every unit (a turning unit looks at the others);
//   - each step's tool path and times, keyed by the step itself (its
//     geometry, tool, cutting data; not its unit's index, which no path
//     reads), the technology data, the tool library, the path parameters,
//     the material and the machine.
// Only what the last plan used is kept: one plan's worth of steps and paths.
// Not thread-safe: one planner at a time (the station's worker thread).
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/plan.h"
#include "model/tool.h"
#include "pipeline/pipeline.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

namespace taiwa {

// One unit's planning through its module's door, as planJob does it.
struct UnitPlan {
    std::vector<Step> steps;  // unordered, no cutting data applied, no paths
    Diagnostics diagnostics;  // what the module said of the unit
    std::optional<WorkSetup> setup;
    std::optional<TurnedPart> turned;
};

// A step's path and times.
struct StepPath {
    ToolPath path;
    double minutes = 0.0;
    std::optional<double> machineMinutes;
};

class PlanCache;

// planJob reusing `cache`'s units and paths (nullptr: none), then keeping
// what it planned there: the same plan as without it.
Plan planJob(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options, PlanCache* cache);

class PlanCache {
public:
    // planJob(checked, library, options), reusing this cache's units and paths.
    Plan plan(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options = {});

    // What the last plan() did: units planned and reused, paths computed and reused.
    struct Counts {
        int unitsPlanned = 0, unitsReused = 0, pathsComputed = 0, pathsReused = 0;
    };
    const Counts& lastCounts() const { return counts_; }
    void clear();

    // Used by the pipeline while it plans (pipeline.cpp).
    // The unit's plan from the cache, or `compute`d and kept.
    const UnitPlan& unit(const Plan& plan, int u, const std::vector<Tool>& library,
                         const std::function<UnitPlan()>& compute);
    // The step's path and times if an earlier plan computed them (the step
    // with its tool and cutting data, its path not yet made).
    const StepPath* findPath(const Step& step);
    void keepPath(const Step& step, StepPath path);
    // Starts a plan: forgets what the new context makes invalid.
    void begin(const Plan& plan, const std::vector<Tool>& library, const PathParameters& params);
    // Ends a plan: forgets what it did not use.
    void end();

private:
    struct UnitKey {
        int unit = 0;
        MachiningUnit mm;
        std::string typedName;
        std::vector<MachiningUnit> others;  // lathe jobs only
        friend bool operator==(const UnitKey&, const UnitKey&) = default;
    };
    struct UnitEntry {
        UnitKey key;
        UnitPlan plan;
        std::uint64_t used = 0;
    };
    struct PathEntry {
        Step step;  // the key: unit 0, no path or times
        StepPath path;
        std::uint64_t used = 0;
    };
    // Everything every unit reads: a change forgets all units.
    struct UnitContext {
        TechnologyData technology;
        std::vector<Tool> library;
        std::string material, machine, workOffset;
        LengthUnit shownUnit = LengthUnit::Millimetre;
        Stock stock;
        std::optional<BarStock> bar;
        friend bool operator==(const UnitContext&, const UnitContext&) = default;
    };
    // Everything every path reads: a change forgets all paths.
    struct PathContext {
        TechnologyData technology;
        std::vector<Tool> library;
        PathParameters params;
        std::string material, machine;
        friend bool operator==(const PathContext&, const PathContext&) = default;
    };
    static std::size_t hashStep(const Step& key);
    static Step pathKey(const Step& step);

    std::optional<UnitContext> unitContext_;
    std::optional<PathContext> pathContext_;
    std::unordered_map<int, UnitEntry> units_;                // by the unit's index
    std::unordered_multimap<std::size_t, PathEntry> paths_;  // by hashStep
    std::uint64_t generation_ = 0;
    Counts counts_;
};

}  // namespace taiwa
