// The probing page of the station (a PROBE unit's form): the touches as
// the operator types them, the fitted circle or rectangle with each touch's
// residual, the centre and the work offset to set, redrawn on every edit;
// a touch off the fit flagged with the fit's message; a touch not yet
// entered leaves the page saying the probing cycle will make the touches.
// With TAIWA_SCREENSHOTS_DIR set it writes docs/screenshots/station-probing.png.
#include "support/gui_fields.h"
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/plan_runner.h"
#include "ui/sketch_view.h"
#include "ui/station_window.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"

#include <QDir>
#include <QLabel>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;
using taiwa::test::GuiFields;

class TestGuiProbing : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    static SketchView* sketchOf(StationWindow& w) { return w.findChild<SketchView*>("probe.sketch"); }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void touchesFitAndFlag()
    {
        StationWindow w(test::sourcePath("resources/samples/probe-flange.taiwa"));
        w.resize(1920, 1080);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.unitList()->selectUnit(0);
        SketchView* sketch = sketchOf(w);
        QVERIFY(sketch);
        QVERIFY(sketch->isVisible());
        QVERIFY(sketch->sketch() && !sketch->sketch()->problem);
        QCOMPARE(sketch->sketch()->marks.size(), std::size_t(4));
        QCOMPARE(sketch->sketch()->outlines.size(), std::size_t(2));  // the boss, and the ball centres' circle
        const QString text = sketchOf(w)->findChild<QLabel*>("sketch.text")->text();
        QVERIFY2(text.contains("Boss: diameter 80.000 mm"), qPrintable(text));
        QVERIFY2(text.contains("Work offset to set: X 312.457 mm Y 145.123 mm Z -235.500 mm"), qPrintable(text));

        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (!out.isEmpty()) {
            w.planRunner()->flush();
            QTRY_VERIFY(!w.planRunner()->isBusy());
            QCoreApplication::sendPostedEvents();
            QDir().mkpath(out);
            QVERIFY(w.grab().toImage().save(QDir(out).filePath("station-probing.png")));
        }

        // P3 X typed 1 mm off: the fit flags it, the page says so in red.
        QLineEdit* p3x = GuiFields::edit(w, "probe.P3.x");
        QVERIFY(p3x);
        const QString was = p3x->text();
        GuiFields::retype(p3x, QString::number(was.toDouble() + 1.0));
        QTRY_VERIFY(sketch->sketch() && sketch->sketch()->problem);
        const auto& marks = sketch->sketch()->marks;
        QVERIFY(std::any_of(marks.begin(), marks.end(), [](const Sketch::Mark& m) { return m.flagged; }));
        const QString wrong = sketchOf(w)->findChild<QLabel*>("sketch.text")->text();
        QVERIFY2(wrong.contains("off the fitted circle"), qPrintable(wrong));
        // Typed back: fitted again.
        GuiFields::retype(p3x, was);
        QTRY_VERIFY(sketch->sketch() && !sketch->sketch()->problem);

        // Only the origin left: the page says the cycle makes the touches.
        for (const char* key : {"probe.P2.x", "probe.P2.y", "probe.P3.x", "probe.P3.y", "probe.P4.x", "probe.P4.y"})
            GuiFields::retype(GuiFields::edit(w, key), "");
        QTRY_VERIFY(sketch->sketch() && sketch->sketch()->marks.size() == 1);
        QVERIFY(sketchOf(w)->findChild<QLabel*>("sketch.text")->text().contains("the probing cycle"));
        // Nothing the operator typed is lost: the emptied touches are gone from the job, the others stay.
        QVERIFY(w.document()->job().units[0].module.name() == std::string("PROBE"));
    }

    // A machining module's form has no sketch.
    void pocketsHaveNone()
    {
        StationWindow w(test::sourcePath("resources/samples/probe-flange.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.unitList()->selectUnit(1);
        auto* m4 = w.findChild<SketchView*>("m4.sketch");
        QVERIFY(m4);
        QVERIFY(!m4->isVisible());
    }
};

QTEST_MAIN(TestGuiProbing)
#include "test_gui_probing.moc"
