// What reading the posted tape back (verify/tape_readback.h) adds to a
// verification: for the shipped milling sample with the most moves, the
// verification at its default cell size (what `taiwa verify` and `taiwa
// export` run), then in each dialect the post (which the read-back needs
// and the export then writes, so it is posted once either way), the reading
// of the tape and its judgement against the plan. Prints milliseconds, the
// best of five runs, and the read-back as a share of the verification.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "tools/tool_library.h"
#include "verify/tape_readback.h"
#include "verify/tape_reader.h"
#include "verify/verify.h"
#include "bench_paths.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

using namespace taiwa;

namespace {

double bestMs(const std::function<void()>& f, int runs = 5)
{
    double best = 1e300;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

std::size_t movesOf(const Plan& p)
{
    std::size_t n = 0;
    for (const auto& s : p.steps) n += s.path ? s.path->moves.size() : 0;
    return n;
}

}  // namespace

int main()
{
    // The milling sample with the most moves.
    Plan largest;
    std::string name;
    for (const auto& e : std::filesystem::directory_iterator(taiwa::bench::dir() + "/../resources/samples")) {
        if (e.path().extension() != ".taiwa" || e.path().filename().string().starts_with("lathe-")) continue;
        const JobReadResult read = readJobFile(e.path().string());
        if (!read.job) continue;
        Plan p = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        if (!p.ok() || p.mmJob.bar || movesOf(p) <= movesOf(largest)) continue;
        largest = std::move(p);
        name = e.path().filename().string();
    }
    std::printf("largest milling sample: %s, %zu moves\n", name.c_str(), movesOf(largest));
    verify::Options o;
    o.resolution = verify::defaultResolution(largest);
    o.maxCellVisits = verify::kDefaultCellVisits;
    verify::Report report;
    const double verifyMs = bestMs([&] { report = verify::verifyPlan(largest, o); }, 3);
    std::printf("verification at %.2f mm: %.1f ms\n", o.resolution, verifyMs);
    std::printf("%-11s %8s %10s %10s %12s %8s\n", "dialect", "lines", "post ms", "read ms", "read-back ms", "share");
    for (const auto& d : post::dialectLibrary()) {
        const PostOptions po = postOptions(largest, d.name);
        PostedProgram posted;
        const double postMs = bestMs([&] { posted = postProcess(largest.steps, largest.tools, po); });
        const double readMs = bestMs([&] { (void)verify::readTape(posted.nc, d); });
        const std::vector<verify::Finding> before = report.findings;
        std::size_t findings = 0;
        const double backMs = bestMs([&] {
            report.findings = before;
            verify::readBack(report, largest, posted, d, po);
            findings = report.findings.size() - before.size();
        });
        report.findings = before;
        std::printf("%-11s %8zu %10.1f %10.1f %12.1f %7.1f%%%s\n", d.name.c_str(), posted.lines.size(), postMs, readMs,
                    backMs, 100.0 * (postMs + backMs) / verifyMs, findings ? "  (findings!)" : "");
    }
    return 0;
}
