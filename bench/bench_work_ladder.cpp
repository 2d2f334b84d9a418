// Work estimates against real time (issue 39), on a ladder of sizes per
// module: what each check or plan estimates before doing the work (the
// counter `estimate`) beside the time it then takes, so that time growing
// faster than the estimate shows. The jobs are generated as in
// tests/test_bounded_work.cpp:
//  - CP: a regular n-gon of radius 400 rounded by 1 mm at every corner,
//    the whole input processing (figure, sizing, checks); estimate: the
//    region's lines and arcs (refused beyond 20,000, named_region.h);
//  - AREA: n passes drawn at random across an 800 mm square, the checks
//    (excursions, unswept area); estimate: the strips' overlapping pairs
//    (refused beyond 50,000, area.h);
//  - FACE: a 1,000 x 1,000 block faced at a step-over ladder, planned with
//    its paths; estimate: estimateMoves of the plan (refused beyond 10⁷);
//  - DXF: a circle of n LINEs read, chained and written as figure text and
//    the text evaluated; estimate: the LINEs.
#include "dxf/dxf_import.h"
#include "figure/figure_eval.h"
#include "figure/figure_text.h"
#include "figure/figure_from_contours.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/area/area.h"
#include "modules/registry.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

using namespace taiwa;

namespace {

Job makeJob(const std::vector<std::string>& figure, const nlohmann::json& unit, double side = 1000)
{
    nlohmann::json j{{"format", "taiwa-job"},
                     {"version", 5},
                     {"lengthUnit", "mm"},
                     {"material", "aluminium-6061"},
                     {"stock", {{"shape", "block"}, {"x", 0}, {"y", 0}, {"width", side}, {"length", side}, {"height", 50}}},
                     {"units", nlohmann::json::array({unit})}};
    if (!figure.empty()) j["figure"] = figure;
    auto r = readJob(j.dump());
    if (!r.job) throw std::runtime_error("bench job not read");
    return *r.job;
}

std::vector<std::string> roundedPolygon(int n)
{
    std::vector<std::string> f;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        f.push_back(fmt::format("P{} = POINT/{:.9f}, {:.9f}", i + 1, 500 + 400 * std::cos(a), 500 + 400 * std::sin(a)));
    }
    std::string k = "K1 = CONTOUR/";
    for (int i = 0; i < n; ++i) {
        f.push_back(fmt::format("L{} = LINE/P{}, P{}", i + 1, i + 1, (i + 1) % n + 1));
        k += fmt::format("{}L{}, ROUND, 1", i ? ", " : "", i + 1);
    }
    f.push_back(k);
    return f;
}

void BM_ContourPocketCheck(benchmark::State& state)
{
    const Job job = makeJob(roundedPolygon(static_cast<int>(state.range(0))),
                            {{"module", "CP"}, {"name", "gon"}, {"outline", "K1"}, {"depth", 10}});
    bool refused = false;
    for (auto _ : state) {
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        refused = hasErrors(ds);
        benchmark::DoNotOptimize(ds);
    }
    state.counters["estimate"] = 2.0 * static_cast<double>(state.range(0));  // lines and roundings
    state.counters["refused"] = refused;
}

void BM_AreaCheck(benchmark::State& state)
{
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> at(130, 870);
    std::vector<Point2> points;
    nlohmann::json pts = nlohmann::json::array();
    for (int i = 0; i < state.range(0); ++i) {
        points.push_back({at(rng), at(rng)});
        pts.push_back({points.back().x, points.back().y});
    }
    const Job job = makeJob({"P1 = POINT/100, 100", "P2 = POINT/900, 900", "L1 = LINE/P1, ATANGL, 0", "L2 = LINE/P2, ATANGL, 90",
                             "L3 = LINE/P2, ATANGL, 180", "L4 = LINE/P1, ATANGL, 270",
                             "K1 = CONTOUR/L1, ROUND, 20, L2, ROUND, 20, L3, ROUND, 20, L4, ROUND, 20"},
                            {{"module", "AREA"}, {"name", "a"}, {"outline", "K1"}, {"diameter", 10}, {"depth", 5}, {"points", pts}});
    bool refused = false;
    for (auto _ : state) {
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        refused = hasErrors(ds);
        benchmark::DoNotOptimize(ds);
    }
    state.counters["estimate"] = static_cast<double>(overlappingStripPairs(points, 5.0, 1u << 30));
    state.counters["refused"] = refused;
}

// Step-over in thousandths of the diameter.
void BM_FacePlan(benchmark::State& state)
{
    const Job job = makeJob({}, {{"module", "FACE"}, {"name", "f"}, {"depth", 2}, {"stepOver", state.range(0) / 1000.0}});
    PlanOptions estimateOnly;
    estimateOnly.withToolPaths = false;
    const Plan steps = planJob(job, TechnologyTable::builtIn(), defaultToolLibrary(), estimateOnly);
    double estimate = 0;
    for (const Step& s : steps.steps)
        estimate += estimateMoves(s, *findTool(defaultToolLibrary(), s.tool->toolId), steps.technology, {});
    std::size_t moves = 0;
    for (auto _ : state) {
        const Plan p = planJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        moves = 0;
        for (const Step& s : p.steps) moves += s.path ? s.path->moves.size() : 0;
        benchmark::DoNotOptimize(p);
    }
    state.counters["estimate"] = estimate;
    state.counters["moves"] = static_cast<double>(moves);
}

// `contours` circles of `n` / `contours` LINEs each, side by side.
std::string circlesOfLines(int n, int contours)
{
    std::string dxf = "0\nSECTION\n2\nENTITIES\n";
    const int k = n / contours;
    const double r = contours == 1 ? 400.0 : 12.0;
    for (int c = 0; c < contours; ++c) {
        const double cx = 30.0 * (c % 40), cy = 30.0 * (c / 40);
        for (int i = 0; i < k; ++i) {
            const double a = 2 * std::numbers::pi * i / k, b = 2 * std::numbers::pi * (i + 1) / k;
            dxf += fmt::format("0\nLINE\n8\n0\n10\n{:.9f}\n20\n{:.9f}\n11\n{:.9f}\n21\n{:.9f}\n", cx + r * std::cos(a),
                               cy + r * std::sin(a), cx + r * std::cos(b), cy + r * std::sin(b));
        }
    }
    return dxf + "0\nENDSEC\n0\nEOF\n";
}

// range(0) LINEs in range(1) closed contours: one circle of all of them, or
// many polygons of 200 (each contour's names used to copy every name before
// it: quadratic in the contours).
void BM_DxfFigure(benchmark::State& state)
{
    const auto n = static_cast<int>(state.range(0));
    const std::string dxf = circlesOfLines(n, static_cast<int>(state.range(1)));
    for (auto _ : state) {
        const dxf::DxfReadResult r = dxf::readDxfBytes(dxf);
        std::vector<Contour> contours;
        for (const auto& c : r.contours) contours.push_back(c.contour);
        const FigureFromContours f = figureFromContours(contours);
        const figure::Evaluation e = figure::evaluate(figure::parseFigure(f.text).definitions);
        benchmark::DoNotOptimize(e);
    }
    state.counters["estimate"] = n;
}

}  // namespace

BENCHMARK(BM_ContourPocketCheck)->RangeMultiplier(2)->Range(250, 16000)->Arg(25000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AreaCheck)->Arg(100)->Arg(200)->Arg(400)->Arg(500)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FacePlan)->Arg(750)->Arg(100)->Arg(20)->Arg(10)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_DxfFigure)
    ->Args({2000, 1})->Args({20000, 1})->Args({200000, 1})
    ->Args({20000, 100})->Args({40000, 200})->Args({200000, 1000})
    ->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
