// End-to-end export of a 1,000-unit job: planning (checks, decomposition,
// tool choice, tool paths), posting G-code, and the whole export with sheet
// and PDF. Prints G-code bytes and blocks per second and the export time.
#include "pipeline/export.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"

#include <QGuiApplication>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <algorithm>

using namespace taiwa;

namespace {

// 1,000 pockets on a 40 x 25 grid: M4 rectangles with every code mix, and an
// M2D every fifth unit.
Job bigJob()
{
    Job job;
    job.name = "bench-1000";
    job.stock = {0, 0, 40 * 30.0 + 10, 25 * 30.0 + 10, 40};
    const int codes[][3] = {{1, 1, 0}, {1, 2, 9}, {1, 3, 0}, {6, 1, 0}, {7, 1, 9}, {8, 2, 9}, {9, 1, 0}};
    for (int i = 0; i < 1000; ++i) {
        const double x = 10 + (i % 40) * 30.0, y = 10 + (i / 40) * 30.0;
        if (i % 5 == 4) {
            M2DPocket m;
            m.corner = {x, y};
            m.lengthX = 24;
            m.lengthY = 20;
            m.depth = 6;
            m.theta1 = 10;
            m.cornerRadius = 4;
            job.units.push_back({"", m});
            continue;
        }
        const auto* c = codes[i % 7];
        M4Pocket m;
        m.corners = {{{x, y}, {x + 24, y}, {x + 24, y + 20}, {x, y + 20}}};
        m.cornerRadius = 5;
        m.depth = 8;
        m.toolUse = c[0];
        m.wallFinish = c[1];
        m.pilotHole = c[2];
        job.units.push_back({"", m});
    }
    return job;
}

const std::vector<Tool>& library()
{
    static const std::vector<Tool> tools = defaultToolLibrary();
    return tools;
}

void BM_PlanJob(benchmark::State& state)
{
    const Job job = bigJob();
    std::size_t moves = 0;
    for (auto _ : state) {
        const Plan plan = planJob(job, TechnologyTable::builtIn(), library());
        if (!plan.ok()) state.SkipWithError("the bench job does not pass input processing");
        moves = 0;
        for (const auto& s : plan.steps) moves += s.path ? s.path->moves.size() : 0;
        benchmark::DoNotOptimize(plan.steps.data());
    }
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["units/s"] = benchmark::Counter(1000.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlanJob)->Unit(benchmark::kMillisecond);

// Input processing, decomposition, tool choice and ordering only: what the
// window recomputes on every keystroke before the paths.
void BM_PlanStepsOnly(benchmark::State& state)
{
    const Job job = bigJob();
    PlanOptions options;
    options.withToolPaths = false;
    for (auto _ : state) benchmark::DoNotOptimize(planJob(job, TechnologyTable::builtIn(), library(), options).steps.data());
    state.counters["units/s"] = benchmark::Counter(1000.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlanStepsOnly)->Unit(benchmark::kMillisecond);

void BM_PostGCode(benchmark::State& state)
{
    const Plan plan = planJob(bigJob(), TechnologyTable::builtIn(), library());
    PostOptions options;
    options.material = plan.mmJob.material;
    std::size_t bytes = 0, blocks = 0;
    for (auto _ : state) {
        const PostedProgram p = postProcess(plan.steps, plan.tools, options);
        bytes = p.nc.size();
        blocks = static_cast<std::size_t>(std::count(p.nc.begin(), p.nc.end(), '\n'));
        benchmark::DoNotOptimize(p.nc.data());
    }
    state.counters["bytes"] = static_cast<double>(bytes);
    state.counters["blocks"] = static_cast<double>(blocks);
    state.counters["MB/s"] = benchmark::Counter(static_cast<double>(bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["blocks/s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PostGCode)->Unit(benchmark::kMillisecond);

// The whole export as `taiwa export` does it (plan + five files incl. PDF).
void BM_ExportEndToEnd(benchmark::State& state)
{
    const Job job = bigJob();
    QTemporaryDir dir;
    for (auto _ : state) {
        const Plan plan = planJob(job, TechnologyTable::builtIn(), library());
        const ExportResult r = exportPlan(plan, dir.path().toStdString(), "bench", {});
        if (r.error) state.SkipWithError(r.error->c_str());
    }
}
BENCHMARK(BM_ExportEndToEnd)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
