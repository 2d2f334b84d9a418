// The station's plan runner on its asynchronous path, without flush(): an
// edit made while the worker plans an older one drops the older result and
// starts the worker again on the newest edit; a burst of edits in one
// event-loop turn is published once (the first starts the idle worker at
// once, only the newest of the rest is planned after it); a dialect change
// re-posts the last plan; start() sets the worker going before announce()
// says what the check found.
#include "job/job_file.h"
#include "modules/m4/m4.h"
#include "support/support.h"
#include "ui/plan_runner.h"

#include <QSignalSpy>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

Job plateWithDepth(double depth)
{
    Job j = *readJobFile(test::sourcePath("resources/samples/plate.taiwa").toStdString()).job;
    j.units[0].module.as<M4Pocket>().depth = depth;
    return j;
}

double firstDepth(const Plan& p) { return p.job.units[0].module.as<M4Pocket>().depth; }

// The plans the runner published, in order.
std::vector<std::shared_ptr<const Plan>> published(const QSignalSpy& spy)
{
    std::vector<std::shared_ptr<const Plan>> out;
    for (const auto& args : spy)
        if (auto p = args.at(0).value<std::shared_ptr<const Plan>>()) out.push_back(p);
    return out;
}

}  // namespace

class TestGuiPlanRunner : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        qRegisterMetaType<std::shared_ptr<const Plan>>();
        qRegisterMetaType<std::vector<BlockSource>>();
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void anEditWhilePlanningDropsTheOlderResult()
    {
        PlanRunner runner;
        QSignalSpy programs(&runner, &PlanRunner::programReady);
        runner.update(plateWithDepth(10));
        QCoreApplication::processEvents();  // the worker started on depth 10 at the edit
        QVERIFY(runner.isBusy());
        runner.update(plateWithDepth(11));  // while it plans
        runner.update(plateWithDepth(12));  // and another, in the same turn
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy(), 20000);
        const auto plans = published(programs);
        // Depth 10's result came back superseded and was dropped; the worker was
        // started again on the newest edit only (11 was never planned).
        QCOMPARE(plans.size(), std::size_t{1});
        QCOMPARE(firstDepth(*plans.front()), 12.0);
        QCOMPARE(runner.fullPlan(), plans.front());
    }

    void aBurstOfEditsIsPlannedOnce()
    {
        PlanRunner runner;
        QSignalSpy programs(&runner, &PlanRunner::programReady);
        QSignalSpy steps(&runner, &PlanRunner::stepsPlanned);
        for (int i = 0; i < 5; ++i) runner.update(plateWithDepth(8 + i));
        QCOMPARE(steps.size(), 5);  // the step list follows every edit at once
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy(), 20000);
        const auto plans = published(programs);
        QCOMPARE(plans.size(), std::size_t{1});
        QCOMPARE(firstDepth(*plans.front()), 12.0);
    }

    // start() sets the worker going before anything is announced (the
    // window refreshes its forms meanwhile); announce() then emits the
    // check and the step list of that job once; a job with errors starts
    // nothing and is announced as no program.
    void startThenAnnounce()
    {
        PlanRunner runner;
        QSignalSpy checked(&runner, &PlanRunner::checked);
        QSignalSpy steps(&runner, &PlanRunner::stepsPlanned);
        QSignalSpy programs(&runner, &PlanRunner::programReady);
        runner.start(plateWithDepth(10));
        QVERIFY(runner.isBusy());
        QCOMPARE(checked.size(), 0);
        QCOMPARE(steps.size(), 0);
        runner.announce();
        QCOMPARE(checked.size(), 1);
        QCOMPARE(steps.size(), 1);
        QVERIFY(steps.at(0).at(0).value<std::shared_ptr<const Plan>>());
        runner.announce();  // nothing more to say
        QCOMPARE(steps.size(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy(), 20000);
        QCOMPARE(published(programs).size(), std::size_t{1});

        Job bad = plateWithDepth(10);
        bad.stock.width = -1;
        runner.start(bad);
        QVERIFY(!runner.isBusy());
        runner.announce();
        QCOMPARE(steps.size(), 2);
        QVERIFY(!steps.at(1).at(0).value<std::shared_ptr<const Plan>>());
        QCOMPARE(programs.size(), 2);
        QVERIFY(!programs.at(1).at(0).value<std::shared_ptr<const Plan>>());
    }

    // The stock grid chosen in the View menu: the last plan simulated again
    // on it (plate.taiwa's 200 x 150 stock: 0.25 mm standard, 0.1 mm fine,
    // 0.5 mm coarse, each within its cell budget).
    void aStockGridChangeSimulatesAgain()
    {
        PlanRunner runner;
        runner.setSimulateStock(true);
        runner.update(plateWithDepth(10));
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy() && runner.stockSimulation(), 20000);
        QCOMPARE(runner.stockSimulation()->initial()->cellSize(), 0.25);
        for (const auto& [grid, cell] : {std::pair{sim::kStockGrids[0], 0.1}, std::pair{sim::kStockGrids[2], 0.5}}) {
            const auto before = runner.stockSimulation();
            runner.setStockGrid(grid);
            QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy() && runner.stockSimulation() != before, 20000);
            QCOMPARE(runner.stockSimulation()->initial()->cellSize(), cell);
        }
    }

    void aDialectChangeRepostsTheSamePlan()
    {
        PlanRunner runner;
        QSignalSpy programs(&runner, &PlanRunner::programReady);
        runner.update(plateWithDepth(10));
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy(), 20000);
        const auto first = runner.fullPlan();
        QVERIFY(first);
        runner.setDialect("fanuc");
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isBusy() && programs.size() == 2, 20000);
        QCOMPARE(runner.fullPlan(), first);  // no tool path computed again
        QVERIFY(programs.at(1).at(1).toString().startsWith("%\nO1000"));
    }
};

QTEST_MAIN(TestGuiPlanRunner)
#include "test_gui_plan_runner.moc"
