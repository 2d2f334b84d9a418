// Stock simulation on the height field: a pocket path leaves every cell the
// tool reached at the pocket depth and every other cell untouched; a drill
// cycle makes a hole of the drill's diameter with its conical point; ball,
// taper and arc sweeps follow their profiles; per-step snapshots are the
// stock before and after each step and are cached.
#include "job/job_file.h"
#include "sim/cutter_profile.h"
#include "sim/material_removal.h"
#include "sim/path_samples.h"
#include "pipeline/pipeline.h"
#include "sim/stock_simulation.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>

using namespace taiwa;
using namespace taiwa::sim;

namespace {

const Stock kStock{0, 0, 100, 80, 30};

Tool tool(ToolType type, double d)
{
    Tool t;
    t.id = 1;
    t.type = type;
    t.diameter = d;
    t.fluteLength = 25;
    return t;
}

// Boustrophedon raster over [x0,x1] x [y0,y1] at depth z with stepover s,
// then the rectangle's contour: every point within R of the rectangle is
// within R of the path. Plunge from and retract to safe height.
ToolPath rasterPocket(double x0, double y0, double x1, double y1, double z, double s)
{
    ToolPath p{{x0, y0, 5.0}, {}};
    p.moves.push_back({MoveKind::Feed, {x0, y0, z}, {}, FeedKind::Plunge});
    bool right = true;
    for (double y = y0;; y = std::min(y + s, y1)) {
        p.moves.push_back({MoveKind::Feed, {right ? x1 : x0, y, z}});
        right = !right;
        if (y >= y1) break;
        p.moves.push_back({MoveKind::Feed, {right ? x0 : x1, std::min(y + s, y1), z}});
    }
    for (Point3 c : {Point3{x0, y0, z}, Point3{x1, y0, z}, Point3{x1, y1, z}, Point3{x0, y1, z}, Point3{x0, y0, z}})
        p.moves.push_back({MoveKind::Feed, c});
    p.moves.push_back({MoveKind::Rapid, {x0, y0, 5.0}});
    return p;
}

double distanceToRect(Point2 p, double x0, double y0, double x1, double y1)
{
    const double dx = std::max({x0 - p.x, 0.0, p.x - x1});
    const double dy = std::max({y0 - p.y, 0.0, p.y - y1});
    return std::hypot(dx, dy);
}

}  // namespace

class TestSim : public QObject {
    Q_OBJECT
private slots:
    // A straight cut in 2,000 chords of 0.02 mm lowers every cell exactly
    // as the one move does (each chord after the first skips the cells its
    // flat bottom cut: SweepChain), flat and bull-nosed.
    void shortChordsCutAsOneMove()
    {
        for (const double corner : {0.0, 2.0}) {
            Tool mill = tool(ToolType::FlatEndMill, 10);
            mill.cornerRadius = corner;
            ToolPath one{{30, 40, 5}, {}};
            one.moves.push_back({MoveKind::Feed, {30, 40, -5}, {}, FeedKind::Plunge});
            ToolPath chords = one;
            one.moves.push_back({MoveKind::Feed, {70, 40, -5}});
            for (int k = 1; k <= 2000; ++k) chords.moves.push_back({MoveKind::Feed, {30 + k * 0.02, 40, -5}});
            HeightField a(kStock, 0.25), b(kStock, 0.25);
            cut(a, one, mill);
            cut(b, chords, mill);
            int cutCells = 0;
            for (int j = 0; j < a.rows(); ++j)
                for (int i = 0; i < a.columns(); ++i) {
                    QVERIFY2(a.at(i, j) == b.at(i, j), qPrintable(QString("corner %1, cell (%2, %3): %4 against %5")
                                                                      .arg(corner).arg(i).arg(j).arg(a.at(i, j)).arg(b.at(i, j))));
                    cutCells += a.at(i, j) < 0.0;
                }
            QVERIFY(cutCells > 5000);
        }
    }

    void cellSizeFollowsTheBudget()
    {
        QCOMPARE(HeightField::cellSizeFor(kStock), 0.25);
        QVERIFY(std::abs(HeightField::cellSizeFor({0, 0, 2000, 1000, 50}, 1'000'000) - std::sqrt(2.0)) < 1e-12);
        const HeightField f(kStock, 0.25);
        QCOMPARE(f.columns(), 400);
        QCOMPARE(f.rows(), 320);
        QCOMPARE(f.at(10, 10), 0.0);
    }

    void pocketCellsAtDepthOthersUntouched()
    {
        HeightField f(kStock, 0.25);
        // Tool centre over [25,75] x [25,55], R = 5: the pocket is [20,80] x [20,60] with R5 corners.
        cut(f, rasterPocket(25, 25, 75, 55, -5.0, 4.0), tool(ToolType::FlatEndMill, 10));
        int inside = 0, outside = 0;
        for (int j = 0; j < f.rows(); ++j)
            for (int i = 0; i < f.columns(); ++i) {
                const double d = distanceToRect(f.centre(i, j), 25, 25, 75, 55);
                if (d < 5.0 - 1e-9) {
                    QCOMPARE(f.at(i, j), -5.0);
                    ++inside;
                } else if (d > 5.0 + 1e-9) {
                    QCOMPARE(f.at(i, j), 0.0);
                    ++outside;
                }
            }
        // The pocket's area in cells: 60 x 40 minus the corner rounding.
        const double area = 60.0 * 40.0 - (4.0 - M_PI) * 25.0;
        QVERIFY(std::abs(inside * 0.0625 - area) < 2.0);
        QVERIFY(outside > 85'000);
    }

    void drillMakesAHoleOfItsDiameter()
    {
        HeightField f(kStock, 0.25);
        Tool drill = tool(ToolType::Drill, 8.0);
        drill.pointAngle = 118;
        ToolPath p{{50, 40, 5}, {}};
        Move m{MoveKind::DrillCycle, {50, 40, -12}};
        m.retractZ = 1.0;
        p.moves.push_back(m);
        cut(f, p, drill);
        // Along the row through the centre, the cells lowered span the diameter.
        const int j = static_cast<int>(40 / 0.25);
        int lowered = 0;
        for (int i = 0; i < f.columns(); ++i) lowered += f.at(i, j) < 0 ? 1 : 0;
        QVERIFY2(std::abs(lowered * 0.25 - 8.0) <= 0.25, qPrintable(QString::number(lowered)));
        // The point: z = -12 + r / tan(59 deg).
        for (int i = 0; i < f.columns(); ++i) {
            const double r = distance(f.centre(i, j), {50.0, 40.0});
            if (r < 3.9) QVERIFY(std::abs(f.at(i, j) - (-12 + r / std::tan(59 * M_PI / 180))) < 1e-4);
            if (r > 4.1) QCOMPARE(f.at(i, j), 0.0);
        }
    }

    void ballSweepLeavesARoundGroove()
    {
        HeightField f(kStock, 0.25);
        ToolPath p{{10, 40.125, -5}, {{MoveKind::Feed, {90, 40.125, -5}}}};
        cut(f, p, tool(ToolType::BallEndMill, 10));
        for (double dy : {0.0, 1.0, 2.5, 4.0}) {
            const double expected = -std::sqrt(25.0 - dy * dy);
            QVERIFY(std::abs(f.atPoint(50.1, 40.125 + dy) - expected) < 1e-4);
        }
        QCOMPARE(f.atPoint(50.1, 40.125 + 5.5), 0.0);
    }

    void taperFlankAndHelicalArcs()
    {
        HeightField f(kStock, 0.25);
        Tool taper = tool(ToolType::TaperEndMill, 4.0);
        taper.taperAngle = 10;
        cut(f, ToolPath{{50.125, 40.125, 5}, {{MoveKind::Feed, {50.125, 40.125, -10}}}}, taper);
        QCOMPARE(f.atPoint(50.125, 40.125), -10.0);
        // Along the row through the axis: the flat tip (R2), then the 10 degree flank.
        const int j = static_cast<int>(40.125 / 0.25);
        int flank = 0;
        for (int i = 0; i < f.columns(); ++i) {
            const double r = std::abs(f.centre(i, j).x - 50.125);
            const double expected = std::min(0.0, -10.0 + std::max(0.0, r - 2.0) / std::tan(10 * M_PI / 180));
            QVERIFY(std::abs(f.at(i, j) - expected) < 1e-4);
            flank += expected < -1e-3 && r > 2.0 ? 1 : 0;
        }
        QVERIFY(flank >= 12);  // 2 x 10 tan 10 deg / 0.25 cells on the flank

        // A full circle (end == start) of radius 20 at Z -3, flat D6.
        HeightField g(kStock, 0.25);
        ToolPath ring{{70, 40, -3}, {{MoveKind::ArcCCW, {70, 40, -3}, {50, 40}}}};
        cut(g, ring, tool(ToolType::FlatEndMill, 6));
        for (double a = 0; a < 6.28; a += 0.3) {
            QCOMPARE(g.atPoint(50 + 20 * std::cos(a), 40 + 20 * std::sin(a)), -3.0);
            QCOMPARE(g.atPoint(50 + 16.5 * std::cos(a), 40 + 16.5 * std::sin(a)), 0.0);
        }
        // Sampled within the chord tolerance.
        for (const auto& piece : flattenPath(ring, 0.01)) {
            const Point2 mid{(piece.from.x + piece.to.x) / 2 - 50, (piece.from.y + piece.to.y) / 2 - 40};
            QVERIFY(20.0 - length(mid) <= 0.01 + 1e-12);
        }
    }

    void snapshotsBeforeAndAfterEachStep()
    {
        Plan plan;
        plan.mmJob.stock = kStock;
        Tool drill = tool(ToolType::Drill, 12);
        drill.id = 2;
        Tool mill = tool(ToolType::FlatEndMill, 10);
        plan.tools = {drill, mill};
        Step hole, rough;
        hole.tool = ToolChoice{2, ""};
        Move m{MoveKind::DrillCycle, {50, 40, -8}};
        m.retractZ = 1;
        hole.path = ToolPath{{50, 40, 5}, {m}};
        rough.tool = ToolChoice{1, ""};
        rough.path = rasterPocket(25, 25, 75, 55, -5.0, 4.0);
        plan.steps = {hole, rough, Step{}};  // the last one has no path yet

        StockSimulation sim(plan);
        QCOMPARE(sim.stepCount(), 3);
        QVERIFY(sim.before(0) == sim.initial());
        QVERIFY(std::abs(sim.after(0)->atPoint(50.1, 40.1) - (-8.0 + 0.125 * std::sqrt(2.0) / std::tan(59 * M_PI / 180))) < 1e-4);
        QCOMPARE(sim.after(0)->atPoint(30, 30), 0.0);
        QCOMPARE(sim.after(1)->atPoint(30, 30), -5.0);
        QVERIFY(sim.after(1)->atPoint(50.1, 40.1) < -7.5);  // the hole is still there
        QVERIFY(sim.before(1) == sim.after(0));  // the same shared snapshot
        QVERIFY(*sim.after(2) == *sim.after(1));
        QVERIFY(sim.finished() == sim.after(2));

        // Cached: asking again costs nothing like the first computation.
        StockSimulation fresh(plan);
        const auto t0 = std::chrono::steady_clock::now();
        fresh.after(1);
        const auto t1 = std::chrono::steady_clock::now();
        for (int k = 0; k < 100; ++k) fresh.after(1);
        const auto t2 = std::chrono::steady_clock::now();
        QVERIFY(t2 - t1 < (t1 - t0) / 5);
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, fresh.after(3));
    }

    // plate.taiwa's 29 steps: the finished part cut in two halves on two
    // threads is the same, cell for cell, as every step cut in order; and
    // stepping through all steps keeps a bounded number of snapshots.
    void finishedInParallelEqualsInOrder()
    {
        const auto read = readJobFile(test::sourcePath("resources/samples/plate.taiwa").toStdString());
        QVERIFY(read.job);
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok() && plan.steps.size() > 20);
        StockSimulation parallel(plan), inOrder(plan);
        const HeightField& finished = *parallel.finished();
        for (int k = 0; k < inOrder.stepCount(); ++k) {
            inOrder.after(k);
            QVERIFY(inOrder.snapshotCount() <= StockSimulation::kCheckpoints + StockSimulation::kRecent);
        }
        QVERIFY(finished == *inOrder.after(inOrder.stepCount() - 1));
        QVERIFY(finished.atPoint(42.5, 37.5) < -9.9);  // unit 1's floor, 10 mm deep
        QVERIFY(!(finished == *inOrder.after(10)));
        // A step asked for after the finished part comes from a checkpoint
        // or the start, and agrees with the in-order one.
        QVERIFY(*parallel.after(20) == *inOrder.after(20));
    }

    // Many steps: only the checkpoints and the last few asked for are kept.
    void snapshotsAreBounded()
    {
        Plan plan;
        plan.mmJob.stock = kStock;
        Tool mill = tool(ToolType::FlatEndMill, 6);
        mill.id = 1;
        plan.tools = {mill};
        for (int i = 0; i < 300; ++i) {
            Step s;
            s.tool = ToolChoice{1, ""};
            const double x = 5 + (i % 30) * 3, y = 5 + (i / 30) * 7;
            s.path = ToolPath{{x, y, 5}, {{MoveKind::Feed, {x, y, -1.0 - i % 3}}}};
            plan.steps.push_back(s);
        }
        StockSimulation sim(plan);
        // A snapshot handed out stays valid and unchanged however many others are asked for
        // (it was a reference into the cache, dropped after kRecent other requests).
        const StockSimulation::Snapshot held = sim.after(3);
        const HeightField heldCopy = *held;
        for (int k = 0; k < 300; ++k) sim.after(k);
        QVERIFY(*held == heldCopy);
        QVERIFY2(sim.snapshotCount() <= StockSimulation::kCheckpoints + StockSimulation::kRecent,
                 qPrintable(QString::number(sim.snapshotCount())));
        for (int k = 299; k >= 0; k -= 7) sim.before(k);
        QVERIFY(sim.snapshotCount() <= StockSimulation::kCheckpoints + StockSimulation::kRecent);
        StockSimulation again(plan);
        QVERIFY(*again.finished() == *sim.after(299));
    }

    // Block by block: each move's stock is the step's prefix cut; played
    // onward it cuts only the moves between; the last move is the whole
    // step, and going back starts again from the stock before the step.
    void afterMoveCutsTheBlocksPlayed()
    {
        const auto read = readJobFile(test::sourcePath("resources/samples/m4-standard.taiwa").toStdString());
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        StockSimulation played(plan), fresh(plan);
        const int k = 1;
        const ToolPath& path = *plan.steps[k].path;
        const int n = static_cast<int>(path.moves.size());
        QVERIFY(*played.afterMove(k, -1) == *played.before(k));
        for (int m : {0, 3, n / 2, n - 2}) {
            HeightField expected = *fresh.before(k);
            cut(expected, ToolPath{path.start, {path.moves.begin(), path.moves.begin() + m + 1}}, *plan.tool(plan.steps[k].tool->toolId));
            QVERIFY2(*played.afterMove(k, m) == expected, qPrintable(QString::number(m)));
        }
        QVERIFY(*played.afterMove(k, n + 5) == *fresh.after(k));
        QVERIFY(*played.afterMove(k, 2) == *StockSimulation(plan).afterMove(k, 2));  // back
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, played.afterMove(99, 0));
    }
};

QTEST_APPLESS_MAIN(TestSim)
#include "test_sim.moc"
