// Checks and plans for the window, the full plan on a worker thread.
#include "ui/plan_runner.h"
#include "ui/core_messages.h"
#include "model/translate_noop.h"

#include "job/job_check.h"
#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"

#include <QCoreApplication>
#include <QSocketNotifier>
#include <QStringList>

#include <exception>
#include <future>

namespace taiwa::ui {
namespace {

// Posts a plan and, for a 3-D preview, simulates its finished part; runs on
// the worker thread, so it touches nothing but its arguments. The two only
// read the plan: the stock is simulated on a thread of its own meanwhile
// (after an edit it re-cuts one unit on one core; on 200 units the post
// took 7-12 ms and the re-cut 5-10 ms one after the other, before the view
// got the plan).
PlanRunner::Result postAndSimulate(std::shared_ptr<const Plan> plan, const PostOptions& options,
                                   sim::StockCache* stock, sim::StockGrid grid)
{
    PlanRunner::Result r;
    std::future<std::shared_ptr<sim::StockSimulation>> simulated;
    if (stock)  // the part as the preview first shows it
        simulated = std::async(std::launch::async, [stock, plan, grid] { return stock->simulation(plan, grid); });
    PostedProgram prog = postProcess(plan->steps, plan->tools, options);
    r.nc = QString::fromStdString(prog.nc);
    r.lines = std::move(prog.lines);
    if (simulated.valid()) r.stock = simulated.get();  // rethrows what the simulation threw
    r.plan = std::move(plan);
    return r;
}

}  // namespace

PlanRunner::Settings PlanRunner::settings() const
{
    return {library_, dialect_.toStdString(), fileStem_.toStdString(), simulateStock_, stockGrid_, planCache_.get(),
            stockCache_.get()};
}

PlanRunner::Result PlanRunner::run(const Work& w, const Settings& s)
{
    try {
        std::shared_ptr<const Plan> plan = w.plan;
        if (w.job) plan = std::make_shared<const Plan>(planJob(*w.job, s.library, {}, s.planCache));
        if (!plan->ok()) {
            Result r;
            r.nc = QObject::tr("(no program: the job has input errors)");
            return r;
        }
        return postAndSimulate(plan, postOptions(*plan, s.dialect, std::nullopt, 1000, s.fileStem),
                               s.simulateStock ? s.stockCache : nullptr, s.stockGrid);
    } catch (const std::exception& e) {
        Result r;
        r.nc = QObject::tr("(no program: %1)").arg(QString::fromUtf8(e.what()));
        return r;
    }
}

PlanRunner::PlanRunner(QObject* parent) : QObject(parent)
{
    pool_.setMaxThreadCount(1);
    reloadLibrary();
}

PlanRunner::~PlanRunner() { pool_.waitForDone(); }

void PlanRunner::reloadLibrary()
{
    const std::string setting = defaultToolLibraryPath();
    libraryStatus_.clear();
    taiwa::Result<std::vector<Tool>> read = Failure{""};
    if (!isServerSetting(setting)) {
        read = readToolLibrary(setting);
    } else {
        if (!server_) {
            auto opened = PgToolStore::open(setting, {defaultServerCopyPath(), {}, 3});
            if (opened) server_ = std::move(*opened);
            else read = Failure{opened.error()};
        } else if (server_->readOnly()) {
            (void)server_->reconnect();  // back, perhaps
        }
        if (server_) {
            read = server_->tools();
            if (server_->readOnly()) libraryStatus_ = coreMessage(server_->status());
            watchServer();
        }
    }
    std::vector<Tool> tools = read ? std::move(*read) : std::vector<Tool>{};
    libraryError_.clear();
    if (tools.empty()) {
        libraryError_ = QString::fromStdString(read ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the library has no tools") : read.error());
        tools = defaultToolLibrary();
    }
    library_ = std::move(tools);
}

std::string PlanRunner::toolsOrigin() const { return server_ ? server_->origin() : std::string(); }

// LISTEN on the server's connection, watched by the event loop; none while
// the station reads its copy.
void PlanRunner::watchServer()
{
    const int socket = server_ ? server_->socket() : -1;
    if (serverWatch_ && static_cast<int>(serverWatch_->socket()) == socket) return;
    delete serverWatch_;
    serverWatch_ = nullptr;
    if (socket < 0 || !server_->listen()) return;
    serverWatch_ = new QSocketNotifier(socket, QSocketNotifier::Read, this);
    connect(serverWatch_, &QSocketNotifier::activated, this, &PlanRunner::serverSpoke);
}

void PlanRunner::serverSpoke()
{
    // A change committed while the library is being read comes back with the
    // read's own answer: libpq keeps it in its queue and the socket has
    // nothing more to say, so it would wait for the next notification. The
    // queue is taken again after each read and the library read again for
    // what it held (a few times at most; a later notification does the rest).
    constexpr int kReads = 4;
    std::vector<ToolChange> changes;
    for (int read = 0; read < kReads; ++read) {
        const auto more = server_->changes(0);
        if (server_->readOnly()) {  // the connection went: the copy, read-only
            delete serverWatch_;
            serverWatch_ = nullptr;
            reloadLibrary();
            emit toolsChangedOnServer(coreMessage(server_->status()));
            return;
        }
        if (more.empty()) break;
        changes.insert(changes.end(), more.begin(), more.end());
        reloadLibrary();
    }
    if (changes.empty()) return;
    QStringList tools;
    for (const auto& c : changes)
        if (!tools.contains(QStringLiteral("T%1").arg(c.id))) tools << QStringLiteral("T%1").arg(c.id);
    emit toolsChangedOnServer(tr("%1 changed by %2 at station %3; the plan is run again")
                                  .arg(tools.join(QStringLiteral(", ")), QString::fromStdString(changes.back().who),
                                       QString::fromStdString(changes.back().station)));
}

void PlanRunner::start(const Job& job)
{
    ++generation_;
    started_ = std::make_shared<const CheckedJob>(checkedJob(job, TechnologyTable::builtIn(), library_));
    if (!started_->ok()) {
        pendingFull_ = false;
        return;
    }
    // The worker first: it plans while the window shows the edit.
    schedule({started_, nullptr}, true);
}

void PlanRunner::announce()
{
    if (!started_) return;
    const std::shared_ptr<const CheckedJob> checkedOnce = std::move(started_);
    emit checked(checkedOnce->diagnostics);
    if (!checkedOnce->ok()) {
        emit stepsPlanned(nullptr);
        emit programReady(nullptr, tr("(no program: the job has input errors)"), {});
        return;
    }
    std::shared_ptr<const Plan> steps;
    try {
        PlanOptions fastOptions;
        fastOptions.withToolPaths = false;
        steps = std::make_shared<const Plan>(planJob(*checkedOnce, library_, fastOptions));
    } catch (const std::exception& e) {
        emit checked({Diagnostic{Severity::Error, std::nullopt, "", "", std::string("planning failed: ") + e.what()}});
        return;
    }
    emit stepsPlanned(std::move(steps));
}

void PlanRunner::schedule(Work work, bool now)
{
    pending_ = std::move(work);
    pendingFull_ = true;
    if (now && inFlight_ < 0 && !startQueued_) startFull();
    else queueStart();
}

void PlanRunner::queueStart()
{
    if (startQueued_) return;
    startQueued_ = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            startQueued_ = false;
            startFull();
        },
        Qt::QueuedConnection);
}

void PlanRunner::repost()
{
    if (!full_ && inFlight_ < 0) return;  // a pending edit's start reads the new settings
    ++generation_;
    // The tool paths depend on neither the dialect nor the program name: only
    // the post runs again (unless an edit is pending, whose plan comes anyway,
    // or one is being planned with the settings before: it is planned again,
    // its units and paths from the cache, and its result dropped).
    const auto job = pendingFull_ ? pending_.job : inFlight_ >= 0 ? running_.job : nullptr;
    schedule({job, job ? nullptr : full_});
}

void PlanRunner::setDialect(const QString& dialect)
{
    if (dialect == dialect_) return;
    dialect_ = dialect;
    repost();
}

void PlanRunner::setStockGrid(sim::StockGrid grid)
{
    if (grid == stockGrid_) return;
    stockGrid_ = grid;
    repost();
}

void PlanRunner::setFileStem(const QString& stem)
{
    if (stem == fileStem_) return;
    fileStem_ = stem;
    repost();
}

void PlanRunner::startFull()
{
    if (!pendingFull_) return;
    if (inFlight_ >= 0) return;  // finished() starts the newest edit when the worker is free
    pendingFull_ = false;
    const int generation = generation_;
    inFlight_ = generation;
    running_ = pending_;
    pool_.start([this, generation, work = pending_, settings = settings()] {
        const Result r = run(work, settings);
        QMetaObject::invokeMethod(this, [this, generation, r] { finished(generation, r); }, Qt::QueuedConnection);
    });
}

void PlanRunner::finished(int generation, const Result& r)
{
    if (generation == inFlight_) inFlight_ = -1;
    if (generation == generation_) publish(r);
    if (pendingFull_ && !startQueued_) startFull();
}

void PlanRunner::publish(const Result& r)
{
    if (r.plan) {
        full_ = r.plan;
        stock_ = r.stock;
    }
    emit programReady(r.plan, r.nc, r.lines);
}

void PlanRunner::flush()
{
    pool_.waitForDone();
    if (!pendingFull_) {
        if (inFlight_ >= 0) {  // its result is queued: deliver it now
            QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
        }
    } else {
        pendingFull_ = false;  // a queued start finds nothing to do
        inFlight_ = -1;        // the worker is done; its result, still queued, is older than this one
        ++generation_;         // anything still queued is older than this
        publish(run(pending_, settings()));
    }
    emit flushed();
}

}  // namespace taiwa::ui
