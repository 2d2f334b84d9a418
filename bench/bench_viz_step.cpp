// Selecting a step in the 3-D preview of the largest sample job
// (resources/samples/plate.taiwa) with the simulated stock shown: the time
// to bring the scene to the step (stock simulated up to it, its surface
// rebuilt) and to draw the next frame (800 x 600, offscreen, Mesa under
// Xvfb), walking forward through every step as the play button does, and
// jumping back to the first step. Run under `xvfb-run -a` from the source
// tree's root, or set TAIWA_BENCH_JOB.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "viz/render.h"
#include "viz/scene.h"

#include <benchmark/benchmark.h>

#include <vtkRenderWindow.h>

#include <chrono>
#include <cstdlib>
#include <memory>

using namespace taiwa;

namespace {

std::shared_ptr<const Plan> samplePlan()
{
    const char* path = std::getenv("TAIWA_BENCH_JOB");
    const auto read = readJobFile(path ? path : "resources/samples/plate.taiwa");
    if (!read.job) return nullptr;
    return std::make_shared<const Plan>(planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary()));
}

using Clock = std::chrono::steady_clock;
double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// arg 0: walk forward through every step; arg 1: jump between the last
// and the first step (the snapshots are kept, so the stock comes from cache).
void BM_SelectStep(benchmark::State& state)
{
    const auto plan = samplePlan();
    if (!plan || plan->steps.empty()) {
        state.SkipWithError("cannot plan resources/samples/plate.taiwa (run from the source root)");
        return;
    }
    const int n = static_cast<int>(plan->steps.size());
    double sceneMs = 0, frameMs = 0;
    long selections = 0;
    for (auto _ : state) {
        state.PauseTiming();
        viz::Scene scene;  // a fresh scene: nothing simulated yet
        scene.setPlan(plan);
        scene.setShowStock(true);
        scene.setView(viz::ViewPreset::Iso, 800.0 / 600.0);
        const viz::OffscreenWindow offscreen(800, 600);
        vtkRenderWindow* window = offscreen.window();
        if (!window) {
            state.SkipWithError(offscreen.problem()->c_str());
            return;
        }
        window->AddRenderer(scene.renderer());
        window->Render();
        state.ResumeTiming();
        const auto select = [&](int k) {
            const auto t0 = Clock::now();
            scene.setSelectedStep(k);
            const auto t1 = Clock::now();
            window->Render();
            const auto t2 = Clock::now();
            sceneMs += ms(t1 - t0);
            frameMs += ms(t2 - t1);
            ++selections;
        };
        if (state.range(0) == 0)
            for (int k = 0; k < n; ++k) select(k);
        else
            for (int i = 0; i < 10; ++i) select(i % 2 == 0 ? n - 1 : 0);
    }
    state.counters["steps"] = n;
    state.counters["scene_ms"] = sceneMs / static_cast<double>(selections);
    state.counters["frame_ms"] = frameMs / static_cast<double>(selections);
}
BENCHMARK(BM_SelectStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
