// 3-D preview speed: frames per second while the camera turns around a
// scene with a 10,000-segment and a 1,000,000-segment tool path (offscreen
// under Xvfb with Mesa, 800 x 600, no multisampling), against an anchor
// measured in the same run: raw VTK drawing the same segments (one
// polyline, one vtkPolyDataMapper and vtkActor in a plain vtkRenderer, the
// same camera and motion). The frames of the raw scene, the scene still
// (full detail) and the scene moving (Scene::setMoving: its level of
// detail) are interleaved, so a load that comes and goes on the shared
// machine weighs on all three alike. Also the time to build the scene for a
// plan and to make its level of detail. Run under `xvfb-run -a`.
#include "viz/render.h"
#include "viz/scene.h"

#include <benchmark/benchmark.h>

#include <algorithm>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <map>
#include <memory>

using namespace taiwa;

namespace {

// One roughing step whose path zig-zags over the 200 x 150 stock in
// `segments` feed moves at Z -5.
std::shared_ptr<const Plan> zigzagPlan(int segments)
{
    auto plan = std::make_shared<Plan>();
    plan->mmJob.stock = {0, 0, 200, 150, 30};
    Tool mill;
    mill.id = 1;
    mill.diameter = 10;
    plan->tools = {mill};
    Step s;
    s.tool = ToolChoice{1, ""};
    ToolPath p{{5, 5, 5}, {{MoveKind::Feed, {5, 5, -5}}}};
    const int rows = 1000;
    const int perRow = std::max(1, segments / rows);
    p.moves.reserve(static_cast<std::size_t>(segments) + 1);
    for (int k = 0; static_cast<int>(p.moves.size()) < segments; ++k) {
        const double y = 5 + 140.0 * (k % rows) / rows;
        const bool right = k % 2 == 0;
        for (int i = 1; i <= perRow && static_cast<int>(p.moves.size()) < segments; ++i) {
            const double t = static_cast<double>(i) / perRow;
            p.moves.push_back({MoveKind::Feed, {right ? 5 + 190 * t : 195 - 190 * t, y, -5}});
        }
    }
    s.path = p;
    plan->steps = {s};
    return plan;
}

// The anchor: the plan's one path (straight feeds) as raw VTK draws it,
// every VTK default left as it is.
vtkSmartPointer<vtkRenderer> rawScene(const Plan& plan)
{
    const ToolPath& path = *plan.steps.front().path;
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->InsertNextPoint(path.start.x, path.start.y, path.start.z);
    for (const Move& m : path.moves) points->InsertNextPoint(m.end.x, m.end.y, m.end.z);
    auto line = vtkSmartPointer<vtkCellArray>::New();
    line->InsertNextCell(static_cast<int>(points->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) line->InsertCellPoint(i);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(line);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->AddActor(actor);
    return renderer;
}

// Processor time of the whole process (Mesa's drawing threads included):
// less swayed by other builders than the clock.
double cpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

struct Figures {
    double raw = 0, still = 0, moving = 0;  // frames per second
    double rawCpu = 0, stillCpu = 0, movingCpu = 0;  // processor ms per frame
    std::size_t drawnStill = 0, drawnMoving = 0;  // path segments drawn
};
std::map<int, Figures> figures;

using Clock = std::chrono::steady_clock;

void BM_Rotate(benchmark::State& state)
{
    const int segments = static_cast<int>(state.range(0));
    const auto plan = zigzagPlan(segments);
    const viz::OffscreenWindow rawWindow(800, 600), stillWindow(800, 600), movingWindow(800, 600);
    for (const auto* w : {&rawWindow, &stillWindow, &movingWindow})
        if (w->problem()) {
            state.SkipWithError(w->problem()->c_str());
            return;
        }
    viz::Scene still, moving;
    for (viz::Scene* scene : {&still, &moving}) {
        scene->setPlan(plan);
        scene->setView(viz::ViewPreset::Iso, 800.0 / 600.0);
    }
    moving.setMoving(true);
    const vtkSmartPointer<vtkRenderer> raw = rawScene(*plan);
    raw->GetActiveCamera()->DeepCopy(still.renderer()->GetActiveCamera());
    raw->ResetCameraClippingRange();
    struct Run {
        vtkRenderWindow* window;
        vtkRenderer* renderer;
        Clock::duration time{};
        double cpu = 0;
    };
    Run runs[3] = {{rawWindow.window(), raw}, {stillWindow.window(), still.renderer()}, {movingWindow.window(), moving.renderer()}};
    for (Run& r : runs) {
        r.window->AddRenderer(r.renderer);
        r.window->Render();  // the first frame uploads the geometry
    }
    long frames = 0;
    for (auto _ : state) {
        for (Run& r : runs) {  // a frame of each, in turn
            const auto start = Clock::now();
            const double cpu = cpuSeconds();
            r.renderer->GetActiveCamera()->Azimuth(3.0);
            r.renderer->ResetCameraClippingRange();  // as the interactor does
            r.window->Render();
            // Until the frame is drawn: Mesa draws on its own threads after
            // Render returns, and the next window's frame would pay for it.
            r.window->WaitForCompletion();
            r.time += Clock::now() - start;
            r.cpu += cpuSeconds() - cpu;
        }
        ++frames;
    }
    const auto fps = [&](const Run& r) { return static_cast<double>(frames) / std::chrono::duration<double>(r.time).count(); };
    Figures& f = figures[segments];
    const auto cpuMs = [&](const Run& r) { return 1000 * r.cpu / static_cast<double>(frames); };
    f = {fps(runs[0]), fps(runs[1]), fps(runs[2]), cpuMs(runs[0]), cpuMs(runs[1]), cpuMs(runs[2]),
         still.drawnPathSegments(), moving.drawnPathSegments()};
    state.counters["raw_fps"] = f.raw;
    state.counters["fps"] = f.still;
    state.counters["lod_fps"] = f.moving;
    state.counters["ratio"] = f.still / f.raw;
    state.counters["lod_ratio"] = f.moving / f.raw;
}
BENCHMARK(BM_Rotate)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void BM_BuildScene(benchmark::State& state)
{
    const auto plan = zigzagPlan(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        viz::Scene scene;
        scene.setPlan(plan);
        benchmark::DoNotOptimize(scene.renderer());
    }
}
BENCHMARK(BM_BuildScene)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// The first motion of a large plan's scene: its decimated paths made.
void BM_BuildLod(benchmark::State& state)
{
    const auto plan = zigzagPlan(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        state.PauseTiming();
        viz::Scene scene;
        scene.setPlan(plan);
        state.ResumeTiming();
        scene.setMoving(true);
        benchmark::DoNotOptimize(scene.drawnPathSegments());
    }
}
BENCHMARK(BM_BuildLod)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    for (const auto& [segments, f] : figures) {
        if (f.raw <= 0) continue;
        std::printf("rotate %d segments: raw VTK %.1f fps; scene still %.1f fps (%.0f %% of raw, %zu segments drawn), "
                    "moving %.1f fps (%.0f %% of raw, %zu segments drawn)\n",
                    segments, f.raw, f.still, 100 * f.still / f.raw, f.drawnStill, f.moving, 100 * f.moving / f.raw, f.drawnMoving);
        std::printf("  processor time a frame: raw VTK %.1f ms, scene still %.1f ms (raw / scene %.0f %%), moving %.1f ms (%.0f %%)\n",
                    f.rawCpu, f.stillCpu, 100 * f.rawCpu / f.stillCpu, f.movingCpu, 100 * f.rawCpu / f.movingCpu);
    }
    const Figures small = figures[10'000], large = figures[1'000'000];
    if (small.still > 0 && large.still > 0)
        std::printf("rotate: %.1f fps with 10,000 segments, %.1f fps with 1,000,000: ratio %.1f\n", small.still, large.still,
                    small.still / large.still);
    return 0;
}
