// The verifying simulation (core/verify): cells swept per second on one core
// against a plain Z-map stamping loop on the same grid in the same run (the
// ratio printed as `ratio_to_stamping`), then the largest sample
// (plate.taiwa) at 0.1 and 0.05 mm on every core, and the memory a grid
// takes, which follows the stock's area and not its height.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "sim/cutter_profile.h"
#include "sim/height_field.h"
#include "tools/tool_library.h"
#include "verify/verify.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

using namespace taiwa;

namespace {

const Plan& plate()
{
    static const Plan plan = [] {
        const auto read = readJobFile(std::string(TAIWA_BENCH_DIR) + "/../resources/samples/plate.taiwa");
        return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
    }();
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

}  // namespace

BENCHMARK_MAIN();
