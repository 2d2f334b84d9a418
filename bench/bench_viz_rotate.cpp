// 3-D preview speed: frames per second while the camera turns around a
// scene with a 10,000-segment and a 1,000,000-segment tool path (offscreen
// under Xvfb with Mesa), and the time to build the scene for a plan. Prints
// both frame rates and their ratio. Run under `xvfb-run -a`.
#include "viz/render.h"
#include "viz/scene.h"

#include <benchmark/benchmark.h>

#include <algorithm>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>

#include <chrono>
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

std::map<int, double> framesPerSecond;

void BM_Rotate(benchmark::State& state)
{
    const viz::OffscreenWindow offscreen(800, 600);
    if (offscreen.problem()) {
        state.SkipWithError(offscreen.problem()->c_str());
        return;
    }
    const int segments = static_cast<int>(state.range(0));
    viz::Scene scene;
    scene.setPlan(zigzagPlan(segments));
    scene.setView(viz::ViewPreset::Iso, 800.0 / 600.0);
    vtkRenderWindow* window = offscreen.window();
    window->AddRenderer(scene.renderer());
    window->Render();  // first frame uploads the geometry
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        scene.renderer()->GetActiveCamera()->Azimuth(3.0);
        window->Render();
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    framesPerSecond[segments] = static_cast<double>(state.iterations()) / elapsed.count();
    state.counters["fps"] = framesPerSecond[segments];
}
BENCHMARK(BM_Rotate)->Arg(10'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

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

}  // namespace

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    const double small = framesPerSecond[10'000], large = framesPerSecond[1'000'000];
    if (small > 0 && large > 0)
        std::printf("rotate: %.1f fps with 10,000 segments, %.1f fps with 1,000,000: ratio %.1f\n", small, large, small / large);
    return 0;
}
