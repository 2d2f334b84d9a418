// Where each path's tool stands on the two-path timeline
// (verify/two_path_timeline.h toolsAt, toolPlaces; docs/two-path-lathe.md
// "In the station"), on the cylinder sample as the station balances it
// (export/two_path_sheet.h balancedRoughing): at the start both tools at
// their programs' starts; at a block's cut its path's tool at the cut's
// start, in its own program's coordinates the block's own numbers (path 2's
// X negative), the other path's tool on its own block at that moment, the
// set revolutions ahead; the places at every move of the single path agree
// with the clock.
#include "export/two_path_sheet.h"
#include "job/job_file.h"
#include "machine/machine.h"
#include "model/turn_path.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "verify/two_path_timeline.h"

#include <QtTest>

#include <cmath>

using namespace taiwa;
using turning::ZR;

namespace {

const Plan& cylinderPlan()
{
    static const Plan plan = [] {
        auto r = readJobFile(test::sourcePath("resources/samples/lathe-two-path-cylinder.taiwa").toStdString());
        if (!r.job) qFatal("cannot read the cylinder sample");
        return planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary());
    }();
    return plan;
}

const Machine& twoPath()
{
    const Machine* m = findMachine("lathe-two-path");
    if (!m) qFatal("no two-path lathe");
    return *m;
}

bool near(ZR a, ZR b, double tol = 1e-6) { return std::abs(a.z - b.z) <= tol && std::abs(a.r - b.r) <= tol; }
QByteArray text(ZR p) { return QByteArray::number(p.z, 'f', 4) + " " + QByteArray::number(p.r, 'f', 4); }

}  // namespace

class TestTwoPathPlaces : public QObject {
    Q_OBJECT

private slots:
    // The cylinder (Ø40 bar to Ø20, 1.96 mm a pass): CB1 on path 1 at
    // radius 18.04, CB2 on path 2 at 16.08 (X-32.16 on its own tape), both
    // approaching from Z2; feed 0.3 mm a revolution under G96.
    void placesAtTheStartAndAtTheCuts()
    {
        const Plan& plan = cylinderPlan();
        const auto b = balancedRoughing(plan);
        QVERIFY(b && b->cut && *b->cut && b->timeline);
        const BalancedCut& cut = **b->cut;
        const MultiPath& mp = *twoPath().layout.multiPath;
        QCOMPARE(cut.paths.size(), std::size_t(2));
        const auto block = [&](int n) {
            for (const auto& t : b->timeline->blocks)
                if (t.number == n) return t;
            qFatal("no CB%d", n);
        };

        // Before anything moves: each at its program's start (path 2's X mirrored).
        const ToolPlaces places = toolPlaces(cut, twoPath());
        QCOMPARE(places.start.size(), std::size_t(2));
        QVERIFY2(near(places.start[0], {2.0, 22.0}), text(places.start[0]));
        QVERIFY2(near(mp.fromPath1(places.start[1], 1), {2.0, -22.0}), text(mp.fromPath1(places.start[1], 1)));
        QVERIFY(near(toolsAt(cut, twoPath(), 0.0)[1], places.start[1]));

        // CB1's cut (path 1 leads): path 1 at the cut's start; path 2 at its
        // own cut's start already, standing at the meeting M101 (its approach
        // is a rapid, the shorter in X).
        const auto atCb1 = toolsAt(cut, twoPath(), block(1).cutStart);
        QVERIFY2(near(atCb1[0], {2.0, 18.04}), text(atCb1[0]));
        QVERIFY2(near(mp.fromPath1(atCb1[1], 1), {2.0, -16.08}), text(mp.fromPath1(atCb1[1], 1)));

        // CB2's cut (path 2 follows): path 2 at its cut's start, X-32.16 as
        // its tape has it; path 1 has cut on from M101 for path 2's dwell, at
        // the spindle speed at Ø36.08: 0.3 mm a revolution, at least the set
        // revolution ahead.
        const BalancedBlock& cb2 = cut.paths[1].blocks.front();
        QCOMPARE(cb2.number, 2);
        QCOMPARE(cb2.dwellSeconds, 0.035);
        const auto atCb2 = toolsAt(cut, twoPath(), block(2).cutStart);
        QVERIFY2(near(mp.fromPath1(atCb2[1], 1), {2.0, -16.08}), text(mp.fromPath1(atCb2[1], 1)));
        const double rpm = cut.cutting.rpmAt(36.08, cut.spindleLimit);
        QCOMPARE(cut.cutting.feedPerRev, 0.3);
        const double ahead = 0.3 * rpm / 60.0 * 0.035;
        QVERIFY2(near(atCb2[0], {2.0 - ahead, 18.04}, 1e-6), text(atCb2[0]) + " against Z" + QByteArray::number(2.0 - ahead));
        QVERIFY2(ahead >= 0.3, QByteArray::number(ahead));
        // The negative control: a moment earlier path 1 is elsewhere (the clock matters).
        QVERIFY(!near(toolsAt(cut, twoPath(), block(2).cutStart - 0.01)[0], atCb2[0], 1e-3));
        // After the end: each where its program ended.
        const auto atEnd = toolsAt(cut, twoPath(), 1e6);
        QVERIFY(near(atEnd[0], cut.paths[0].tail.back().end));
        QVERIFY(near(mp.fromPath1(atEnd[1], 1), cut.paths[1].tail.back().end));
    }

    // At every move of the single path (the station's 3-D view draws the
    // tools there): the path that runs it at its end, the places those of
    // the clock at that moment (the cut of every block: toolsAt there).
    void placesAtEveryMoveOfTheSinglePath()
    {
        const Plan& plan = cylinderPlan();
        const auto b = balancedRoughing(plan);
        QVERIFY(b && b->cut && *b->cut && b->timeline);
        const BalancedCut& cut = **b->cut;
        const TurnPath& single = turnOf(plan.steps[b->step])->path;
        const ToolPlaces places = toolPlaces(cut, twoPath());
        QCOMPARE(places.afterMove.size(), single.moves.size());
        // Which path runs each single-path move: the blocks in CB order, then path 1's tail.
        std::vector<std::size_t> runBy;
        std::vector<std::size_t> firstOf(static_cast<std::size_t>(cut.blockCount) + 1, 0);
        for (int n = 1; n <= cut.blockCount; ++n)
            for (const auto& p : cut.paths)
                for (const auto& blk : p.blocks)
                    if (blk.number == n) {
                        firstOf[static_cast<std::size_t>(n)] = runBy.size();
                        runBy.insert(runBy.end(), blk.moves.size(), blk.path);
                    }
        runBy.insert(runBy.end(), cut.paths[0].tail.size(), 0);
        QCOMPARE(runBy.size(), single.moves.size());
        int onOtherSide = 0;
        for (std::size_t m = 0; m < single.moves.size(); ++m) {
            QCOMPARE(places.afterMove[m].size(), std::size_t(2));
            QVERIFY2(near(places.afterMove[m][runBy[m]], single.moves[m].end, 1e-9),
                     QByteArray::number(int(m)) + ": " + text(places.afterMove[m][runBy[m]]) + " against " + text(single.moves[m].end));
            onOtherSide += runBy[m] == 1;
        }
        QVERIFY(onOtherSide > 4);
        // Each block's cut starts where the move before its first feed
        // leaves its tool (the wait and the dwell stand there): the clock's
        // place at the cut.
        for (const auto& t : b->timeline->blocks)
            for (const auto& blk : cut.paths[t.path].blocks)
                if (blk.number == t.number) {
                    QVERIFY(blk.cutFrom > 0);
                    const std::size_t before = firstOf[static_cast<std::size_t>(t.number)] + blk.cutFrom - 1;
                    QVERIFY2(near(places.afterMove[before][t.path], toolsAt(cut, twoPath(), t.cutStart)[t.path], 1e-9),
                             QByteArray("CB") + QByteArray::number(t.number));
                }
    }
};

QTEST_GUILESS_MAIN(TestTwoPathPlaces)
#include "test_two_path_places.moc"
