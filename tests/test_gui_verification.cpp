// The verification in the station (QTest on the offscreen platform): the
// Verify button on a sample lists nothing and says clean; a job beyond the
// machine's travel lists its fault in red; a finding chosen in the list
// selects its step in the step list and its block in the NC view; an edit
// makes the list stale; a result that arrives for a plan replaced
// meanwhile is dropped; the colour map is offered after a verification.
#include "support/hand_plan.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/verification_panel.h"

#include <QCheckBox>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

QString summary(VerificationPanel* p) { return p->findChild<QLabel*>("verify.summary")->text(); }

}  // namespace

class TestGuiVerification : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void sampleVerifiesCleanWithTheButton()
    {
        StationWindow w;
        QVERIFY(test::showSettled(w, "resources/samples/m4-standard.taiwa"));
        VerificationPanel* v = w.verificationPanel();
        QCOMPARE(summary(v), QString("Not verified since the last change."));
        auto* run = v->findChild<QPushButton*>("verify.run");
        QVERIFY(run->isEnabled());
        QSignalSpy done(v, &VerificationPanel::verified);
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(done.wait(60000));
        QCOMPARE(v->list()->count(), 0);
        QCOMPARE(summary(v), QString("Verified at 0.05 mm: clean."));
        QVERIFY(run->isEnabled());
    }

    void faultListedAndAnEditMakesItStale()
    {
        nlohmann::json job = nlohmann::json::parse(test::readFile(test::sourcePath("resources/samples/m4-standard.taiwa")));
        job["stock"]["width"] = 1000;
        nlohmann::json far = job["units"][0];
        far["name"] = "far";
        for (auto& c : far["corners"]) c[0] = c[0].get<double>() + 850;
        job["units"].push_back(far);
        const QString path = dir_.filePath("wide.taiwa");
        test::writeFile(path, job.dump(2));

        StationWindow w;
        w.show();
        QVERIFY(w.fileActions()->openPath(path));
        test::settle(w);
        VerificationPanel* v = w.verificationPanel();
        v->verifyNow();
        QCOMPARE(v->list()->count(), 1);
        QVERIFY(v->list()->item(0)->text().contains("more along x than the machine 'vmc' travels"));
        QCOMPARE(v->list()->item(0)->foreground().color(), QColor(192, 0, 0));
        // A 1,000 x 90 mm stock: the finest grid within 16 M cells (0.075 -> 0.08 mm).
        QCOMPARE(summary(v), QString("Verified at 0.08 mm: 1 faults, 0 with material left."));

        // An edit: a new plan, the findings gone until verified again.
        Job edited = w.document()->job();
        edited.units.pop_back();
        w.document()->edit(edited, "drop the far pocket");
        test::settle(w);
        QCOMPARE(v->list()->count(), 0);
        QCOMPARE(summary(v), QString("Not verified since the last change."));
    }

    // After a verification the Colour map box offers the finished part's
    // map: ticked, the map goes to the 3-D view and the legend shows;
    // cleared, no map; an edit drops it and greys the box until verified
    // again. A lathe job has none.
    void colourMapOfferedAfterVerifying()
    {
        StationWindow w;
        QVERIFY(test::showSettled(w, "resources/samples/m4-standard.taiwa"));
        VerificationPanel* v = w.verificationPanel();
        QCheckBox* box = v->colourMapBox();
        auto* legend = v->findChild<QLabel*>("verify.legend");
        QVERIFY(!box->isEnabled());
        std::vector<std::shared_ptr<const verify::DeviationMap>> shown;
        connect(v, &VerificationPanel::colourMapChanged, this,
                [&](std::shared_ptr<const verify::DeviationMap> m) { shown.push_back(std::move(m)); });
        v->verifyNow();
        QVERIFY(box->isEnabled());
        const auto map = v->deviationMap();
        QVERIFY(map);
        QCOMPARE(std::count(map->band.begin(), map->band.end(), verify::DeviationBand::Gouge), 0);
        QVERIFY(std::count(map->band.begin(), map->band.end(), verify::DeviationBand::AtSize) > 1000);
        QVERIFY(v->report().stock.heights().empty());  // the map keeps what is drawn; the fine grid is let go
        QVERIFY(!legend->isVisibleTo(&w));
        box->click();
        QVERIFY(!shown.empty() && shown.back() == map);
        QVERIFY(legend->isVisibleTo(&w));
        QVERIFY(legend->text().contains("gouge") && legend->text().contains("up to 0.1 mm left"));
        box->click();
        QVERIFY(!shown.back());
        QVERIFY(!legend->isVisibleTo(&w));
        box->click();
        QVERIFY(shown.back() == map);

        Job edited = w.document()->job();
        edited.units.front().name = "renamed";
        w.document()->edit(edited, "rename");
        test::settle(w);
        QVERIFY(!shown.back());
        QVERIFY(!box->isEnabled());
        QVERIFY(!v->deviationMap());

        StationWindow lathe;
        QVERIFY(test::showSettled(lathe, "resources/samples/lathe-turned-shaft.taiwa"));
        lathe.verificationPanel()->verifyNow();
        QVERIFY(!lathe.verificationPanel()->deviationMap());
        QVERIFY(!lathe.verificationPanel()->colourMapBox()->isEnabled());
    }

    // A finding chosen in the list: its step selected, its block the NC
    // view's current line. The panel is given a plan with a gouge (made by
    // hand) as the window would give it one.
    void chosenFindingSelectsStepAndBlock()
    {
        StationWindow w;
        QVERIFY(test::showSettled(w, "resources/samples/m4-standard.taiwa"));
        auto plan = std::make_shared<Plan>(*w.planRunner()->fullPlan());
        int floor = -1;
        for (std::size_t i = 0; i < plan->steps.size(); ++i)
            if (plan->steps[i].kind == StepKind::FloorFinishing && floor < 0) floor = static_cast<int>(i);
        QVERIFY(floor >= 0);
        auto& moves = plan->steps[static_cast<std::size_t>(floor)].path->moves;
        int k = -1;
        for (std::size_t i = 2; i < moves.size() && k < 0; ++i)
            if (moves[i].kind == MoveKind::Feed) k = static_cast<int>(i);
        moves[static_cast<std::size_t>(k)].end.z -= 0.3;
        VerificationPanel* v = w.verificationPanel();
        v->setPlan(plan);
        v->verifyNow();
        QVERIFY(v->list()->count() >= 1);
        QVERIFY(v->list()->item(0)->text().contains("gouge 0.30"));
        QSignalSpy chosen(v, &VerificationPanel::findingSelected);
        v->list()->setCurrentRow(0);
        QCOMPARE(chosen.count(), 1);
        QCOMPARE(chosen.at(0).at(0).toInt(), floor);
        QCOMPARE(chosen.at(0).at(1).toInt(), k);
        QCOMPARE(w.stepPanel()->selectedStep(), floor);
        const BlockSource at = w.ncView()->currentSource();
        QCOMPARE(at.step, floor);
        QCOMPARE(at.move, k);
    }

    // A result computed for a plan that was replaced before it arrived is
    // not shown against the new one.
    void resultForAnOldPlanDropped()
    {
        VerificationPanel v;
        auto first = std::make_shared<Plan>(test::samplePlan("plate.taiwa"));
        v.setPlan(first);
        QSignalSpy done(&v, &VerificationPanel::verified);
        v.verify();
        v.setPlan(std::make_shared<Plan>(test::samplePlan("m4-standard.taiwa")));
        QTRY_VERIFY_WITH_TIMEOUT(!v.isBusy(), 60000);
        QCOMPARE(summary(&v), QString("Not verified since the last change."));
        QCOMPARE(v.list()->count(), 0);
    }
};

QTEST_MAIN(TestGuiVerification)
#include "test_gui_verification.moc"
