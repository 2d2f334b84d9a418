// Input processing of single units: one test per refusal of the spec
// (field, unit and message checked). The job-level checks are in
// test_input_check_job.cpp; the hand-made tool library and the helpers in
// support/check_fixtures.h.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "job/job_check.h"
#include "support/check_fixtures.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace taiwa;
using namespace taiwa::test;

class TestInputCheck : public QObject {
    Q_OBJECT
private slots:
    void validJobPasses() { QVERIFY2(check(job({m4(), m2d()})).empty(), dump(check(job({m4(), m2d()})))); }

    void duplicateCorner()
    {
        M4Pocket p = m4();
        p.corners[2] = p.corners[1];
        EXPECT_ONLY(check(job({p})), 1, "corners[2]", "P2 and P3 are the same point (120 mm, 20 mm)");
        QCOMPARE(check(job({p}))[0].module, std::string("M4"));
    }
    void selfIntersecting()
    {
        M4Pocket p = m4();
        std::swap(p.corners[1], p.corners[2]);
        EXPECT_ONLY(check(job({p})), 1, "corners", "crosses itself");
    }
    void nonConvex()
    {
        M4Pocket p = m4();
        p.corners[2] = {60, 40};
        p.cornerRadius = 2;
        EXPECT_ONLY(check(job({p})), 1, "corners", "not convex");
    }
    void radiusOverHalfShorterSide()
    {
        M4Pocket p = m4();
        p.cornerRadius = 31;
        EXPECT_ONLY(check(job({p})), 1, "cornerRadius", "corner radius 31 mm is larger than half the shortest side (60 mm long)");
    }
    void roughingRadiusBelowSmallestTool()
    {
        M4Pocket p = m4();
        p.cornerRadius = 1.2;  // r1 - alpha2 = 0.9 < 1 (T2, the smallest flat end mill)
        EXPECT_ONLY(check(job({p})), 1, "cornerRadius", "r1 − α2 = 0.9 mm is smaller than the radius of the smallest suitable tool, T2");
        QVERIFY(check(job({p}))[0].message.find("at least 1.3 mm") != std::string::npos);
    }
    void semiFinishRadiusBelowSmallestTool()
    {
        M4Pocket p = m4();
        p.toolUse = 8;  // walls only: only r1 - alpha3 matters
        p.wallFinish = 3;
        p.cornerRadius = 1.05;
        EXPECT_ONLY(check(job({p})), 1, "cornerRadius", "r1 − α3 = 0.95 mm");
    }
    void noEndMillAtAll()
    {
        const std::vector<Tool> drillsOnly{tool(1, ToolType::Drill, 5)};
        const auto ds = check(job({m4()}), drillsOnly);
        QCOMPARE(ds.size(), std::size_t(2));  // roughing and wall finishing both need one
        QCOMPARE(ds[0].field, std::string("tools.roughing"));
        QVERIFY(ds[0].message.find("has no flat end mill") != std::string::npos);
    }
    void pinnedToolTooBigNamesOneThatFits()
    {
        M4Pocket p = m4();
        p.tools = {{"roughing", 5}};  // Ø16 in r1 - alpha2 = 7.7
        EXPECT_ONLY(check(job({p})), 1, "tools.roughing", "T5 (flat end mill Ø16 mm) is too big for r1 − α2 = 7.7 mm; T4 (flat end mill Ø10 mm) would fit");
    }
    void pinnedToolNotInLibrary()
    {
        M4Pocket p = m4();
        p.tools = {{"roughing", 99}};
        EXPECT_ONLY(check(job({p})), 1, "tools.roughing", "tool T99 is not in the tool library");
        p.tools = {{"chamfer", 3}};
        EXPECT_ONLY(check(job({p})), 1, "tools.chamfer", "\"chamfer\" is not a step of module M4; its steps are pilot, roughing, floor, wall, inclined");
    }
    void depthNotPositive()
    {
        M4Pocket p = m4();
        p.depth = 0;
        EXPECT_ONLY(check(job({p})), 1, "depth", "the depth is 0 mm; it must be greater than zero");
        M2DPocket q = m2d();
        q.depth = -3;
        EXPECT_ONLY(check(job({q})), 1, "depth", "the depth is -3 mm");
    }
    void alpha1NotBelowDepth()
    {
        Job j = job({m4()});
        j.technology.alpha1 = 12;
        EXPECT_ONLY(check(j), 0, "technology.alpha1", "α1 = 12 mm is not smaller than the depth 12 mm of unit 1");
        j.units[0].module = [] { M4Pocket p = m4(); p.pilotHole = 9; return p; }();
        QVERIFY(check(j).empty());  // no pilot hole, alpha1 is not used
    }
    void beta2NotBelowDepth()
    {
        Job j = job({m4(), m2d()});
        j.technology.beta2 = 10;
        EXPECT_ONLY(check(j), 0, "technology.beta2", "β2 = 10 mm is not smaller than the depth 10 mm of unit 2");
    }
    void taperOutOfRange_data()
    {
        QTest::addColumn<double>("taper");
        QTest::newRow("31") << 31.0;
        QTest::newRow("-1") << -1.0;
    }
    void taperOutOfRange()
    {
        QFETCH(double, taper);
        M4Pocket p = m4();
        p.taper = taper;
        EXPECT_ONLY(check(job({p})), 1, "taper", "is outside 0° to 30°");
    }
    void noTaperEndMillOfThatAngle()
    {
        M4Pocket p = m4();
        p.taper = 5;
        EXPECT_ONLY(check(job({p})), 1, "taper", "no taper end mill of 5° per side in the tool library (it has 3°)");
        p.taper = 3;
        QVERIFY2(check(job({p})).empty(), dump(check(job({p}))));
    }
    void thetaOutOfRange()
    {
        M2DPocket q = m2d();
        q.theta1 = 60;
        EXPECT_ONLY(check(job({q})), 1, "theta1", "θ1 = 60° is outside 0° to under 60°");
        q.theta1 = 20;
        q.theta2 = -1;
        EXPECT_ONLY(check(job({q})), 1, "theta2", "θ2 = -1°");
    }
    void thetaMakesFloorVanish()
    {
        M2DPocket q = m2d();
        q.depth = 20;
        q.theta1 = 55;  // floor 60 - 40 tan 55° = 2.874 mm, needs > 10 mm
        const double floor = 60 - 40 * std::tan(55 * std::numbers::pi / 180);
        const auto ds = check(job({q}));
        EXPECT_ONLY(ds, 1, "theta1", "leave a floor " + QString::number(floor, 'f', 3).toStdString() + " mm wide");
        QVERIFY(ds[0].message.find("short by " + QString::number(10 - floor, 'f', 3).toStdString() + " mm") != std::string::npos);
        QCOMPARE(ds[0].module, std::string("M2D"));
    }
    void undefinedCodes()
    {
        M4Pocket p = m4();
        p.toolUse = 3;
        EXPECT_ONLY(check(job({p})), 1, "U", "U = 3 is not defined");
        p.toolUse = 0;
        EXPECT_ONLY(check(job({p})), 1, "U", "U = 0 does not exist");
        p = m4();
        p.wallFinish = 4;
        EXPECT_ONLY(check(job({p})), 1, "F", "F = 4 does not exist");
        p = m4();
        p.pilotHole = 1;
        EXPECT_ONLY(check(job({p})), 1, "H", "H = 1 does not exist");
        M2DPocket q = m2d();
        q.toolUse = 6;
        EXPECT_ONLY(check(job({q})), 1, "U", "U = 6 is not allowed for M2D");
        q.toolUse = 4;
        EXPECT_ONLY(check(job({q})), 1, "U", "U = 4 is not defined");
    }
    void valuesThatWouldMakeTheWorkUnboundedAreRefused()
    {
        // γ 1e-9 once planned 1e10 layers (bad_alloc after 84 s and 13.6 GB).
        Job j = job({m4()});
        j.technology.gamma = 1e-9;
        EXPECT_ONLY(check(j), 0, "technology.gamma", "γ is 1e-09; it must lie between 0.01 and 2");
        j.technology.gamma = 5;
        EXPECT_ONLY(check(j), 0, "technology.gamma", "it must lie between 0.01 and 2");
        j = job({m4()});
        j.technology.alpha2 = 500;
        EXPECT_ONLY(check(j), 0, "technology.alpha2", "α2 is 500 mm; it must lie between 0 and 20 mm");
        M2DPocket q = m2d();
        q.scallop = 0.0004;
        EXPECT_ONLY(check(job({q})), 1, "scallop", "the scallop height is 0.0004 mm; it must be at least 0.001 mm");
        // A job shifted by 1e10 mm: refused at the stock and at the unit, each named.
        j = job({m4()});
        j.stock.x = 1e10;
        EXPECT_ONLY(check(j), 0, "stock.x", "every length and coordinate must lie within ±1000000 mm");
        M4Pocket far = m4();
        for (auto& c : far.corners) c.x += 1e10;
        const Diagnostics ds = check(job({far}));
        QVERIFY(std::any_of(ds.begin(), ds.end(), [](const Diagnostic& d) {
            return d.unit == 1 && d.field == "corners[0]" && d.message.find("within ±1000000 mm") != std::string::npos;
        }));
        QVERIFY(std::none_of(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.message.find("radius 0") != std::string::npos; }));
        j = job({m4()});
        j.stock.width = 20000;
        EXPECT_ONLY(check(j), 0, "stock.width", "the stock width is 20000 mm; a stock of more than 10000 mm a side");
    }

    void nonFiniteNumbers()
    {
        M4Pocket p = m4();
        p.depth = std::numeric_limits<double>::quiet_NaN();
        EXPECT_ONLY(check(job({p})), 1, "depth", "not a finite number");
        p = m4();
        p.corners[1].x = std::numeric_limits<double>::infinity();
        EXPECT_ONLY(check(job({p})), 1, "corners[1]", "the coordinate X of P2 is not a finite number");
        M2DPocket q = m2d();
        q.scallop = std::numeric_limits<double>::quiet_NaN();
        EXPECT_ONLY(check(job({q})), 1, "scallop", "not a finite number");
    }
    void unknownMaterial()
    {
        Job j = job({m4()});
        j.material = "unobtainium";
        EXPECT_ONLY(check(j), 0, "material", "material \"unobtainium\" is not in the technology table; known materials: aluminium-6061");
    }
    void stockNotPositive()
    {
        Job j = job({m4()});
        j.stock.height = 0;
        EXPECT_ONLY(check(j), 0, "stock.height", "the stock height is 0 mm");
    }
    void pocketOutsideStock()
    {
        EXPECT_ONLY(check(job({m4(150, 20)})), 1, "corners", "reaches outside the stock");
        M2DPocket q = m2d();
        q.lengthY = 140;
        EXPECT_ONLY(check(job({q})), 1, "corner", "reaches outside the stock");
    }
    void deeperThanStock()
    {
        M4Pocket p = m4();
        p.depth = 45;
        EXPECT_ONLY(check(job({p})), 1, "depth", "the depth 45 mm is deeper than the stock, which is 40 mm high");
        p.depth = 40;  // a through pocket is allowed
        QVERIFY(check(job({p})).empty());
    }
    void scallopNotPositive()
    {
        M2DPocket q = m2d();
        q.scallop = 0;
        EXPECT_ONLY(check(job({q})), 1, "scallop", "scallop height is 0 mm");
    }
    void m2dLengthNotPositive()
    {
        M2DPocket q = m2d();
        q.lengthX = 0;
        EXPECT_ONLY(check(job({q})), 1, "L1", "L1 is 0 mm");
    }
    void technologyOverrides()
    {
        Job j = job({m4()});
        j.technology.gamma = 0;
        EXPECT_ONLY(check(j), 0, "technology.gamma", "γ = 0 must be greater than zero");
        j.technology = {};
        j.technology.alpha3 = 0.5;  // not below alpha2 = 0.3, but no unit finishes its walls in two stages
        QVERIFY(check(j).empty());
        M4Pocket twoStage = m4();
        twoStage.wallFinish = 3;
        M4Pocket another = m4(20, 90, 60, 40);
        another.wallFinish = 3;
        j.units = {{"", m4()}, {"", twoStage}};
        j.units[1].module.as<M4Pocket>().corners = m4(130, 20, 50, 40).corners;
        j.units.push_back({"", another});
        // Checked where it is used, said once for the job.
        EXPECT_ONLY(check(j), 0, "technology.alpha3", "α3 = 0.5 mm must be smaller than the roughing wall allowance α2 = 0.3 mm");
    }
};

QTEST_APPLESS_MAIN(TestInputCheck)
#include "test_input_check.moc"
