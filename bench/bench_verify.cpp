// The verifying simulation (core/verify): cells swept per second on one core
// against a plain Z-map stamping loop on the same grid in the same run (the
// ratio printed as `ratio_to_stamping`), then the largest sample
// (plate.taiwa) at 0.1 and 0.05 mm on every core, and the memory a grid
// takes, which follows the stock's area and not its height. Then the
// issue's three anchors (cp-islands.taiwa, plate.taiwa and
// bench/fine-pocket.taiwa at 0.05 mm), each timed beside what a plain
// stamping loop, measured in the same run, takes to touch once every cell
// the moves sweep (`ratio_to_stamping`: 1 is a verification whose work
// follows the material swept, with all its checks on top).
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "sim/cutter_profile.h"
#include "sim/height_field.h"
#include "sim/path_samples.h"
#include "tools/tool_library.h"
#include "verify/verify.h"
#include "bench_paths.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

using namespace taiwa;

namespace {

Plan planOf(const std::string& path)
{
    const auto read = readJobFile(path);
    return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
}

const Plan& plate()
{
    static const Plan plan = planOf(taiwa::bench::sample("plate"));
    return plan;
}

// One pocket 80 x 60 roughed 5 deep in layers of 1 mm by a D10 flat end
// mill in a raster 4 mm apart: the shape of work the verification does most.
Plan rasterPlan()
{
    Plan plan;
    plan.mmJob.stock = {0, 0, 100, 80, 30};
    plan.job = plan.mmJob;
    Tool t;
    t.id = 1;
    t.type = ToolType::FlatEndMill;
    t.diameter = 10;
    t.fluteLength = 25;
    t.stickout = 45;
    plan.tools = {t};
    Step s;
    s.kind = StepKind::Roughing;
    s.tool = ToolChoice{1, "bench"};
    ToolPath p{{15, 15, 5}, {}};
    for (double z = -1; z >= -5; z -= 1) {
        p.moves.push_back({MoveKind::Rapid, {15, 15, 1}});
        p.moves.push_back({MoveKind::Feed, {15, 15, z}, {}, FeedKind::Plunge});
        bool right = true;
        for (double y = 15; y <= 65 + 1e-9; y += 4) {
            p.moves.push_back({MoveKind::Feed, {right ? 15.0 : 85.0, y, z}});
            p.moves.push_back({MoveKind::Feed, {right ? 85.0 : 15.0, y, z}});
            right = !right;
        }
    }
    s.path = p;
    plan.steps = {s};
    return plan;
}

// The anchor: the same raster stamped as discs every half cell along the
// path, each cell under the disc lowered to the tip plus the cutter's
// height at its distance (the plain Z-map loop: no checks, no order, one
// thread).
double stampingCellsPerSecond(double cell)
{
    const Plan plan = rasterPlan();
    sim::HeightField f(plan.mmJob.stock, cell);
    const sim::CutterProfile cutter(plan.tools[0]);
    const double r = cutter.reach(), r2 = r * r;
    std::uint64_t cells = 0;
    const auto start = std::chrono::steady_clock::now();
    Point3 at = plan.steps[0].path->start;
    float* z = f.data();
    for (const Move& m : plan.steps[0].path->moves) {
        const double len = std::hypot(m.end.x - at.x, m.end.y - at.y);
        const int n = std::max(1, static_cast<int>(std::ceil(len / (cell / 2))));
        for (int k = 1; k <= n; ++k) {
            const double t = static_cast<double>(k) / n;
            const double cx = at.x + t * (m.end.x - at.x), cy = at.y + t * (m.end.y - at.y), cz = at.z + t * (m.end.z - at.z);
            const int i0 = std::max(0, static_cast<int>((cx - r) / cell)), i1 = std::min(f.columns() - 1, static_cast<int>((cx + r) / cell));
            const int j0 = std::max(0, static_cast<int>((cy - r) / cell)), j1 = std::min(f.rows() - 1, static_cast<int>((cy + r) / cell));
            for (int j = j0; j <= j1; ++j) {
                const double dy = (j + 0.5) * cell - cy;
                for (int i = i0; i <= i1; ++i) {
                    const double dx = (i + 0.5) * cell - cx;
                    const double d2 = dx * dx + dy * dy;
                    if (d2 > r2) continue;
                    ++cells;
                    float& h = z[f.indexOf(i, j)];
                    h = std::min(h, static_cast<float>(cz + cutter.height(std::sqrt(d2))));
                }
            }
        }
        at = m.end;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(z);
    return static_cast<double>(cells) / s;
}

// Cells per second of the verification on one core, and its ratio to the
// stamping loop's measured just before it.
void BM_VerifySweepOneCore(benchmark::State& state)
{
    const double cell = static_cast<double>(state.range(0)) / 100.0;
    const Plan plan = rasterPlan();
    verify::Options o;
    o.resolution = cell;
    o.threads = 1;
    double visits = 0, seconds = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        const verify::Report r = verify::verifyPlan(plan, o);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        visits += r.cellVisits;
        benchmark::DoNotOptimize(r);
    }
    const double ours = visits / seconds, stamping = stampingCellsPerSecond(cell);
    state.counters["Mcells_per_s"] = ours / 1e6;
    state.counters["stamping_Mcells_per_s"] = stamping / 1e6;
    state.counters["ratio_to_stamping"] = ours / stamping;
}
BENCHMARK(BM_VerifySweepOneCore)->Arg(5)->Arg(10)->Unit(benchmark::kMillisecond)->UseRealTime();

// plate.taiwa (200 x 150 mm, 12 units) verified on every core.
void BM_VerifyPlate(benchmark::State& state)
{
    verify::Options o;
    o.resolution = static_cast<double>(state.range(0)) / 100.0;
    verify::Report r;
    for (auto _ : state) {
        r = verify::verifyPlan(plate(), o);
        benchmark::DoNotOptimize(r);
    }
    state.counters["cells_M"] = static_cast<double>(r.columns) * r.rows / 1e6;
    state.counters["findings"] = static_cast<double>(r.findings.size());
    state.counters["grid_MB"] = static_cast<double>(r.columns) * r.rows * 2 * sizeof(float) / 1e6;
}
BENCHMARK(BM_VerifyPlate)->Arg(10)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// The grid's memory at 0.05 mm for the plate's stock 30 and 300 mm high:
// the same (a height field holds one height per cell, whatever the height).
void BM_VerifyMemoryByHeight(benchmark::State& state)
{
    Plan plan = plate();
    plan.mmJob.stock.height = static_cast<double>(state.range(0));
    verify::Options o;
    o.resolution = 0.05;
    verify::Report r;
    for (auto _ : state) {
        r = verify::verifyPlan(plan, o);
        benchmark::DoNotOptimize(r);
    }
    state.counters["grid_MB"] = static_cast<double>(r.stock.heights().size()) * 2 * sizeof(float) / 1e6;
}
BENCHMARK(BM_VerifyMemoryByHeight)->Arg(30)->Arg(300)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// The material a plan's cutting moves sweep, in cells: each piece below the
// stock top covers a band two reaches wide along its length, and a disc
// where a run of pieces starts (the tool's footprint, counted once per
// pass). The anchor of the issue: this many cells at a plain stamping
// loop's rate (stampingCellsPerSecond) is what the work of cutting the
// material costs, whatever the path's number of moves.
double sweptCells(const Plan& plan, double cell)
{
    double area = 0.0;
    for (const Step& s : plan.steps) {
        const Tool* tool = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        if (!s.path || !tool || tool->type == ToolType::Probe) continue;
        const double r = sim::CutterProfile(*tool).reach();
        bool running = false;
        for (const sim::SweptPiece& p : sim::sweptPieces(*s.path)) {
            if (std::min(p.from.z, p.to.z) >= 0.0) {
                running = false;
                continue;
            }
            const double len = p.arc ? std::abs(p.sweep) * std::hypot(p.from.x - p.centre.x, p.from.y - p.centre.y)
                                     : std::hypot(p.to.x - p.from.x, p.to.y - p.from.y);
            area += 2.0 * r * len + (running ? 0.0 : 3.14159265358979 * r * r);
            running = true;
        }
    }
    return area / (cell * cell);
}

// A sample verified at 0.05 mm on every core beside the anchor: the cells
// its moves sweep at the stamping loop's rate on one core, both in this run.
void verifyAgainstStamping(benchmark::State& state, const Plan& plan)
{
    verify::Options o;
    o.resolution = 0.05;
    verify::Report r;
    double seconds = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        r = verify::verifyPlan(plan, o);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        benchmark::DoNotOptimize(r);
    }
    const double ours = seconds / static_cast<double>(state.iterations());
    const double swept = sweptCells(plan, o.resolution);
    const double stamping = swept / stampingCellsPerSecond(o.resolution);
    std::size_t moves = 0;
    for (const Step& s : plan.steps)
        if (s.path) moves += s.path->moves.size();
    state.counters["verify_s"] = ours;
    state.counters["stamping_s"] = stamping;
    state.counters["ratio_to_stamping"] = ours / stamping;
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["cells_M"] = static_cast<double>(r.columns) * r.rows / 1e6;
    state.counters["swept_M"] = swept / 1e6;
    state.counters["visits_M"] = r.cellVisits / 1e6;
    state.counters["findings"] = static_cast<double>(r.findings.size());
}

void BM_VerifyCpIslands(benchmark::State& state)
{
    static const Plan plan = planOf(taiwa::bench::sample("cp-islands"));
    verifyAgainstStamping(state, plan);
}
BENCHMARK(BM_VerifyCpIslands)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_VerifyPlateFine(benchmark::State& state) { verifyAgainstStamping(state, plate()); }
BENCHMARK(BM_VerifyPlateFine)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_VerifyFinePocket(benchmark::State& state)
{
    static const Plan plan = planOf(taiwa::bench::dir() + "/fine-pocket.taiwa");
    verifyAgainstStamping(state, plan);
}
BENCHMARK(BM_VerifyFinePocket)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// The bound of the work (issue "bounded work", item 3): m4-standard.taiwa
// with its step-over and layer depth (γ) overridden to 1/1000 of the
// argument, verified as `taiwa verify` does when no cell size is given
// (kDefaultCellVisits). Counters: the moves, the grid it ended on, the
// cells visited in the run that finished, and the bound.
void BM_VerifyBoundedStepOver(benchmark::State& state)
{
    auto read = readJobFile(taiwa::bench::sample("m4-standard"));
    read.job->technology.stepOver = read.job->technology.gamma = static_cast<double>(state.range(0)) / 1000.0;
    const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
    std::size_t moves = 0;
    for (const Step& s : plan.steps) moves += s.path ? s.path->moves.size() : 0;
    verify::Report r;
    for (auto _ : state) {
        verify::Options o;
        o.resolution = verify::defaultResolution(plan);
        o.maxCellVisits = verify::kDefaultCellVisits;
        r = verify::verifyPlan(plan, o);
    }
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["resolution_um"] = r.resolution * 1000.0;
    state.counters["visits_M"] = r.cellVisits / 1e6;
    state.counters["bound_M"] = verify::kDefaultCellVisits / 1e6;
    state.counters["findings"] = static_cast<double>(r.findings.size());
}
BENCHMARK(BM_VerifyBoundedStepOver)->Arg(450)->Arg(100)->Arg(30)->Arg(10)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
