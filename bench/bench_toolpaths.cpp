// CL creation of a 100 x 80 mm pocket (r = 4, 12 mm deep, gamma 0.5) with a
// 6 mm end mill: roughing with and without a pilot hole, floor finishing,
// wall finishing in several incisions, and the coverage proof alone; each
// reports its segment count, path length and estimated machining minutes.
#include "modules/registry.h"
#include "paths/coverage.h"

#include <benchmark/benchmark.h>

using namespace taiwa;

namespace {

const Quad kOutline{{{{0, 0}, {100, 0}, {100, 80}, {0, 80}}}, 4.0};

Tool endMill()
{
    Tool t;
    t.id = 1;
    t.type = ToolType::FlatEndMill;
    t.diameter = 6;
    return t;
}

Step step(StepKind kind, double start, double cut)
{
    Step s;
    s.module = "M4";
    s.kind = kind;
    editMilling(s).outline = kOutline;
    editMilling(s).position = centroid(kOutline.corners);
    editMilling(s).startDepth = start;
    editMilling(s).cutDepth = cut;
    return s;
}

void report(benchmark::State& state, const ToolPath& p)
{
    const SpeedsFeeds sf{10600, 1270, 635};  // 6 mm carbide in aluminium, 2 flutes
    state.counters["segments"] = static_cast<double>(p.moves.size());
    state.counters["feed_mm"] = pathLength(p).feed;
    state.counters["minutes"] = estimateMinutes(p, sf);
}

void run(benchmark::State& state, const Step& s)
{
    ToolPath p;
    for (auto _ : state) {
        p = makeToolPath(s, endMill(), TechnologyData{}, PathParameters{});
        benchmark::DoNotOptimize(p);
    }
    report(state, p);
}

void roughingHelix(benchmark::State& state) { run(state, step(StepKind::Roughing, 0, 11.8)); }

void roughingPilotHole(benchmark::State& state)
{
    Step s = step(StepKind::Roughing, 0, 11.8);
    editMilling(s).holeDiameter = 6;
    run(state, s);
}

void floorFinishing(benchmark::State& state) { run(state, step(StepKind::FloorFinishing, 11.8, 12)); }

void wallFinishingF2(benchmark::State& state)
{
    Step s = step(StepKind::WallFinishing, 0, 12);
    editMilling(s).multiIncision = true;
    run(state, s);
}

// The Clipper proof of one roughing layer on its own.
void coverageProof(benchmark::State& state)
{
    const ToolPath p = makeToolPath(step(StepKind::Roughing, 0, 3), endMill(), TechnologyData{}, PathParameters{});
    for (auto _ : state) benchmark::DoNotOptimize(paths::uncutArea(kOutline, p, 3.0));
}

}  // namespace

BENCHMARK(roughingHelix)->Unit(benchmark::kMillisecond);
BENCHMARK(roughingPilotHole)->Unit(benchmark::kMillisecond);
BENCHMARK(floorFinishing)->Unit(benchmark::kMillisecond);
BENCHMARK(wallFinishingF2)->Unit(benchmark::kMillisecond);
BENCHMARK(coverageProof)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
