// Incremental planning (pipeline/plan_cache.h, sim/stock_cache.h): after
// every edit of a sequence (values, names, cutting data, units added,
// removed and reordered, the stock, the technology data, the tool library,
// undo) the cached plan is the plan from scratch step by step and move by
// move, its tape the same text, and the cached finished part the fresh
// simulation's cell for cell; and an edit of one unit re-plans and re-cuts
// that unit only.
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "pipeline/pipeline.h"
#include "pipeline/plan_cache.h"
#include "post/post.h"
#include "sim/stock_cache.h"
#include "sim/stock_simulation.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace taiwa;

namespace {

Job sample(const char* name)
{
    auto r = readJobFile(test::sourcePath(QString("resources/samples/") + name).toStdString());
    if (!r.job) qFatal("cannot read %s", name);
    return *r.job;
}

const sim::StockGrid kGrid{0.5, 200'000};

// One state of the job and the library, planned both ways and compared.
struct Checker {
    PlanCache cache;
    sim::StockCache stock;

    std::shared_ptr<const Plan> check(const Job& job, const std::vector<Tool>& library, const QString& what)
    {
        const TechnologyTable& table = TechnologyTable::builtIn();
        const Plan fresh = planJob(job, table, library);
        auto cached = std::make_shared<const Plan>(cache.plan(checkedJob(job, table, library), library));
        const Plan& inc = *cached;
        const QByteArray at = what.toUtf8();
        [&] {
            QVERIFY2(inc.diagnostics == fresh.diagnostics, at);
            QVERIFY2(inc.unitOrder == fresh.unitOrder, at);
            QVERIFY2(inc.setups == fresh.setups, at);
            QCOMPARE(inc.turned.size(), fresh.turned.size());
            for (std::size_t i = 0; i < inc.turned.size(); ++i) {
                QVERIFY2(inc.turned[i].unit == fresh.turned[i].unit && inc.turned[i].name == fresh.turned[i].name, at);
                QVERIFY2(inc.turned[i].noseRadiusTool == fresh.turned[i].noseRadiusTool, at);
            }
            QVERIFY2(inc.steps.size() == fresh.steps.size(), at);
            for (std::size_t i = 0; i < inc.steps.size(); ++i) {
                const Step& a = inc.steps[i];
                const Step& b = fresh.steps[i];
                QVERIFY2(a.path.has_value() == b.path.has_value(), at);
                if (a.path) {
                    QVERIFY2(a.path->moves.size() == b.path->moves.size(), at + " step " + QByteArray::number(int(i)));
                    for (std::size_t m = 0; m < a.path->moves.size(); ++m)
                        QVERIFY2(a.path->moves[m] == b.path->moves[m],
                                 at + " step " + QByteArray::number(int(i)) + " move " + QByteArray::number(int(m)));
                }
                QVERIFY2(a == b, at + " step " + QByteArray::number(int(i)));
            }
            QVERIFY2(inc.tools == fresh.tools, at);
            QVERIFY2(inc.totalMinutes == fresh.totalMinutes, at);
            QVERIFY2(inc.totalMachineMinutes == fresh.totalMachineMinutes, at);
            QVERIFY2(inc.toolChanges == fresh.toolChanges, at);
            if (!fresh.ok()) return;
            const PostOptions options = postOptions(fresh, "linuxcnc", std::nullopt, 1000, "job");
            QVERIFY2(postProcess(inc.steps, inc.tools, options).nc == postProcess(fresh.steps, fresh.tools, options).nc, at);
            if (fresh.mmJob.bar) return;
            const auto part = stock.finished(cached, kGrid);
            sim::StockSimulation sim(fresh, kGrid);
            QVERIFY2(*part == *sim.finished(), at + " (finished part)");
        }();
        return cached;
    }
};

// The edits every job takes: each is applied to the job (and library) as
// the last edit left them.
using Edit = std::function<void(Job&, std::vector<Tool>&)>;

void runSequence(const char* file, const std::vector<std::pair<QString, Edit>>& extra)
{
    Job job = sample(file);
    std::vector<Tool> library = defaultToolLibrary();
    const Job original = job;
    Checker c;
    c.check(job, library, QString("%1: first plan").arg(file));
    if (QTest::currentTestFailed()) return;
    std::vector<std::pair<QString, Edit>> edits = extra;
    const std::vector<std::pair<QString, Edit>> common = {
        {"unit 1 renamed", [](Job& j, auto&) { j.units[0].name += " renamed"; }},
        {"unit 1 spindle speed", [](Job& j, auto&) { j.units[0].cutting["roughing"].speed = 4321; }},
        {"unit 1 appended again", [](Job& j, auto&) { j.units.push_back(j.units[0]); }},
        {"units reversed", [](Job& j, auto&) { std::reverse(j.units.begin(), j.units.end()); }},
        {"last unit removed", [](Job& j, auto&) { j.units.pop_back(); }},
        {"first unit removed", [](Job& j, auto&) { if (j.units.size() > 1) j.units.erase(j.units.begin()); }},
        {"stock larger",
         [](Job& j, auto&) {
             j.stock.width += 10;
             j.stock.height += 2;
         }},
        {"technology gamma", [](Job& j, auto&) { j.technology.gamma = 2.0; }},
        {"tool library: first tool's cutting data",
         [](Job&, std::vector<Tool>& lib) {
             for (auto& cd : lib.front().cutting) cd.surfaceSpeed *= 0.9;
         }},
        {"tool library: the second tool gone", [](Job&, std::vector<Tool>& lib) { lib.erase(lib.begin() + 1); }},
        {"back to the original", [&](Job& j, std::vector<Tool>& lib) {
             j = original;
             lib = defaultToolLibrary();
         }},
    };
    edits.insert(edits.end(), common.begin(), common.end());
    for (const auto& [what, edit] : edits) {
        edit(job, library);
        c.check(job, library, QString("%1: %2").arg(file, what));
        if (QTest::currentTestFailed()) return;
    }
}

}  // namespace

class TestPlanCache : public QObject {
    Q_OBJECT
private slots:
    void plateSequence()
    {
        runSequence("plate.taiwa",
                    {{"unit 1 depth", [](Job& j, auto&) { j.units[0].module.as<M4Pocket>().depth += 0.5; }},
                     {"unit 4 depth", [](Job& j, auto&) { j.units[3].module.as<M2DPocket>().depth += 0.5; }},
                     {"unit 1 depth back", [](Job& j, auto&) { j.units[0].module.as<M4Pocket>().depth -= 0.5; }},
                     {"unit 2 out of range (an input error)",
                      [](Job& j, auto&) { j.units[1].module.as<M4Pocket>().depth = -3; }},
                     {"unit 2 repaired", [](Job& j, auto&) { j.units[1].module.as<M4Pocket>().depth = 6; }}});
    }
    void otherModules_data()
    {
        QTest::addColumn<QString>("file");
        // (cp-islands.taiwa would take a minute: its islands plan slowly.)
        for (const char* f : {"face-one-way-angle.taiwa", "holes-grid.taiwa", "probe-flange.taiwa", "bracket-inch.taiwa",
                              "side-open-contour.taiwa", "area-drawn-passes.taiwa",
                              "lathe-bushing.taiwa", "lathe-grooved-shaft.taiwa"})
            QTest::newRow(f) << QString(f);
    }
    void otherModules()
    {
        QFETCH(QString, file);
        runSequence(file.toUtf8().constData(), {});
    }
    // One unit's value typed: that unit planned and cut again, the others reused.
    void oneUnitReplanned()
    {
        Job job = sample("plate.taiwa");
        const auto library = defaultToolLibrary();
        Checker c;
        c.check(job, library, "first plan");
        QCOMPARE(c.cache.lastCounts().unitsPlanned, 6);
        QCOMPARE(c.cache.lastCounts().pathsReused, 0);
        job.units[0].module.as<M4Pocket>().depth += 0.5;
        const auto plan = c.check(job, library, "unit 1 deeper");
        const auto& counts = c.cache.lastCounts();
        QCOMPARE(counts.unitsPlanned, 1);
        QCOMPARE(counts.unitsReused, 5);
        int unit1 = 0;
        for (const Step& s : plan->steps) unit1 += s.unit == 0 && s.path ? 1 : 0;
        QVERIFY(unit1 > 0);
        QCOMPARE(counts.pathsComputed, unit1);
        QCOMPARE(counts.pathsReused, static_cast<int>(plan->steps.size()) - unit1);
        QCOMPARE(c.stock.lastCounts().unitsCut, 1);
        QCOMPARE(c.stock.lastCounts().unitsReused, 5);
        // The same job again: nothing planned, nothing cut.
        c.check(job, library, "unchanged");
        QCOMPARE(c.cache.lastCounts().unitsPlanned, 0);
        QCOMPARE(c.cache.lastCounts().pathsComputed, 0);
        QCOMPARE(c.stock.lastCounts().unitsCut, 0);
    }
};

QTEST_GUILESS_MAIN(TestPlanCache)
#include "test_plan_cache.moc"
