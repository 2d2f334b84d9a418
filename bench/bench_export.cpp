// End-to-end export of a 1,000-unit job: planning (checks, decomposition,
// tool choice, tool paths), posting G-code, and the whole export with sheet
// and PDF. Prints G-code bytes and blocks per second and the export time,
// and the export with the sheet's pictures (drawn by the core, no display:
// goal <= 3 s) beside the same export without them in the same run.
#include "bench_job.h"
#include "export/export.h"
#include "export/sheet_pdf.h"
#include "export/sheet_pictures.h"
#include "paths/cl.h"
#include "sheet/sheet.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"

#include <QGuiApplication>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <algorithm>

using namespace taiwa;

namespace {

using bench::bigJob;

const std::vector<Tool>& library()
{
    static const std::vector<Tool> tools = defaultToolLibrary();
    return tools;
}

// Planning with tool paths, each time from scratch (nothing proved kept).
// "repeated": the shared job, whose pockets repeat a few shapes (a pocket
// shape is proved once); "distinct": no two pockets alike.
void BM_PlanJob(benchmark::State& state, bool distinct)
{
    const Job job = bigJob(bench::kUnits, distinct);
    std::size_t moves = 0;
    for (auto _ : state) {
        state.PauseTiming();
        forgetProvedLayers();
        state.ResumeTiming();
        const Plan plan = planJob(job, TechnologyTable::builtIn(), library());
        if (!plan.ok()) state.SkipWithError("the bench job does not pass input processing");
        moves = 0;
        for (const auto& s : plan.steps) moves += s.path ? s.path->moves.size() : 0;
        benchmark::DoNotOptimize(plan.steps.data());
    }
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["units/s"] = benchmark::Counter(1000.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_CAPTURE(BM_PlanJob, repeated, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PlanJob, distinct, true)->Unit(benchmark::kMillisecond);

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

// The parts of an export besides planning and posting, each on its own.
void BM_Sheet(benchmark::State& state, int part)
{
    const Plan plan = planJob(bigJob(), TechnologyTable::builtIn(), library());
    SheetOptions o;
    o.programNumber = 1000;
    std::size_t bytes = 0;
    for (auto _ : state) {
        std::string out;
        if (part == 0) out = sheetHtml(plan, o);
        else if (part == 1) out = *sheetPdf(plan, o);  // two writers at once (a large sheet)
        else if (part == 3) out = *sheetPdf(plan, o, PdfParts::One);  // one writer, the anchor of the above
        else out = stepsJson(plan);
        bytes = out.size();
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK_CAPTURE(BM_Sheet, html, 0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sheet, pdf, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Sheet, pdf_one_writer, 3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Sheet, steps_json, 2)->Unit(benchmark::kMillisecond);

// The whole export as `taiwa export` does it (plan + five files incl. PDF),
// from scratch each time (nothing proved kept).
// With `pictures`: the setup's and the first 200 steps' (export/sheet_pictures.h), as
// `taiwa export` draws them; the same export without them is its anchor.
void BM_ExportEndToEnd(benchmark::State& state, bool distinct, bool pictures)
{
    const Job job = bigJob(bench::kUnits, distinct);
    QTemporaryDir dir;
    std::size_t drawn = 0;
    for (auto _ : state) {
        state.PauseTiming();
        forgetProvedLayers();
        state.ResumeTiming();
        const Plan plan = planJob(job, TechnologyTable::builtIn(), library());
        ExportOptions o;
        if (pictures) {
            if (const std::string problem = addSheetPictures(plan, o); !problem.empty()) state.SkipWithError(problem.c_str());
            drawn = o.stepPictures.size() + (o.setupPicture.empty() ? 0 : 1);
        }
        const auto written = exportPlan(plan, dir.path().toStdString(), "bench", o);
        if (!written) state.SkipWithError(written.error().c_str());
    }
    state.counters["pictures"] = static_cast<double>(drawn);
}
BENCHMARK_CAPTURE(BM_ExportEndToEnd, repeated, false, false)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK_CAPTURE(BM_ExportEndToEnd, repeated_pictures, false, true)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK_CAPTURE(BM_ExportEndToEnd, distinct, true, false)->Unit(benchmark::kMillisecond)->Iterations(3);

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
