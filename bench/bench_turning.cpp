// The grinding allowance (core/turning/allowance.h) on a long profile: a
// stepped shaft of 200 edges (100 cylinders, each with its shoulder), with 1,
// 10 and 50 allowance rows on cylinders (every other one, half of them with
// a relief groove). Prints the time per call and, as "per_row", per
// allowance row; the profile's resolution from its table on its own.
#include "turning/allowance.h"
#include "turning/profile_resolve.h"

#include <benchmark/benchmark.h>

#include <stdexcept>

using namespace taiwa;
using namespace taiwa::turning;

namespace {

TurnedProfile longShaft(int rows)
{
    TurnedProfile p;
    double x = 10.0, z = 0.0;
    int id = 1;
    ProfileRow face;
    face.id = id++;
    face.x = x;
    p.rows.push_back(face);
    for (int step = 0; step < 100; ++step) {
        ProfileRow cyl;
        cyl.id = id++;
        cyl.x = x;
        cyl.z = z -= 5.0;
        p.rows.push_back(cyl);
        if (step == 99) break;
        ProfileRow shoulder;
        shoulder.id = id++;
        shoulder.x = x += 2.0;
        shoulder.z = z;
        p.rows.push_back(shoulder);
    }
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

}  // namespace

BENCHMARK_MAIN();
