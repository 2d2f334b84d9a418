// Runs the pipeline for the window. On every change the job is converted and
// checked once (checkedJob) on the GUI thread, and the fast step list planned
// from that checked job (planJob without tool paths; a few milliseconds);
// the full plan with tool paths and the NC program follow on a worker thread
// from the same checked job, started at once when the worker is free (it
// plans while the GUI thread shows the step list), newest edit wins: results
// of an edit that has been superseded are dropped, and edits made while the
// worker plans wait for it and only the newest is planned next. There is no
// fixed delay to scale with the job's size; a burst of edits in one
// event-loop turn plans the first and the last. A change of
// dialect or program name only re-posts the last plan. For a 3-D preview the
// worker also simulates the stock of the finished part. The worker keeps
// what it planned and simulated per unit (PlanCache, StockCache): an edit of
// one unit re-plans and re-cuts that unit only. A tool library on the
// shop server (docs/shop-server.md) is watched: another station's change
// re-reads it and says so (toolsChangedOnServer), and the server away
// leaves the station on its copy, read-only (libraryStatus).
#pragma once

#include "job/job_check.h"
#include "model/diagnostic.h"
#include "model/job.h"
#include "model/tool.h"
#include "pipeline/pipeline.h"
#include "pipeline/plan_cache.h"
#include "post/post.h"
#include "sim/stock_cache.h"
#include "sim/stock_simulation.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

class QSocketNotifier;
namespace taiwa {
class PgToolStore;
}

#include <memory>
#include <vector>

namespace taiwa::ui {

class PlanRunner : public QObject {
    Q_OBJECT
public:
    explicit PlanRunner(QObject* parent = nullptr);
    ~PlanRunner() override;

    const std::vector<Tool>& library() const { return library_; }
    // Empty, or why the shop's tool library could not be opened (the
    // built-in default library is used instead).
    const QString& libraryError() const { return libraryError_; }
    // Re-reads the shop's tool library (after the tool library dialog).
    void reloadLibrary();
    // Empty, or the tools' state while the shop server is away: "tools as
    // of … (read only: … cannot be reached)".
    const QString& libraryStatus() const { return libraryStatus_; }
    // Where the library came from, for the sheet (ToolStore::origin):
    // empty for the station's own file.
    std::string toolsOrigin() const;

    // Checks the job now; plans the step list now when there are no errors
    // and schedules the full plan.
    void update(const Job& job)
    {
        start(job);
        announce();
    }
    // update() in two: start() checks the job and starts the worker on it
    // at once, announce() then emits what the check found (checked) and the
    // step list (stepsPlanned). The window starts the worker first and
    // refreshes its forms meanwhile (they would otherwise hold it up 2-3 ms
    // on each edit), then announces.
    void start(const Job& job);
    void announce();
    // The controller dialect of the NC program; re-posts the last plan.
    void setDialect(const QString& dialect);
    const QString& dialect() const { return dialect_; }
    // The job file's stem, the program name of an unnamed job (as export
    // names it); re-posts the last plan.
    void setFileStem(const QString& stem);
    // The last full plan (nullptr until one ran without errors).
    std::shared_ptr<const Plan> fullPlan() const { return full_; }
    // Runs a pending full plan at once, on the calling thread (export,
    // tests), then emits flushed().
    void flush();
    bool isBusy() const { return inFlight_ >= 0 || pendingFull_; }
    // What the last full plan reused (pipeline/plan_cache.h, sim/stock_cache.h);
    // read it only while !isBusy().
    const PlanCache::Counts& planCounts() const { return planCache_->lastCounts(); }
    const sim::StockCache::Counts& stockCounts() const { return stockCache_->lastCounts(); }

    // Whether the worker also simulates the stock of the finished part (for
    // a 3-D preview; off by default).
    void setSimulateStock(bool on) { simulateStock_ = on; }
    // The grid the stock is simulated on (View > Stock grid); the last plan
    // is simulated again on it.
    void setStockGrid(sim::StockGrid grid);
    sim::StockGrid stockGrid() const { return stockGrid_; }
    // The stock simulation of fullPlan(), the finished part already
    // simulated on the worker thread (nullptr when not asked for); the GUI
    // thread owns it from here.
    std::shared_ptr<sim::StockSimulation> stockSimulation() const { return stock_; }

    struct Result {
        std::shared_ptr<const Plan> plan;
        std::shared_ptr<sim::StockSimulation> stock;
        QString nc;  // the tape, or why there is none
        std::vector<BlockSource> lines;
    };

signals:
    // The shop server announced another station's change of tools (or went
    // away); the library has been re-read. `message` names the tools, who
    // and which station, for the status bar; the window re-plans.
    void toolsChangedOnServer(const QString& message);
    void checked(const taiwa::Diagnostics& diagnostics);
    void stepsPlanned(std::shared_ptr<const taiwa::Plan> plan);
    // plan nullptr: no program; nc says why.
    void programReady(std::shared_ptr<const taiwa::Plan> plan, const QString& nc,
                      const std::vector<taiwa::BlockSource>& lines);
    // flush() is done: whatever a view put off (the window's NC text) is
    // wanted now.
    void flushed();

private:
    // What the worker does next: plan and post a checked job, or re-post the
    // last plan only.
    struct Work {
        std::shared_ptr<const CheckedJob> job;  // null: re-post `plan`
        std::shared_ptr<const Plan> plan;
    };
    // Plans `work` next: `now` (an edit) starts the worker at once when it is
    // free, else a queued call starts it.
    void schedule(Work work, bool now = false);
    void queueStart();
    void repost();
    void startFull();
    void finished(int generation, const Result& r);
    void publish(const Result& r);
    // Everything the worker reads, copied when it starts: the GUI thread may
    // change the runner's own values meanwhile.
    struct Settings {
        std::vector<Tool> library;
        std::string dialect;
        std::string fileStem;
        bool simulateStock = false;
        sim::StockGrid stockGrid;
        // The worker's caches: one plan runs at a time (on the worker, or
        // in flush() after the worker is done).
        PlanCache* planCache = nullptr;
        sim::StockCache* stockCache = nullptr;
    };
    Settings settings() const;
    static Result run(const Work& w, const Settings& s);

    std::vector<Tool> library_;
    QString libraryError_;
    // The shop server's store, when the setting names one, and the watch
    // on its connection for NOTIFY.
    std::unique_ptr<PgToolStore> server_;
    QSocketNotifier* serverWatch_ = nullptr;
    QString libraryStatus_;
    void watchServer();
    void serverSpoke();
    QString dialect_ = QStringLiteral("linuxcnc");
    bool simulateStock_ = false;
    sim::StockGrid stockGrid_;
    QString fileStem_;
    Work pending_;
    Work running_;  // what the worker was last started on
    bool pendingFull_ = false;
    int generation_ = 0;
    int inFlight_ = -1;  // generation being planned on the worker, -1: none
    bool startQueued_ = false;  // a call of startFull is queued
    QThreadPool pool_;
    std::shared_ptr<const CheckedJob> started_;  // by start(), for announce()
    std::shared_ptr<const Plan> full_;
    std::shared_ptr<sim::StockSimulation> stock_;
    std::unique_ptr<PlanCache> planCache_ = std::make_unique<PlanCache>();
    std::unique_ptr<sim::StockCache> stockCache_ = std::make_unique<sim::StockCache>();
};

}  // namespace taiwa::ui
