// Station responsiveness (issue 11): the time from a changed value (the depth
// of unit 1, as the form sets it after parsing a keystroke) to
//   StepList: the check messages and the step list updated (on the GUI
//             thread, before the edit returns), and
//   FullPlan: the full plan with tool paths and the stock delivered back to
//             the GUI thread and given to the 3-D view, and (with a display)
//             its first frame rendered: "value typed -> preview updated".
//             Counters: edit (the edit's own call: checks, step list,
//             step table), toView (from there to the plan given to the 3-D
//             view: the worker, then the window's handler), frame (the
//             view's next frame, grabbed) and again (the same frame
//             rendered once more: what a frame costs with nothing new);
//   FullPlanShown: the same to the 3-D view's frame swapped on screen (no
//             grab: what the operator sees; counters toView and shown);
//   FullPlanNc: the same to the NC view's new text, which the window puts
//             off until after the 3-D view (and on a large job until the
//             typing pauses);
//   SameFrame: the anchor, the view's frame rendered again and again;
//   (FullPlan, FullPlanShown and FullPlanNc: each edit after the last
//   one's work is flushed and 100 ms of the event loop, as keystrokes
//   come, untimed: settle());
//   Parts:    FullPlan's parts, each timed here by calling the same functions
//             the runner and the window call, one after the other (counters
//             in ms; the product has no timers).
// on two jobs: resources/samples/plate.taiwa (the largest sample; or the job
// file TAIWA_BENCH_JOB names) and a 200-unit job (bench_job.h's bigJob(200)).
// Offscreen unless a display is set; under `xvfb-run -a` the preview exists,
// its setPlan is inside FullPlan and Parts times it, its first render and
// the same frame again (sameFrame).
// Run from the source tree's root.
#include "bench_job.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "pipeline/pipeline.h"
#include "pipeline/plan_cache.h"
#include "post/post.h"
#include "sim/stock_cache.h"
#include "sim/stock_simulation.h"
#include "ui/job_document.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/verification_panel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QPlainTextEdit>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

double depth = 10.0;

Job changedDepth(StationWindow* window)
{
    Job j = window->document()->job();
    depth = depth == 10.0 ? 10.5 : 10.0;
    (j.units[0].module).as<M4Pocket>().depth = depth;
    return j;
}

void changeDepth(StationWindow* window) { window->document()->edit(changedDepth(window), "bench", "bench"); }

void StepList(benchmark::State& state, StationWindow* window)
{
    for (auto _ : state) {
        changeDepth(window);
        benchmark::DoNotOptimize(window->stepTable()->rowCount());
        state.PauseTiming();
        window->planRunner()->flush();  // no worker left running into the next edit
        QCoreApplication::processEvents();
        state.ResumeTiming();
    }
    state.counters["steps"] = window->stepTable()->rowCount();
}

// After an edit's iteration, timing paused: the runner flushed (the NC
// text and the step list's times shown) and then 100 ms of the event loop,
// as between keystrokes, so that what the last edit left to the
// background (its NC document freed, a frame requested) is not timed in
// the next one.
void settle(StationWindow* window)
{
    window->planRunner()->flush();
    QEventLoop pause;
    QTimer::singleShot(100, &pause, &QEventLoop::quit);
    pause.exec();
}

double moves(const Plan& plan)
{
    double n = 0;
    for (const Step& s : plan.steps)
        if (s.path) n += static_cast<double>(s.path->moves.size());
    return n;
}

void FullPlan(benchmark::State& state, StationWindow* window)
{
    using Clock = std::chrono::steady_clock;
    double edit = 0, toProgram = 0, toFrame = 0, again = 0;
    for (auto _ : state) {
        QEventLoop loop;
        auto t0 = Clock::now();
        Clock::time_point ready;
        // After the window's own handler (connected first): the plan is in the 3-D view.
        auto c = QObject::connect(window->planRunner(), &PlanRunner::programReady, &loop, [&] {
            ready = Clock::now();
            loop.quit();
        });
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        changeDepth(window);
        const auto edited = Clock::now();
        loop.exec();
        QObject::disconnect(c);
        // The window has given the plan to the 3-D view: its frame.
        if (PreviewWidget* p = window->preview()) benchmark::DoNotOptimize(p->grabImage());
        const auto framed = Clock::now();
        state.PauseTiming();
        if (PreviewWidget* p = window->preview()) benchmark::DoNotOptimize(p->grabImage());  // not in the time
        const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
        again += ms(framed, Clock::now());
        edit += ms(t0, edited);
        toProgram += ms(edited, ready);
        toFrame += ms(ready, framed);
        settle(window);
        state.ResumeTiming();
    }
    state.counters["moves"] = moves(*window->planRunner()->fullPlan());
    // The parts of the time in ms: the edit's own call (checks, step list),
    // from there to the plan given to the 3-D view, and its frame.
    const double n = static_cast<double>(state.iterations());
    state.counters["edit"] = edit / n;
    state.counters["toView"] = toProgram / n;
    state.counters["frame"] = toFrame / n;
    state.counters["again"] = again / n;
}

// The same to the 3-D view's frame on screen (its GL window swapped; with a
// display only): what the operator sees, no grab. Its time is from the
// edit's call to that frame (manual time: what the window does after the
// frame in the same pass of the event loop is not in it). Counters: edit
// (the edit's own call), toView as in FullPlan, shown (from there to the
// frame swapped).
void FullPlanShown(benchmark::State& state, StationWindow* window)
{
    PreviewWidget* p = window->preview();
    if (!p) {
        state.SkipWithError("no 3-D view (no display)");
        return;
    }
    using Clock = std::chrono::steady_clock;
    double edit = 0, toProgram = 0, toShown = 0;
    for (auto _ : state) {
        QEventLoop loop;
        Clock::time_point edited, ready, shown;
        bool delivered = false;
        auto c1 = QObject::connect(window->planRunner(), &PlanRunner::programReady, &loop, [&] {
            ready = Clock::now();
            delivered = true;
        });
        bool framed = false;
        auto c2 = QObject::connect(p, &PreviewWidget::frameShown, &loop, [&] {
            if (!delivered || framed) return;  // a frame of the plan before, or one after the first
            framed = true;
            shown = Clock::now();
            loop.quit();
        });
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        const auto t0 = Clock::now();
        changeDepth(window);
        edited = Clock::now();
        loop.exec();
        QObject::disconnect(c1);
        QObject::disconnect(c2);
        const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
        state.SetIterationTime(ms(t0, shown) / 1000.0);
        edit += ms(t0, edited);
        toProgram += ms(edited, ready);
        toShown += ms(ready, shown);
        settle(window);
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["edit"] = edit / n;
    state.counters["toView"] = toProgram / n;
    state.counters["shown"] = toShown / n;
}

// The same to the NC view's new text (put off after the 3-D view's frame).
void FullPlanNc(benchmark::State& state, StationWindow* window)
{
    for (auto _ : state) {
        QEventLoop loop;
        auto c = QObject::connect(window->ncView()->text(), &QPlainTextEdit::textChanged, &loop, &QEventLoop::quit);
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        changeDepth(window);
        loop.exec();
        QObject::disconnect(c);
        state.PauseTiming();
        settle(window);
        state.ResumeTiming();
    }
}

// FullPlan's parts, one after the other on the GUI thread, with the runner's
// own cache (pipeline/plan_cache.h) where it plans; each counter is the mean
// of its part in ms.
void Parts(benchmark::State& state, StationWindow* window)
{
    using Clock = std::chrono::steady_clock;
    std::map<std::string, double> total;
    const auto lap = [&](const char* name, Clock::time_point& t) {
        const auto now = Clock::now();
        total[name] += std::chrono::duration<double, std::milli>(now - t).count();
        t = now;
    };
    PlanRunner* runner = window->planRunner();
    const std::vector<Tool>& library = runner->library();
    PlanCache cache;  // as the runner has them: the job before the edit planned and simulated
    sim::StockCache stockCache;
    stockCache.finished(std::make_shared<const Plan>(
                            cache.plan(checkedJob(window->document()->job(), TechnologyTable::builtIn(), library), library)),
                        runner->stockGrid());
    for (auto _ : state) {
        const Job job = changedDepth(window);
        auto t = Clock::now();
        {  // the start of the full plan: a call queued at once (no timer)
            QEventLoop loop;
            QMetaObject::invokeMethod(&loop, &QEventLoop::quit, Qt::QueuedConnection);
            loop.exec();
        }
        lap("queuedStart", t);
        const CheckedJob checked = checkedJob(job, TechnologyTable::builtIn(), library);
        lap("checks", t);
        PlanOptions fast;
        fast.withToolPaths = false;
        const auto stepList = std::make_shared<const Plan>(planJob(checked, library, fast));
        lap("stepList", t);
        {
            Job one = job;
            one.units.resize(1);
            benchmark::DoNotOptimize(planJob(one, TechnologyTable::builtIn(), library));
        }
        lap("planUnit1", t);
        const auto fresh = std::make_shared<const Plan>(planJob(checked, library));
        lap("planAll", t);
        const auto plan = std::make_shared<const Plan>(cache.plan(checked, library));
        lap("planCached", t);
        PostedProgram prog = postProcess(plan->steps, plan->tools, postOptions(*plan, "linuxcnc"));
        lap("post", t);
        const QString nc = QString::fromStdString(prog.nc);
        window->ncView()->setProgram(nc, prog.lines);
        lap("ncView", t);
        auto stock = std::make_shared<sim::StockSimulation>(*fresh, runner->stockGrid());
        stock->finished();
        lap("stockFresh", t);
        auto stockCached = stockCache.simulation(plan, runner->stockGrid());
        lap("stockCached", t);
        window->stepPanel()->setPlan(plan);
        lap("stepPanel", t);
        window->verificationPanel()->setPlan(plan);
        lap("verifyPanel", t);
        if (PreviewWidget* p = window->preview()) {
            p->setPlan(plan, stockCached);
            lap("previewSetPlan", t);
            benchmark::DoNotOptimize(p->grabImage());
            lap("firstRender", t);
            // The anchor: the same frame again, nothing changed.
            benchmark::DoNotOptimize(p->grabImage());
            lap("sameFrame", t);
        }
        QCoreApplication::processEvents();
        t = Clock::now();
    }
    for (const auto& [name, ms] : total) state.counters[name] = ms / static_cast<double>(state.iterations());
}

// The anchor of FullPlan's frame: the 3-D view's frame rendered again,
// nothing changed (with a display only).
void SameFrame(benchmark::State& state, StationWindow* window)
{
    PreviewWidget* p = window->preview();
    if (!p) {
        state.SkipWithError("no 3-D view (no display)");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(p->grabImage());
    state.counters["width"] = p->width();
    state.counters["height"] = p->height();
}

// The 200-unit job as a file the window opens.
QString writeBigJob(const QTemporaryDir& dir)
{
    const QString path = dir.filePath("units200.taiwa");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(QByteArray::fromStdString(writeJob(bench::bigJob(200))));
    return path;
}

}  // namespace

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
    benchmark::Initialize(&argc, argv);
    const std::pair<const char*, QString> jobs[] = {
        {"plate", qEnvironmentVariable("TAIWA_BENCH_JOB", "resources/samples/plate.taiwa")},
        {"units200", writeBigJob(dir)},
    };
    std::vector<std::unique_ptr<StationWindow>> windows;
    for (const auto& [name, path] : jobs) {
        auto w = std::make_unique<StationWindow>(path);
        if (w->document()->job().units.empty()) {
            qCritical("bench_gui_update: cannot open %s (run from the source root or set TAIWA_BENCH_JOB)",
                      qPrintable(path));
            return 1;
        }
        w->show();
        w->planRunner()->flush();
        QCoreApplication::processEvents();
        StationWindow* window = w.get();
        windows.push_back(std::move(w));
        const std::string n = name;
        benchmark::RegisterBenchmark(("StepList/" + n).c_str(), StepList, window)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("FullPlan/" + n).c_str(), FullPlan, window)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("FullPlanShown/" + n).c_str(), FullPlanShown, window)
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
        benchmark::RegisterBenchmark(("FullPlanNc/" + n).c_str(), FullPlanNc, window)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("SameFrame/" + n).c_str(), SameFrame, window)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("Parts/" + n).c_str(), Parts, window)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->Iterations(n == "plate" ? 10 : 3);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
