// Balanced roughing on a two-path lathe (docs/two-path-lathe.md): for each
// two-path sample (resources/samples/lathe-two-path-*.taiwa) the roughing balanced
// between the turrets and run on the two-path timeline. Prints, per sample,
// the roughing's time on one path and on two, their ratio (a cylinder
// comes close to half), the least lag of a follower behind its leader in
// spindle revolutions, the waits and the deadlocks; and the time the
// balancing and the timeline take.
#include "job/job_file.h"
#include "machine/machine.h"
#include "turning/balanced_roughing.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "verify/two_path_timeline.h"
#include "bench_paths.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <stdexcept>
#include <string>

using namespace taiwa;

namespace {

const TurnStep& roughing(const std::string& stem)
{
    static std::map<std::string, Plan> plans;
    auto it = plans.find(stem);
    if (it == plans.end()) {
        auto r = readJobFile(taiwa::bench::sample(stem));
        if (!r.job) throw std::runtime_error("cannot read " + stem);
        it = plans.emplace(stem, planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary())).first;
    }
    for (const auto& s : it->second.steps)
        if (s.kind == StepKind::TurnRoughing) return *turnOf(s);
    throw std::runtime_error("no roughing in " + stem);
}

void balance(benchmark::State& state, const std::string& stem, double revolutions)
{
    const TurnStep& s = roughing(stem);
    const Machine& m = *findMachine("lathe-two-path");
    turning::BalanceSettings set;
    set.dwellRevolutions = revolutions;
    Timeline t;
    BalancedCut c;
    for (auto _ : state) {
        c = *turning::balanceRoughing(s.path, s.cutting, m, set);
        t = runTimeline(c, m);
        benchmark::DoNotOptimize(t);
    }
    const double one = singlePathSeconds(s.path, s.cutting, m);
    int waits = 0;
    for (const auto& b : c.paths[0].blocks) waits += b.wait ? 1 : 0;
    state.counters["blocks"] = c.blockCount;
    state.counters["one_path_s"] = one;
    state.counters["two_paths_s"] = t.seconds();
    state.counters["ratio"] = t.seconds() / one;
    state.counters["least_lag_rev"] = t.leastLag();
    state.counters["waits"] = waits;
    state.counters["deadlocks"] = static_cast<double>(t.deadlocks.size());
}

}  // namespace

BENCHMARK_CAPTURE(balance, cylinder_1rev, std::string("lathe-two-path-cylinder"), 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(balance, cylinder_2rev, std::string("lathe-two-path-cylinder"), 2.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(balance, taper_1rev, std::string("lathe-two-path-taper"), 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(balance, taper_2rev, std::string("lathe-two-path-taper"), 2.0)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
