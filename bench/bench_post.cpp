// Post-processing speed on a synthetic program: 1,000 steps of 1,000 moves
// each (1M moves: zig-zag feeds, a full circle and a quarter arc per lap,
// plunges, rapids; ten tools, so 1,000 tool changes), posted for both
// dialects in mm and in inch. Reports blocks and MB of G-code written per
// second (the tape and its tape image list); the path generator is not
// involved. The anchor: a plain to_chars loop writing lines like the tape's.
#include "bench_anchor.h"
#include "post/post.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <numbers>

using namespace taiwa;

namespace {

constexpr int kSteps = 1000;
constexpr int kMovesPerStep = 1000;

std::vector<Tool> tools()
{
    std::vector<Tool> t;
    for (int id = 1; id <= 10; ++id) {
        Tool x;
        x.id = id;
        x.name = "end mill " + std::to_string(id);
        x.diameter = 2.0 + id;
        x.cutting.push_back({"aluminium-6061", 300, 0.05, 0.5});
        t.push_back(x);
    }
    return t;
}

const std::vector<Step>& steps()
{
    static const std::vector<Step> all = [] {
        std::vector<Step> s;
        for (int i = 0; i < kSteps; ++i) {
            Step st;
            st.unit = i / 4;
            st.module = "M4";
            st.tool = ToolChoice{1 + i % 10, ""};
            const double ox = (i % 40) * 50.123, oy = (i / 40) * 50.321;
            ToolPath p{{ox, oy, 5}, {}};
            p.moves.push_back({MoveKind::Rapid, {ox, oy, 1}});
            double z = 0;
            while (p.moves.size() + 8 <= kMovesPerStep) {
                z -= 0.25;
                Move plunge{MoveKind::Feed, {ox, oy, z}};
                plunge.feed = FeedKind::Plunge;
                p.moves.push_back(plunge);
                for (int k = 0; k < 40 && p.moves.size() + 4 <= kMovesPerStep; ++k)
                    p.moves.push_back({MoveKind::Feed, {ox + (k % 2) * 40.0 + 0.0007 * k, oy + k * 0.9137, z}});
                p.moves.push_back({MoveKind::Feed, {ox + 10, oy, z}});
                p.moves.push_back({MoveKind::ArcCCW, {ox + 10, oy, z}, {ox, oy}});       // full circle
                p.moves.push_back({MoveKind::ArcCW, {ox, oy - 10, z}, {ox, oy}});        // quarter
                p.moves.push_back({MoveKind::Feed, {ox, oy, z}});
            }
            p.moves.push_back({MoveKind::Rapid, {ox, oy, 5}});
            st.path = std::move(p);
            s.push_back(std::move(st));
        }
        return s;
    }();
    return all;
}

void BM_Post(benchmark::State& state, const char* dialect, LengthUnit units)
{
    const auto library = tools();
    PostOptions o;
    o.dialect = dialect;
    o.units = units;
    o.programName = "bench";
    o.material = "aluminium-6061";
    std::size_t moves = 0;
    for (const auto& s : steps()) moves += s.path->moves.size();
    std::size_t bytes = 0, blocks = 0;
    for (auto _ : state) {
        const PostedProgram p = postProcess(steps(), library, o);
        bytes = p.nc.size();
        blocks = p.lines.size();  // one source per line of the tape
        benchmark::DoNotOptimize(p.nc.data());
    }
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["lines"] = static_cast<double>(blocks);
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
    state.counters["lines/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["MB/s"] = benchmark::Counter(static_cast<double>(bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

// The anchor (bench_anchor.h): the bound for a writer that formats each
// number once. The post-processor's lines/s over this loop's is the ratio
// the README reports.
void BM_ToCharsAnchor(benchmark::State& state)
{
    constexpr int kLines = 1'000'000;
    std::size_t bytes = 0;
    for (auto _ : state) {
        bytes = bench::toCharsLines(kLines);
        benchmark::DoNotOptimize(bytes);
    }
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
    state.counters["lines/s"] = benchmark::Counter(static_cast<double>(kLines), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(BM_ToCharsAnchor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Post, linuxcnc_mm, "linuxcnc", LengthUnit::Millimetre)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Post, linuxcnc_inch, "linuxcnc", LengthUnit::Inch)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Post, fanuc_mm, "fanuc", LengthUnit::Millimetre)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
