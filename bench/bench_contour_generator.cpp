// The contour units proved by generation at scale (issue 33): 10,000 seeded
// random contour jobs of tests/support/contour_generator.h (the generator
// test_contour_generator replays 240 of in CI), half CP pockets with necks
// and islands, half SIDE contours with notches, each planned, verified by
// the product, its linuxcnc tape run through rs274 and the tool centre
// measured against the walls. One iteration; prints the counts (cases,
// planned, verified clean, refused with a reason by field, tapes accepted,
// the least margin of the tool centre to R, failing seeds) and reports them
// as counters. TAIWA_CONTOUR_SEEDS sets the count (default 10,000);
// TAIWA_CONTOUR_NO_TAPE=1 leaves rs274 out (about ten times as fast);
// TAIWA_CONTOUR_REFUSALS=1 lists every refusal on stderr;
// TAIWA_BENCH_FIRST=<seed> starts there (a run in slices, as the lathe
// generator's bench does).
#include "support/contour_generator.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

using namespace taiwa;

namespace {

void BM_GeneratedContours(benchmark::State& state)
{
    const char* seeds = std::getenv("TAIWA_CONTOUR_SEEDS");
    const auto n = seeds ? std::strtoull(seeds, nullptr, 10) : static_cast<unsigned long long>(state.range(0));
    const bool tapes = !std::getenv("TAIWA_CONTOUR_NO_TAPE");
    const char* firstEnv = std::getenv("TAIWA_BENCH_FIRST");
    const std::uint64_t first = firstEnv && std::strtoull(firstEnv, nullptr, 10) > 0 ? std::strtoull(firstEnv, nullptr, 10) : 1;
    const std::uint64_t last = first + n - 1;
    test::ContourTally tally;
    double seconds = 0.0;
    for (auto _ : state) {
        tally = {};
        const auto start = std::chrono::steady_clock::now();
        std::vector<test::ContourCase> cases;
        std::vector<test::ContourOutcome> outcomes;
        const auto flush = [&] {
            std::vector<std::pair<const test::ContourCase*, test::ContourOutcome*>> batch;
            for (std::size_t k = 0; k < cases.size(); ++k)
                if (outcomes[k].planned) batch.push_back({&cases[k], &outcomes[k]});
            if (tapes && !batch.empty()) test::runTapes(batch);  // twenty tapes to one rs274
            for (std::size_t k = 0; k < cases.size(); ++k) {
                tally.add(cases[k], outcomes[k]);
                // TAIWA_CONTOUR_REFUSALS=1: every refusal on stderr, by seed.
                if (std::getenv("TAIWA_CONTOUR_REFUSALS") && !outcomes[k].planned)
                    std::fprintf(stderr, "seed %llu %s %s: %s\n", static_cast<unsigned long long>(cases[k].seed),
                                 cases[k].module.c_str(), outcomes[k].refusedOn.c_str(), outcomes[k].refusal.c_str());
            }
            cases.clear();
            outcomes.clear();
        };
        for (std::uint64_t seed = first; seed <= last; ++seed) {
            cases.push_back(test::generateContourCase(seed));
            outcomes.push_back(test::runContourCase(cases.back(), false));
            if (cases.size() == 20) flush();
            if (seed % 1000 == 0) {  // the counts so far, for a run stopped early
                std::fprintf(stderr, "seeds %llu-%llu: %s\n", static_cast<unsigned long long>(first),
                             static_cast<unsigned long long>(seed), tally.summary().c_str());
                std::fflush(stderr);
            }
        }
        flush();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("seeds %llu-%llu: %s; %.1f s\n", static_cast<unsigned long long>(first), static_cast<unsigned long long>(last),
                tally.summary().c_str(), seconds);
    state.counters["cases"] = tally.cases;
    state.counters["planned"] = tally.planned;
    state.counters["clean"] = tally.clean;
    state.counters["refused"] = tally.refused;
    state.counters["rs274_accepted"] = tally.tapesAccepted;
    state.counters["failing"] = static_cast<double>(tally.failing.size());
    state.counters["ms_per_case"] = 1000.0 * seconds / static_cast<double>(n);
}
BENCHMARK(BM_GeneratedContours)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
