// Surface machining speed (docs/surfaces.md): tool-nose points per second
// on a 200 × 200 mm free-form surface (z = 10 sin(x/20) cos(y/25), given as
// point-sequence paths 1 mm apart, 80,000 triangles tessellated once) at
// 0.1 mm step with a 10 mm ball and a 10 mm bull-nose r 2; the whole
// finishing program (pick-feed holding a 0.01 mm scallop, all 200 × 200 mm
// at 0.1 mm step); Z-level roughing of it; and beside them, why the hot loop
// does not ask OpenCASCADE: one GeomAPI_ProjectPointOnSurf per point on the
// same surface as a B-spline.
#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"

#include <benchmark/benchmark.h>

#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cmath>

using namespace taiwa;
using namespace taiwa::surface;

namespace {

double height(double x, double y) { return 10 * std::sin(x / 20) * std::cos(y / 25); }

std::vector<std::vector<Point3>> surfacePaths(double spacing)
{
    std::vector<std::vector<Point3>> paths;
    const int n = static_cast<int>(std::lround(200 / spacing));
    for (int i = 0; i <= n; ++i) {
        std::vector<Point3> path;
        for (int j = 0; j <= n; ++j) path.push_back({j * spacing, i * spacing, height(j * spacing, i * spacing)});
        paths.push_back(std::move(path));
    }
    return paths;
}

const MeshIndex& surfaceIndex()
{
    static const MeshIndex index(meshFromPaths(surfacePaths(1.0)));
    return index;
}

// Tool-nose points along rows at 0.1 mm step, rows spread over the surface.
void BM_NosePoints(benchmark::State& state, Cutter cutter)
{
    DropCutter drop(surfaceIndex(), cutter);
    std::int64_t points = 0;
    double y = 0;
    for (auto _ : state) {
        for (const auto& p : dropLine(drop, y, 0, 200, 0.1)) points += static_cast<std::int64_t>(p.size());
        y = std::fmod(y + 7.3, 200);
    }
    state.SetItemsProcessed(points);
    state.counters["triangles"] = static_cast<double>(surfaceIndex().mesh().triangles.size());
}

void BM_Tessellate(benchmark::State& state)
{
    const auto paths = surfacePaths(1.0);
    for (auto _ : state) {
        MeshIndex index(meshFromPaths(paths));
        benchmark::DoNotOptimize(index.mesh().triangles.data());
    }
}

void BM_FinishingProgram(benchmark::State& state)
{
    DropCutter drop(surfaceIndex(), Cutter{10, 5});
    std::size_t paths = 0, points = 0;
    for (auto _ : state) {
        const FinishingPaths f = finishingPaths(drop, Area{0, 0, 200, 200}, 0.1, 0.01);
        paths = f.paths.size();
        points = 0;
        for (const auto& p : f.paths) points += p.size();
    }
    state.counters["paths"] = static_cast<double>(paths);
    state.counters["nose_points"] = static_cast<double>(points);
}

void BM_ZLevelRoughing(benchmark::State& state)
{
    ZLevelOptions o;
    o.top = 11;
    o.depth = 2;
    o.stepOver = 6;
    o.step = 0.5;
    o.allowance = 0.3;
    std::size_t passes = 0;
    for (auto _ : state) passes = zLevelRoughing(surfaceIndex(), Cutter{10, 5}, Area{0, 0, 200, 200}, o).size();
    state.counters["passes"] = static_cast<double>(passes);
}

// The alternative: OpenCASCADE projecting each point onto the exact
// B-spline surface (the surface only, no cutter): points per second.
void BM_OcctProjection(benchmark::State& state)
{
    const auto paths = surfacePaths(5.0);
    TColgp_Array2OfPnt pts(1, static_cast<int>(paths.size()), 1, static_cast<int>(paths[0].size()));
    for (std::size_t i = 0; i < paths.size(); ++i)
        for (std::size_t j = 0; j < paths[i].size(); ++j)
            pts.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1,
                         gp_Pnt(paths[i][j].x, paths[i][j].y, paths[i][j].z));
    const Handle(Geom_BSplineSurface) surf = GeomAPI_PointsToBSplineSurface(pts).Surface();
    std::int64_t points = 0;
    double x = 0.05;
    for (auto _ : state) {
        GeomAPI_ProjectPointOnSurf proj(gp_Pnt(x, 100.05, 20), surf);
        benchmark::DoNotOptimize(proj.NbPoints());
        ++points;
        x = std::fmod(x + 0.1, 200);
    }
    state.SetItemsProcessed(points);
}

}  // namespace

BENCHMARK(BM_Tessellate)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_NosePoints, ball_d10, Cutter{10, 5})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_NosePoints, bullnose_d10_r2, Cutter{10, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FinishingProgram)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_ZLevelRoughing)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_OcctProjection)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
