// How the work grows with the job: `taiwa check` (read, checks, unit order,
// decomposition, tool choice and step order) and the whole export (plan with
// paths, tape, sheet with its PDF, steps) at 100 / 1,000 / 10,000 / 100,000
// units (100,000 units hold about 35 million moves: refused by the job's
// move budget, which the figure shows), each
// in a child process of its own so that its peak memory (ru_maxrss) is its
// alone. Prints time per unit and peak memory; time per unit should stay
// flat (the overlap check and the unit order go through grids). Last, the
// export of bench/fine-pocket.taiwa (step-over 2 %, step-down 0.2 mm).
#include "bench_anchor.h"
#include "bench_child.h"
#include "bench_job.h"

#include "export/export.h"
#include "io/job_io.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "bench_paths.h"

#include <QGuiApplication>
#include <QTemporaryDir>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string_view>


using namespace taiwa;

namespace {

// The export child's exit code when the plan is refused for its size.
constexpr int kRefused = 3;

// Whether `plan` was made; a plan refused for its size alone (the job's
// move budget, which `taiwa check` applies too) ends the child with
// kRefused, so that the figure says so rather than "FAILED".
bool planned(const Plan& plan)
{
    if (plan.ok()) return true;
    for (const auto& d : plan.diagnostics)
        if (d.severity == Severity::Error && d.message.find("moves") != std::string::npos) ::_exit(kRefused);
    return false;
}

void print(const char* what, int units, const bench::Measured& m)
{
    std::printf("%-8s %7d units  %9.3f s  %8.1f us/unit  peak %7.1f MB  %s\n", what, units, m.seconds,
                m.seconds / units * 1e6, m.peakKb / 1024.0,
                m.ok ? "ok" : m.exitCode == kRefused ? "refused: over the job's move budget (kMaxPlanMoves)" : "FAILED");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv)
{
    // `bench_scale --write-job N FILE` only writes the N-unit job, for profiling
    // `taiwa check FILE` / `taiwa export FILE` by hand.
    if (argc == 4 && std::string_view(argv[1]) == "--write-job")
        return writeFileAtomically(argv[3], writeJob(bench::bigJob(std::atoi(argv[2])))) ? 0 : 1;
    const std::vector<Tool> library = defaultToolLibrary();
    QTemporaryDir dir;
    // The machine's speed in this run (bench_anchor.h): the figures below
    // scale with it from run to run and machine to machine.
    const auto anchor = [] {
        std::printf("anchor: a plain to_chars loop writes %.1f M tape-like lines/s\n", bench::toCharsLinesPerSecond() / 1e6);
        std::fflush(stdout);
    };
    anchor();
    for (const int units : {100, 1'000, 10'000, 100'000}) {
        const std::string file = dir.filePath(QString("job-%1.taiwa").arg(units)).toStdString();
        if (!writeFileAtomically(file, writeJob(bench::bigJob(units)))) return 1;
        // What `taiwa check` does: read, input processing, decomposition,
        // tool choice and step order, no paths.
        print("check", units, bench::inChild([&] {
            const auto read = readJobFile(file);
            if (!read.job) return false;
            PlanOptions stepsOnly;
            stepsOnly.withToolPaths = false;
            return planned(planJob(*read.job, TechnologyTable::builtIn(), library, stepsOnly));
        }));
    }
    for (const int units : {100, 1'000, 10'000, 100'000}) {
        const std::string file = dir.filePath(QString("job-%1.taiwa").arg(units)).toStdString();
        print("export", units, bench::inChild([&] {
            qputenv("QT_QPA_PLATFORM", "offscreen");
            QGuiApplication app(argc, argv);
            const auto read = readJobFile(file);
            if (!read.job) return false;
            const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), library);
            if (!planned(plan)) return false;
            return exportPlan(plan, dir.filePath(QString("out-%1").arg(units)).toStdString(), "job", {}).ok();
        }));
    }
    // The fine pocket of the CAM comparison (bench/fine-pocket.taiwa): 100 x 60
    // x 20, a 10 mm end mill, step-over 2 %, step-down 0.2 mm.
    const std::string fine = taiwa::bench::dir() + "/fine-pocket.taiwa";
    print("fine", 1, bench::inChild([&] {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        const auto read = readJobFile(fine);
        if (!read.job) return false;
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), library);
        if (!plan.ok()) return false;
        std::size_t moves = 0;
        for (const Step& s : plan.steps) moves += s.path ? s.path->moves.size() : 0;
        std::printf("fine pocket: %zu moves\n", moves);
        std::fflush(stdout);
        return exportPlan(plan, dir.filePath("fine").toStdString(), "fine-pocket", {}).ok();
    }));
    anchor();
    return 0;
}
