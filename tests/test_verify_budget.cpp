// The bound of the verification's work (verify::Options::maxCellVisits,
// issue "bounded work"): within the bound the report is the unbounded one;
// past it the verification runs on a grid twice as coarse, and again, and
// its report is exactly that grid's own, with a sentence saying why; the
// coarsest grid is finished whatever the bound; no bound, no coarsening.
#include "support/hand_plan.h"
#include "support/support.h"
#include "verify/verify.h"

#include <QtTest>

#include <fmt/format.h>

using namespace taiwa;

namespace {

verify::Report verifyAt(const Plan& plan, double resolution, double maxVisits = 0.0)
{
    verify::Options o;
    o.resolution = resolution;
    o.maxCellVisits = maxVisits;
    return verify::verifyPlan(plan, o);
}

void sameReport(const verify::Report& a, const verify::Report& b)
{
    QCOMPARE(a.resolution, b.resolution);
    QCOMPARE(a.columns, b.columns);
    QCOMPARE(a.rows, b.rows);
    QCOMPARE(a.findings, b.findings);
    QCOMPARE(a.removed, b.removed);
    QCOMPARE(a.cellVisits, b.cellVisits);
    QCOMPARE(a.stock.heights(), b.stock.heights());
}

}  // namespace

class TestVerifyBudget : public QObject {
    Q_OBJECT
private slots:
    void withinTheBoundNothingChanges()
    {
        const Plan plan = test::samplePlan("m4-standard.taiwa");
        const verify::Report free = verifyAt(plan, 0.1);
        QVERIFY(free.cellVisits > 1e5);
        const verify::Report bounded = verifyAt(plan, 0.1, free.cellVisits * 1.01);
        sameReport(bounded, free);
        QVERIFY(bounded.coarsened.empty());
    }

    void pastTheBoundACoarserGrid()
    {
        const Plan plan = test::samplePlan("m4-standard.taiwa");
        const verify::Report fine = verifyAt(plan, 0.1);
        const verify::Report coarse = verifyAt(plan, 0.2);
        QVERIFY(coarse.cellVisits < fine.cellVisits / 2.5);  // the square of the cell size, less the edges
        const double bound = (fine.cellVisits + coarse.cellVisits) / 2.0;
        const verify::Report bounded = verifyAt(plan, 0.1, bound);
        sameReport(bounded, coarse);  // exactly the coarser grid's own report
        QVERIFY(bounded.cellVisits <= bound);
        QCOMPARE(QString::fromStdString(bounded.coarsened),
                 QString("verified at 0.2 mm, not 0.1 mm: on that grid the paths would have swept more than %1 cells; "
                         "--resolution 0.1 verifies on it all the same")
                     .arg(QString::fromStdString(fmt::format("{:.3g}", bound))));
        // Twice past: two steps coarser.
        const verify::Report twice = verifyAt(plan, 0.1, coarse.cellVisits / 2.0);
        QCOMPARE(twice.resolution, 0.4);
        sameReport(twice, verifyAt(plan, 0.4));
    }

    // A bound no grid meets: the coarsest grid --resolution takes is
    // finished all the same (the work is the fewest cells there are).
    void theCoarsestGridIsFinished()
    {
        const Plan plan = test::samplePlan("m4-standard.taiwa");
        const verify::Report r = verifyAt(plan, 0.05, 1.0);
        QCOMPARE(r.resolution, 3.2);  // 0.05, 0.1, 0.2, 0.4, 0.8, 1.6, 3.2; 6.4 is past 5 mm
        QVERIFY(!r.coarsened.empty());
        sameReport(r, verifyAt(plan, 3.2));
    }

    // A lathe job's verification is exact and takes milliseconds: no bound applies.
    void latheJobsAreNotCoarsened()
    {
        const Plan plan = test::samplePlan("lathe-turned-shaft.taiwa");
        const verify::Report r = verifyAt(plan, 0.05, 1.0);
        QCOMPARE(r.resolution, 0.05);
        QVERIFY(r.coarsened.empty());
        QVERIFY(r.skipped.empty());
    }
};

QTEST_GUILESS_MAIN(TestVerifyBudget)
#include "test_verify_budget.moc"
