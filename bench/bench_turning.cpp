// The grinding allowance (core/turning/allowance.h) on a long profile: a
// stepped shaft of 200 edges (100 cylinders, each with its shoulder), with 1,
// 10 and 50 allowance rows on cylinders (every other one, half of them with
// a relief groove). Prints the time per call and, as "per_row", per
// allowance row; the profile's resolution from its table on its own. And
// the turning process of a 100-element profile (issue: under 50 ms):
// decomposition, tool choice, every path and the lathe tape, with the
// number of moves and tape lines, for the control's cycle and for explicit
// passes.
#include "post/lathe_post.h"
#include "tools/tool_library.h"
#include "turning/allowance.h"
#include "modules/turn/turn_plan.h"
#include "turning/profile_resolve.h"
#include "model/turn_path.h"

#include <benchmark/benchmark.h>

#include <stdexcept>

using namespace taiwa;
using namespace taiwa::turning;

namespace {

// A stepped shaft: `steps` cylinders of `length`, each with its shoulder
// `rise` up (diameter), a rounding of `rounding` on every fifth shoulder
// when it is not 0.
TurnedProfile steppedShaft(int steps, double length, double rise, double rounding)
{
    TurnedProfile p;
    double x = 10.0, z = 0.0;
    int id = 1;
    ProfileRow face;
    face.id = id++;
    face.x = x;
    p.rows.push_back(face);
    for (int step = 0; step < steps; ++step) {
        ProfileRow cyl;
        cyl.id = id++;
        cyl.x = x;
        cyl.z = z -= length;
        p.rows.push_back(cyl);
        if (step == steps - 1) break;
        ProfileRow shoulder;
        shoulder.id = id++;
        shoulder.x = x += rise;
        shoulder.z = z;
        if (rounding > 0 && step % 5 == 0) {
            shoulder.corner = CornerKind::Rounding;
            shoulder.cornerSize = rounding;
        }
        p.rows.push_back(shoulder);
    }
    return p;
}

TurnedProfile longShaft(int rows)
{
    TurnedProfile p = steppedShaft(100, 5.0, 2.0, 0.0);
    for (int k = 0; k < rows; ++k) {
        AllowanceRow a;
        a.edge = edgeId(2 + 4 * k);  // every other cylinder
        a.allowance = 0.2;
        if (k % 2 == 0) a.grooveWidth = 1.0;
        p.allowances.push_back(a);
    }
    return p;
}

void BM_ResolveProfile(benchmark::State& state)
{
    const TurnedProfile p = longShaft(0);
    for (auto _ : state) {
        const Resolution r = resolveProfile(p);
        benchmark::DoNotOptimize(r.profile.edges.data());
    }
    state.counters["edges"] = static_cast<double>(resolveProfile(p).profile.edges.size());
}
BENCHMARK(BM_ResolveProfile)->Unit(benchmark::kMicrosecond);

void BM_Allowance(benchmark::State& state)
{
    const int rows = static_cast<int>(state.range(0));
    const TurnedProfile p = longShaft(rows);
    const Resolution r = resolveProfile(p);
    if (!r.ok()) throw std::logic_error("the bench profile is refused: " + r.problems.front().message);
    {
        const Deformation d = applyAllowances(r.profile, p.allowances);
        if (!d.ok()) throw std::logic_error("the bench allowances are refused: " + d.problems.front().message);
    }
    for (auto _ : state) {
        const Deformation d = applyAllowances(r.profile, p.allowances);
        benchmark::DoNotOptimize(d.profile.edges.data());
    }
    state.counters["edges"] = static_cast<double>(r.profile.edges.size());
    state.counters["rows"] = rows;
    state.counters["per_row"] = benchmark::Counter(static_cast<double>(rows) * static_cast<double>(state.iterations()),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Allowance)->Arg(1)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond);

// A stepped shaft of 100 elements: 50 cylinders of 2 mm, each with its
// shoulder 0.5 mm up (radius), rounded every fifth with R0.2 arcs kept as arcs.
TurnedProfile hundredElements() { return steppedShaft(50, 2.0, 1.0, 0.2); }

void BM_TurningProcess(benchmark::State& state)
{
    const bool cycles = state.range(0) != 0;
    const TurnedProfile p = hundredElements();
    const DeformedProfile d = applyAllowances(resolveProfile(p).profile, {}).profile;
    const std::vector<Tool> library = defaultToolLibrary();
    TurnPlanRequest q;
    q.deformed = &d;
    q.bar = {62.0, 140.0, 1.0, 0.0};
    q.library = &library;
    q.material = "steel-s45c";
    q.maxRpm = 4500;
    PostOptions o;
    o.dialect = "fanuc";
    o.turningCycles = cycles;
    std::size_t moves = 0, lines = 0;
    for (auto _ : state) {
        const TurnPlanResult r = planTurnedUnit(q);
        if (!r.problems.empty()) throw std::logic_error("the bench profile is refused: " + r.problems.front().message);
        const PostedProgram tape = postLathe(r.steps, library, o);
        moves = 0;
        for (const auto& s : r.steps) moves += turnOf(s)->path.moves.size();
        lines = tape.lines.size();
        benchmark::DoNotOptimize(tape.nc.data());
    }
    state.counters["elements"] = static_cast<double>(d.edges.size());
    state.counters["moves"] = static_cast<double>(moves);
    state.counters["tape_lines"] = static_cast<double>(lines);
}
BENCHMARK(BM_TurningProcess)->ArgName("cycles")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
