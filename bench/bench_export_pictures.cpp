// The sheet's pictures drawn by the core on the processor (core/picture):
// one step picture and the setup picture at the sheet's size (320 x 240)
// beside a plain loop that writes every pixel of such a picture three
// times with a depth test (the least a rasteriser with that overdraw can
// cost: the anchor in the same run), the PNG encoding, and the 1,000-unit
// job's 200 pictures with their stock simulation. Goal (issue 35): <= 5 ms
// a picture. The whole export with pictures is in bench_export.
#include "bench_job.h"
#include "export/sheet_pictures.h"
#include "job/job_file.h"
#include "picture/pictures.h"
#include "pipeline/pipeline.h"
#include "sim/stock_simulation.h"
#include "tools/tool_library.h"
#include "bench_paths.h"

#include <QGuiApplication>

#include <benchmark/benchmark.h>

#include <limits>

using namespace taiwa;

namespace {

using picture::kSheetHeight;
using picture::kSheetWidth;

const Plan& plate()
{
    static const Plan plan = [] {
        auto read = readJobFile(taiwa::bench::sample("plate"));
        return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
    }();
    return plan;
}

// The anchor: 320 x 240 RGBA and depth written three times over, depth-tested.
void BM_PictureAnchor(benchmark::State& state)
{
    std::vector<std::uint8_t> rgba(4 * kSheetWidth * kSheetHeight);
    std::vector<float> depth(kSheetWidth * kSheetHeight);
    for (auto _ : state) {
        std::fill(depth.begin(), depth.end(), -std::numeric_limits<float>::infinity());
        for (int layer = 0; layer < 3; ++layer)
            for (std::size_t k = 0; k < depth.size(); ++k) {
                const auto d = static_cast<float>(layer + (k & 7));
                if (d < depth[k]) continue;
                depth[k] = d;
                rgba[4 * k] = static_cast<std::uint8_t>(layer), rgba[4 * k + 1] = static_cast<std::uint8_t>(k), rgba[4 * k + 2] = 7;
            }
        benchmark::DoNotOptimize(rgba.data());
    }
}
BENCHMARK(BM_PictureAnchor)->Unit(benchmark::kMillisecond);

// One step's picture from its height fields (the simulation not counted):
// plate.taiwa's first pocket roughing, on the grid stepPictures uses.
void BM_StepPicture(benchmark::State& state)
{
    const Plan& plan = plate();
    sim::StockSimulation simulation(plan, sim::StockGrid{0.25, static_cast<std::size_t>(kSheetWidth) * kSheetHeight / 2});
    const int k = static_cast<int>(plan.steps.size()) / 2;
    const auto before = simulation.before(k), after = simulation.after(k);
    const Step& step = plan.steps[static_cast<std::size_t>(k)];
    for (auto _ : state) {
        const picture::Picture p = picture::heightFieldPicture(*after, before.get(), step.path ? &*step.path : nullptr, kSheetWidth, kSheetHeight);
        benchmark::DoNotOptimize(p.image.rgba.data());
    }
    state.counters["cells"] = static_cast<double>(after->columns()) * after->rows();
}
BENCHMARK(BM_StepPicture)->Unit(benchmark::kMillisecond);

void BM_SetupPicture(benchmark::State& state)
{
    for (auto _ : state) benchmark::DoNotOptimize(picture::setupPicture(plate(), kSheetWidth, kSheetHeight).image.rgba.data());
}
BENCHMARK(BM_SetupPicture)->Unit(benchmark::kMillisecond);

void BM_PicturePng(benchmark::State& state)
{
    const picture::Picture p = picture::setupPicture(plate(), kSheetWidth, kSheetHeight);
    std::size_t bytes = 0;
    for (auto _ : state) bytes = pngOf(p).size();
    state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_PicturePng)->Unit(benchmark::kMillisecond);

// Every picture of a sheet as an export makes them: simulation, drawing, PNG.
void BM_SheetPictures(benchmark::State& state, bool big)
{
    const Plan plan = big ? planJob(bench::bigJob(), TechnologyTable::builtIn(), defaultToolLibrary()) : plate();
    std::size_t pictures = 0;
    for (auto _ : state) {
        ExportOptions o;
        if (const std::string problem = addSheetPictures(plan, o); !problem.empty()) state.SkipWithError(problem.c_str());
        pictures = o.stepPictures.size() + 1;
    }
    state.counters["pictures"] = static_cast<double>(pictures);
    state.counters["pictures/s"] = benchmark::Counter(static_cast<double>(pictures), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_CAPTURE(BM_SheetPictures, plate, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_SheetPictures, units_1000, true)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

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
