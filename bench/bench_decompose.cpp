// Input processing and decomposition of a 1,000-unit job (M4 with every code
// mix and taper, M2D every fifth unit, on a grid of touching and separate
// figures): checkJob, machiningOrder and the decomposition of all units,
// each reported as time per unit.
#include "job/job_check.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "bench_job.h"

#include <benchmark/benchmark.h>

using namespace taiwa;

namespace {

using bench::bigJob;
using bench::kUnits;

std::vector<Tool> library()
{
    std::vector<Tool> tools;
    int id = 0;
    for (const double d : {2.0, 4.0, 6.0, 8.0}) {
        Tool t;
        t.id = ++id;
        t.type = ToolType::FlatEndMill;
        t.diameter = d;
        tools.push_back(t);
    }
    Tool taper;
    taper.id = ++id;
    taper.type = ToolType::TaperEndMill;
    taper.diameter = 2;
    taper.taperAngle = 3;
    tools.push_back(taper);
    return tools;
}

void perUnit(benchmark::State& state)
{
    // Seconds per unit, printed with its SI prefix ("29.3us").
    state.counters["time_per_unit"] =
        benchmark::Counter(kUnits, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_CheckJob(benchmark::State& state)
{
    const Job job = bigJob();
    const auto tools = library();
    for (auto _ : state) {
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), tools);
        if (!ds.empty()) state.SkipWithError(format(job.name, ds.front()).c_str());
        benchmark::DoNotOptimize(ds.data());
    }
    perUnit(state);
}
BENCHMARK(BM_CheckJob)->Unit(benchmark::kMillisecond);

void BM_MachiningOrder(benchmark::State& state)
{
    const Job job = bigJob();
    for (auto _ : state) {
        const auto order = machiningOrder(job);
        benchmark::DoNotOptimize(order.data());
    }
    perUnit(state);
}
BENCHMARK(BM_MachiningOrder)->Unit(benchmark::kMillisecond);

void BM_DecomposeAll(benchmark::State& state)
{
    const Job job = bigJob();
    const TechnologyData tech = *jobTechnology(job, TechnologyTable::builtIn());
    std::size_t steps = 0;
    for (auto _ : state) {
        steps = 0;
        for (int u = 0; u < kUnits; ++u) {
            const auto& module = job.units[static_cast<std::size_t>(u)].module;
            const auto unitSteps = (module).is<M4Pocket>()
                                       ? decomposeM4((module).as<M4Pocket>(), tech, u)
                                       : decomposeM2D((module).as<M2DPocket>(), tech, 6.0, u);
            steps += unitSteps.size();
            benchmark::DoNotOptimize(unitSteps.data());
        }
    }
    state.counters["steps"] = static_cast<double>(steps);
    perUnit(state);
}
BENCHMARK(BM_DecomposeAll)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
