// Station responsiveness on the largest sample job (resources/samples/
// plate.taiwa): the time from a changed value (the depth of unit 1, as the
// form sets it after parsing a keystroke) to
//   StepList: the check messages and the step list updated (on the GUI
//             thread, before the edit returns), and
//   FullPlan: the full plan with tool paths and the NC program delivered back
//             to the GUI thread (what the 3-D preview's setPlan and the NC
//             view get), debounce included.
// Offscreen unless a display is set; under `xvfb-run -a` the preview exists
// and its setPlan is inside FullPlan. Run from the source tree's root, or
// set TAIWA_BENCH_JOB to the job file.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "ui/job_document.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_table.h"

#include <QApplication>
#include <QEventLoop>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <benchmark/benchmark.h>

#include <memory>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

StationWindow* window = nullptr;
double depth = 10.0;

void changeDepth()
{
    Job j = window->document()->job();
    depth = depth == 10.0 ? 10.5 : 10.0;
    (j.units[0].module).as<M4Pocket>().depth = depth;
    window->document()->edit(j, "bench", "bench");
}

void StepList(benchmark::State& state)
{
    for (auto _ : state) {
        changeDepth();
        benchmark::DoNotOptimize(window->stepTable()->rowCount());
        state.PauseTiming();
        window->planRunner()->flush();  // no worker left running into the next edit
        QCoreApplication::processEvents();
        state.ResumeTiming();
    }
    state.counters["steps"] = window->stepTable()->rowCount();
}

void FullPlan(benchmark::State& state)
{
    for (auto _ : state) {
        QEventLoop loop;
        auto c = QObject::connect(window->planRunner(), &PlanRunner::programReady, &loop, &QEventLoop::quit);
        QTimer::singleShot(10000, &loop, &QEventLoop::quit);
        changeDepth();
        loop.exec();
        QObject::disconnect(c);
    }
    state.counters["moves"] = [] {
        double n = 0;
        for (const Step& s : window->planRunner()->fullPlan()->steps)
            if (s.path) n += static_cast<double>(s.path->moves.size());
        return n;
    }();
}

}  // namespace

BENCHMARK(StepList)->Unit(benchmark::kMillisecond);
BENCHMARK(FullPlan)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QTemporaryDir dir;
    qputenv("TAIWA_AUTOSAVE_DIR", dir.filePath("autosave").toUtf8());
    qputenv("TAIWA_TOOL_DB", dir.filePath("tools.sqlite").toUtf8());
    qputenv("TAIWA_NO_PROMPTS", "1");
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QString job = qEnvironmentVariable("TAIWA_BENCH_JOB", "resources/samples/plate.taiwa");
    auto w = std::make_unique<StationWindow>(job);
    if (w->document()->job().units.empty()) {
        qCritical("bench_gui_update: cannot open %s (run from the source root or set TAIWA_BENCH_JOB)",
                  qPrintable(job));
        return 1;
    }
    w->show();
    window = w.get();
    window->planRunner()->flush();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
