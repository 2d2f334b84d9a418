// What `taiwa render JOB --step all` costs as the job grows: 1,000 and 3,000
// units of the shared benchmark job (bench_job.h), each in a child process
// of its own: the plan with its paths, then the scene and the 800 x 600 iso
// picture (merged above 400 steps: two actors per block of units). Prints the
// two parts, the whole and the peak memory. Needs an X display: run it
// under `xvfb-run -a`.
#include "bench_child.h"
#include "bench_job.h"

#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "viz/render.h"

#include <QTemporaryDir>

#include <chrono>
#include <cstdio>

using namespace taiwa;

int main()
{
    const std::vector<Tool> library = defaultToolLibrary();
    QTemporaryDir dir;
    for (const int units : {1'000, 3'000}) {
        const Job job = bench::bigJob(units);
        const std::string png = dir.filePath(QString("render-%1.png").arg(units)).toStdString();
        const bench::Measured m = bench::inChild([&] {
            const auto start = std::chrono::steady_clock::now();
            const Plan plan = planJob(job, TechnologyTable::builtIn(), library);
            if (!plan.ok()) return false;
            const auto planned = std::chrono::steady_clock::now();
            const auto drawn = viz::renderToPng(plan, viz::RenderOptions{}, png);
            if (!drawn) {
                std::fprintf(stderr, "render: %s\n", drawn.error().c_str());
                return false;
            }
            const auto done = std::chrono::steady_clock::now();
            std::size_t moves = 0;
            for (const Step& s : plan.steps) moves += s.path ? s.path->moves.size() : 0;
            std::printf("render %5d units  %6zu steps  %7zu moves  plan %6.3f s  scene + picture %6.3f s", units,
                        plan.steps.size(), moves, std::chrono::duration<double>(planned - start).count(),
                        std::chrono::duration<double>(done - planned).count());
            std::fflush(stdout);
            return true;
        });
        std::printf("  whole %6.3f s  peak %7.1f MB  %s\n", m.seconds, m.peakKb / 1024.0, m.ok ? "ok" : "FAILED");
        std::fflush(stdout);
    }
    return 0;
}
