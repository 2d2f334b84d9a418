// A contour pocket with a 2,000-element outline and 20 islands (the issue's
// bench for contour units): its reach and inscribed circle, roughing, floor
// finishing and the exact wall pass with a 6 mm end mill, and the post of
// all three (linuxcnc); beside it, in the same run, the M4 pocket of
// bench_toolpaths (100 x 80, r 4, 12 deep, 6 mm) for the ratio the README
// prints. The outline is a gear of 500 teeth (a flank, a tip arc, a flank, a
// root arc each) of 100 mm root radius, the islands round and rounded
// squares by turns on a ring inside it.
#include "modules/registry.h"
#include "paths/region.h"
#include "paths/region_offset.h"
#include "post/post.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

using namespace taiwa;

namespace {

constexpr double kPi = std::numbers::pi;

Contour circle(Point2 c, double r)
{
    Contour k;
    k.closed = true;
    k.segments.push_back(ContourSegment::arc({c.x + r, c.y}, {c.x + r, c.y}, c, false));
    return k;
}

Contour roundedSquare(Point2 c, double half, double r)
{
    Contour k;
    k.closed = true;
    const double a = half - r;
    // Clockwise: an island.
    const Point2 corners[4] = {{c.x + a, c.y + a}, {c.x + a, c.y - a}, {c.x - a, c.y - a}, {c.x - a, c.y + a}};
    const Point2 out[4] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};  // the side before each corner, outward
    for (int i = 0; i < 4; ++i) {
        const Point2 o0 = out[i], o1 = out[(i + 1) % 4];
        const Point2 from = corners[i] + r * o0, to = corners[i] + r * o1;
        k.segments.push_back(ContourSegment::arc(from, to, corners[i], false));
        const Point2 next = corners[(i + 1) % 4] + r * o1;
        k.segments.push_back(ContourSegment::line(to, next));
    }
    return k;
}

const Region& gearPocket()
{
    static const Region r = [] {
        Region g;
        g.outer.closed = true;
        const int teeth = 500;
        const double root = 100.0, tip = 104.0, pitch = 2.0 * kPi / teeth;
        const auto at = [](double radius, double a) { return Point2{radius * std::cos(a), radius * std::sin(a)}; };
        for (int k = 0; k < teeth; ++k) {
            const double a0 = k * pitch, a1 = a0 + 0.5 * pitch, a2 = k + 1 == teeth ? 0.0 : a0 + pitch;
            g.outer.segments.push_back(ContourSegment::line(at(root, a0), at(tip, a0)));
            g.outer.segments.push_back(ContourSegment::arc(at(tip, a0), at(tip, a1), {0, 0}, true));
            g.outer.segments.push_back(ContourSegment::line(at(tip, a1), at(root, a1)));
            g.outer.segments.push_back(ContourSegment::arc(at(root, a1), at(root, a2), {0, 0}, true));
        }
        for (int i = 0; i < 20; ++i) {
            const Point2 c = at(60.0, 2.0 * kPi * i / 20);
            g.islands.push_back(i % 2 == 0 ? circle(c, 6.0) : roundedSquare(c, 6.0, 2.0));
        }
        return g;
    }();
    return r;
}

Tool endMill()
{
    Tool t;
    t.id = 1;
    t.type = ToolType::FlatEndMill;
    t.diameter = 6;
    t.fluteLength = 20;
    t.cutting.push_back({"aluminium-6061", 300, 0.05, 0.5});
    return t;
}

const TechnologyData kTech{1.0, 0.3, 0.1, 0.2, 0.5};  // alpha1, alpha2, alpha3, beta2, gamma

Step contourStep(StepKind kind, double start, double cut, double wall)
{
    Step s;
    s.kind = kind;
    s.module = "CP";
    editMilling(s).region = gearPocket();
    editMilling(s).startDepth = start;
    editMilling(s).cutDepth = cut;
    editMilling(s).wallAllowance = wall;
    s.tool = ToolChoice{1, ""};
    return s;
}

Step m4Step(StepKind kind, double start, double cut, double wall)
{
    Step s;
    s.kind = kind;
    s.module = "M4";
    editMilling(s).outline = Quad{{{{0, 0}, {100, 0}, {100, 80}, {0, 80}}}, 4.0};
    editMilling(s).position = {50, 40};
    editMilling(s).startDepth = start;
    editMilling(s).cutDepth = cut;
    editMilling(s).wallAllowance = wall;
    s.tool = ToolChoice{1, ""};
    return s;
}

void report(benchmark::State& state, const ToolPath& p)
{
    state.counters["moves"] = static_cast<double>(p.moves.size());
    state.counters["feed_mm"] = pathLength(p).feed;
}

void BM_Reach(benchmark::State& state)
{
    double reach = 0, inscribed = 0;
    for (auto _ : state) {
        inscribed = paths::inscribedRadius(gearPocket());
        reach = paths::reachRadius(gearPocket(), inscribed);
    }
    state.counters["reach_mm"] = reach;
    state.counters["inscribed_mm"] = inscribed;
}

void BM_ExactOffset(benchmark::State& state)
{
    std::size_t segments = 0;
    for (auto _ : state) {
        const auto pieces = paths::offsetRegion(gearPocket(), 3.0);
        segments = 0;
        for (const auto& c : paths::loopsOf(pieces.value())) segments += c.segments.size();
    }
    state.counters["segments"] = static_cast<double>(segments);
}

template <class Make>
void BM_Path(benchmark::State& state, Make make, StepKind kind, double start, double cut, double wall)
{
    const Step s = make(kind, start, cut, wall);
    ToolPath p;
    for (auto _ : state) {
        forgetProvedLayers();  // M4 proves a pocket once per shape: measure a first computation
        p = makeToolPath(s, endMill(), kTech, PathParameters{});
        benchmark::DoNotOptimize(p);
    }
    report(state, p);
}

template <class Make>
void BM_AllAndPost(benchmark::State& state, Make make)
{
    std::size_t lines = 0;
    for (auto _ : state) {
        forgetProvedLayers();
        std::vector<Step> steps{make(StepKind::Roughing, 0.0, 11.8, 0.3), make(StepKind::FloorFinishing, 11.8, 12.0, 0.3),
                                make(StepKind::WallFinishing, 0.0, 12.0, 0.0)};
        for (auto& s : steps) s.path = makeToolPath(s, endMill(), kTech, PathParameters{});
        PostOptions o;
        o.dialect = "linuxcnc";
        o.programName = "bench";
        o.material = "aluminium-6061";
        const PostedProgram posted = postProcess(steps, {endMill()}, o);
        lines = posted.lines.size();
        benchmark::DoNotOptimize(posted.nc.data());
    }
    state.counters["lines"] = static_cast<double>(lines);
}

}  // namespace

BENCHMARK(BM_Reach)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExactOffset)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, contour_roughing, contourStep, StepKind::Roughing, 0.0, 11.8, 0.3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, contour_floor, contourStep, StepKind::FloorFinishing, 11.8, 12.0, 0.3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, contour_walls, contourStep, StepKind::WallFinishing, 0.0, 12.0, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AllAndPost, contour, contourStep)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, m4_roughing, m4Step, StepKind::Roughing, 0.0, 11.8, 0.3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, m4_floor, m4Step, StepKind::FloorFinishing, 11.8, 12.0, 0.3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Path, m4_walls, m4Step, StepKind::WallFinishing, 0.0, 12.0, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AllAndPost, m4, m4Step)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
