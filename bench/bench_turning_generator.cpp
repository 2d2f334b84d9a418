// The grinding allowance proved by generation at scale (issue 33): 10,000
// seeded random turned profiles of tests/support/turned_generator.h (the
// generator test_turning_generator replays 400 of in CI), each deformed by
// its allowance table and checked: the deformed profile may not lie inside
// the part by more than 0.1 µm. One iteration; prints the counts (profiles,
// inner ones, tables accepted, refusals by field, grooves made by kind and
// at corners that are not square, failing seeds) and reports them as
// counters, with the time per profile. Then the accepted ones planned as
// lathe jobs and verified: the counts of plans refused and of findings by
// kind, with their first seeds. And generated lathe parts (ridges, front
// roundings, fillets) planned, verified and run through rs274.
#include "support/turned_generator.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace taiwa;

namespace {

void BM_GeneratedProfiles(benchmark::State& state)
{
    const auto n = static_cast<std::uint64_t>(state.range(0));
    test::GeneratorTally tally;
    double seconds = 0.0;
    for (auto _ : state) {
        tally = {};
        const auto start = std::chrono::steady_clock::now();
        for (std::uint64_t seed = 1; seed <= n; ++seed) tally.add(test::runSeed(seed));
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("seeds 1-%llu: %s; %.1f s\n", static_cast<unsigned long long>(n), tally.summary().c_str(), seconds);
    state.counters["profiles"] = static_cast<double>(tally.profiles);
    state.counters["accepted"] = static_cast<double>(tally.accepted);
    state.counters["grooves"] = static_cast<double>(tally.groovesByKind["lateral"] + tally.groovesByKind["longitudinal"] +
                                                    tally.groovesByKind["ring"]);
    state.counters["not_square"] = static_cast<double>(tally.nonSquareGrooves);
    state.counters["failing"] = static_cast<double>(tally.failing.size());
    state.counters["ms_per_profile"] = 1000.0 * seconds / static_cast<double>(n);
}
BENCHMARK(BM_GeneratedProfiles)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond);

// The seeds whose table the deformer accepts, as lathe jobs: planned with
// the default library and verified (issue 33, item 3 is the planner's: the
// counts by class are reported here, not required to be zero).
void BM_GeneratedPlans(benchmark::State& state)
{
    const auto n = static_cast<std::uint64_t>(state.range(0));
    test::PlanTally tally;
    double seconds = 0.0;
    for (auto _ : state) {
        tally = {};
        const auto start = std::chrono::steady_clock::now();
        for (std::uint64_t seed = 1; seed <= n; ++seed)
            if (test::runSeed(seed).accepted) tally.add(seed, test::planAndVerify(test::generateTurnedProfile(seed)));
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("seeds 1-%llu, accepted tables: %s; %.1f s\n", static_cast<unsigned long long>(n), tally.summary().c_str(),
                seconds);
    state.counters["plans"] = static_cast<double>(tally.planned);
    state.counters["clean"] = static_cast<double>(tally.clean);
}
BENCHMARK(BM_GeneratedPlans)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond);

// Issue 33, item 3: 10,000 lathe parts of generateLathePart (ridges, front
// roundings, fillets on both sides of the nose radii, allowance tables)
// planned, verified and their linuxcnc tapes run through rs274; run it with
// TAIWA_RS274_LOCK=/tmp/rs274.lock so that each rs274 run takes the lock the
// tests share (not the whole run). TAIWA_BENCH_PARTS sets another count,
// TAIWA_BENCH_NO_RS274=1 plans and verifies only, TAIWA_BENCH_FIRST=<seed>
// starts there (several runs side by side, each a slice of the seeds). Each plan refused by the
// verifier or rs274 is listed on stderr with its findings.
void BM_GeneratedLatheParts(benchmark::State& state)
{
    const int env = std::getenv("TAIWA_BENCH_PARTS") ? std::atoi(std::getenv("TAIWA_BENCH_PARTS")) : 0;
    const auto n = static_cast<std::uint64_t>(env > 0 ? env : state.range(0));
    const bool rs274 = !std::getenv("TAIWA_BENCH_NO_RS274");
    const int firstEnv = std::getenv("TAIWA_BENCH_FIRST") ? std::atoi(std::getenv("TAIWA_BENCH_FIRST")) : 0;
    const auto firstSeed = static_cast<std::uint64_t>(firstEnv > 0 ? firstEnv : 1);
    test::PlanTally tally;
    double seconds = 0.0;
    for (auto _ : state) {
        tally = {};
        const auto start = std::chrono::steady_clock::now();
        for (std::uint64_t seed = firstSeed; seed < firstSeed + n; ++seed) {
            const test::GeneratedProfile g = test::generateLathePart(seed);
            const test::PlanCheck c = test::planAndVerify(g, rs274);
            tally.add(seed, c, g.shapes);
            // Each plan refused by the verifier or rs274 on stderr, with its
            // findings (to sort the failures into classes).
            if (c.planned && (c.fatal || !c.rs274Refusal.empty())) {
                std::string what = c.rs274Refusal.empty() ? "" : " rs274: " + c.rs274Refusal;
                for (const auto& [kind, first] : c.first)
                    if (kind != "rest-material") what += " | " + first;
                std::fprintf(stderr, "seed %llu:%s\n", static_cast<unsigned long long>(seed), what.c_str());
            }
            // The counts so far every 500 seeds (a long run stopped early still says them).
            if (seed % 500 == 0)
                std::fprintf(stderr, "after seed %llu: %s\n", static_cast<unsigned long long>(seed), tally.summary().c_str());
        }
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("lathe parts %llu-%llu: %s; %.1f s\n", static_cast<unsigned long long>(firstSeed),
                static_cast<unsigned long long>(firstSeed + n - 1), tally.summary().c_str(), seconds);
    state.counters["plans"] = static_cast<double>(tally.planned);
    state.counters["clean"] = static_cast<double>(tally.clean);
    state.counters["rs274_refused"] = static_cast<double>(tally.rs274Refused);
}
BENCHMARK(BM_GeneratedLatheParts)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
