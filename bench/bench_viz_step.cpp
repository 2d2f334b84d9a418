// Selecting a step in the 3-D preview of the largest sample job
// (resources/samples/plate.taiwa) with the simulated stock shown: the time
// to bring the scene to the step (stock simulated up to it, its surface
// rebuilt) and to draw the next frame (800 x 600, offscreen, Mesa under
// Xvfb), walking forward through every step as the play button does, and
// jumping back to the first step. BM_FrameParts: what each element of the
// station's picture of the job (stock shown, iso, the view's 836 x 425)
// costs a frame: the frame with everything, then with each prop hidden in
// turn, interleaved; processor time of the process (Mesa's threads too).
// BM_StockLight: the same picture's frame with the stock lit by VTK per
// pixel (arg 0) and on the processor per quad (arg 1, the scene's default,
// viz/surface_light.h), each frame after a turn of the camera (so the
// processor's lighting is done anew every frame) and without one.
// Run under `xvfb-run -a` from the source tree's root, or set TAIWA_BENCH_JOB.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "viz/render.h"
#include "viz/scene.h"

#include <benchmark/benchmark.h>

#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

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

// A plan's scene with the stock shown, iso, in an offscreen window of
// width x height, drawn once (when there is a window).
struct StockView {
    viz::Scene scene;
    viz::OffscreenWindow offscreen;
    StockView(const std::shared_ptr<const Plan>& plan, int width, int height) : offscreen(width, height)
    {
        scene.setPlan(plan);
        scene.setShowStock(true);
        scene.setView(viz::ViewPreset::Iso, static_cast<double>(width) / height);
        if (vtkRenderWindow* window = offscreen.window()) {
            window->AddRenderer(scene.renderer());
            window->Render();
        }
    }
};

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
        StockView view(plan, 800, 600);  // a fresh scene: nothing simulated yet
        viz::Scene& scene = view.scene;
        vtkRenderWindow* window = view.offscreen.window();
        if (!window) {
            state.SkipWithError(view.offscreen.problem()->c_str());
            return;
        }
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

double cpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// One frame rendered and finished: processor time of the process (Mesa's
// threads too) and clock time, in ms.
struct FrameTime {
    double cpu = 0, wall = 0;
};
FrameTime timedFrame(vtkRenderWindow* window)
{
    const double c0 = cpuMs();
    const auto t0 = Clock::now();
    window->Render();
    window->WaitForCompletion();
    return {cpuMs() - c0, ms(Clock::now() - t0)};
}

void BM_FrameParts(benchmark::State& state)
{
    const auto plan = samplePlan();
    if (!plan || plan->steps.empty()) {
        state.SkipWithError("cannot plan resources/samples/plate.taiwa (run from the source root)");
        return;
    }
    StockView view(plan, 836, 425);  // the station's view size
    viz::Scene& scene = view.scene;
    vtkRenderWindow* window = view.offscreen.window();
    if (!window) {
        state.SkipWithError(view.offscreen.problem()->c_str());
        return;
    }
    std::vector<vtkProp*> props;
    vtkPropCollection* all = scene.renderer()->GetViewProps();
    all->InitTraversal();
    while (vtkProp* p = all->GetNextProp())
        if (p->GetVisibility()) props.push_back(p);
    // Configuration 0: everything; k: prop k - 1 hidden.
    std::vector<double> cpu(props.size() + 1, 0.0), wall(props.size() + 1, 0.0);
    long frames = 0;
    for (auto _ : state) {
        for (std::size_t c = 0; c <= props.size(); ++c) {
            if (c > 0) props[c - 1]->VisibilityOff();
            const FrameTime t = timedFrame(window);
            wall[c] += t.wall;
            cpu[c] += t.cpu;
            if (c > 0) props[c - 1]->VisibilityOn();
        }
        ++frames;
    }
    const double n = static_cast<double>(frames);
    std::printf("frame of the station's view (stock shown): %.1f ms processor, %.1f ms clock\n", cpu[0] / n, wall[0] / n);
    for (std::size_t k = 0; k < props.size(); ++k) {
        std::string what = props[k]->GetClassName();
        if (auto* a = vtkActor::SafeDownCast(props[k]); a && a->GetMapper())
            if (auto* pd = vtkPolyData::SafeDownCast(a->GetMapper()->GetInputDataObject(0, 0)))
                what += " (" + std::to_string(pd->GetNumberOfPolys()) + " polys, " + std::to_string(pd->GetNumberOfLines()) + " lines)";
        std::printf("  without prop %zu %s: saves %.1f ms processor, %.1f ms clock\n", k, what.c_str(), (cpu[0] - cpu[k + 1]) / n,
                    (wall[0] - wall[k + 1]) / n);
    }
    state.counters["frame_cpu_ms"] = cpu[0] / n;
}
BENCHMARK(BM_FrameParts)->Unit(benchmark::kMillisecond)->Iterations(20);

void BM_StockLight(benchmark::State& state)
{
    const auto plan = samplePlan();
    if (!plan || plan->steps.empty()) {
        state.SkipWithError("cannot plan resources/samples/plate.taiwa (run from the source root)");
        return;
    }
    StockView view(plan, 836, 425);
    vtkRenderWindow* window = view.offscreen.window();
    if (!window) {
        state.SkipWithError(view.offscreen.problem()->c_str());
        return;
    }
    view.scene.setLightOnProcessor(state.range(0) == 1);
    const bool turn = state.range(1) == 1;
    window->Render();
    double cpu = 0, wall = 0;
    long frames = 0;
    for (auto _ : state) {
        if (turn) view.scene.renderer()->GetActiveCamera()->Azimuth(frames % 2 == 0 ? 1.0 : -1.0);
        const FrameTime t = timedFrame(window);
        wall += t.wall;
        cpu += t.cpu;
        ++frames;
    }
    state.counters["frame_cpu_ms"] = cpu / static_cast<double>(frames);
    state.counters["frame_ms"] = wall / static_cast<double>(frames);
}
BENCHMARK(BM_StockLight)->ArgsProduct({{0, 1}, {0, 1}})->ArgNames({"processor", "turning"})->Unit(benchmark::kMillisecond)->Iterations(40);

}  // namespace

BENCHMARK_MAIN();
