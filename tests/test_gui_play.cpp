// Play block by block in the station (QTest on the offscreen platform): with
// a step selected Play walks through its blocks at the speed set, the NC
// view on each block; single blocks back and forward; the step's last
// block, then the next step's first; another step chosen ends it. The
// preview's side (the stock cut to the block, the tool at its end) is
// test_render_scene's selectedStepCutInItsColourAndPlayedByBlock.
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/file_actions.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiPlay : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void playsTheBlocksOfTheSelectedStep()
    {
        StationWindow w;
        QVERIFY(test::showSettled(w, "resources/samples/m4-standard.taiwa"));
        StepPanel* p = w.stepPanel();
        const auto plan = w.planRunner()->fullPlan();
        QVERIFY(plan && plan->steps.size() >= 3);
        const int k = 1;  // Roughing I
        const int moves = static_cast<int>(plan->steps[k].path->moves.size());
        QVERIFY(moves > 10);
        p->selectStep(k);
        QSignalSpy played(p, &StepPanel::playheadMoved);
        auto* play = p->findChild<QToolButton*>("step.play");
        QTest::mouseClick(play, Qt::LeftButton);
        QVERIFY(p->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(played.count() >= 4, 5000);
        QTest::mouseClick(play, Qt::LeftButton);  // pause
        QVERIFY(!p->isPlaying());
        // (k, -1) first: before its first block; then one block a tick.
        QCOMPARE(played.at(0).at(0).toInt(), k);
        QCOMPARE(played.at(0).at(1).toInt(), -1);
        for (int i = 1; i < 4; ++i) {
            QCOMPARE(played.at(i).at(0).toInt(), k);
            QCOMPARE(played.at(i).at(1).toInt(), i - 1);
        }
        // The NC view on the block's line, or on the last line written up to
        // it (the tape writes some moves with the block before).
        const int at = p->playMove();
        QCOMPARE(w.ncView()->currentSource().step, k);
        QVERIFY(w.ncView()->currentSource().move <= at && w.ncView()->currentSource().move >= at - 2);

        // Single blocks, from where it paused.
        QTest::mouseClick(p->findChild<QToolButton*>("step.blockBack"), Qt::LeftButton);
        QCOMPARE(p->playMove(), at - 1);
        QTest::mouseClick(p->findChild<QToolButton*>("step.blockForward"), Qt::LeftButton);
        QTest::mouseClick(p->findChild<QToolButton*>("step.blockForward"), Qt::LeftButton);
        QCOMPARE(p->playMove(), at + 1);
        QVERIFY(w.ncView()->currentSource().move <= at + 1 && w.ncView()->currentSource().move >= at - 1);

        // Faster: the step's last block, then the next step's first.
        p->setBlocksPerTick(1000);
        played.clear();
        QTest::mouseClick(play, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(played.count() >= 2, 5000);
        QTest::mouseClick(play, Qt::LeftButton);
        QCOMPARE(played.at(0).at(0).toInt(), k);
        QCOMPARE(played.at(0).at(1).toInt(), moves - 1);
        QCOMPARE(played.at(1).at(0).toInt(), k + 1);
        QCOMPARE(played.at(1).at(1).toInt(), 0);
        QCOMPARE(p->selectedStep(), k + 1);

        // Another step chosen by the operator: the playing ends.
        played.clear();
        p->selectStep(0);
        QCOMPARE(played.count(), 1);
        QCOMPARE(played.at(0).at(0).toInt(), -1);
        QCOMPARE(p->playStep(), -1);
    }

    // With no step selected Play still walks through the steps.
    void withoutAStepPlaysTheSteps()
    {
        StationWindow w;
        QVERIFY(test::showSettled(w, "resources/samples/m4-standard.taiwa"));
        StepPanel* p = w.stepPanel();
        p->selectStep(-1);
        p->setPlayInterval(20);
        QSignalSpy steps(p, &StepPanel::stepSelected);
        QSignalSpy played(p, &StepPanel::playheadMoved);
        p->setPlaying(true);
        QTRY_VERIFY_WITH_TIMEOUT(!p->isPlaying(), 5000);
        QVERIFY(steps.count() >= 4);
        QCOMPARE(played.count(), 0);
    }
};

QTEST_MAIN(TestGuiPlay)
#include "test_gui_play.moc"
