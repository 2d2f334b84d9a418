// The station on the sample plate.taiwa: it opens with every unit listed,
// the step list and the NC program filled, and each step can be selected;
// in Japanese, the compiled-in translation is used.
// With TAIWA_SCREENSHOTS_DIR set (run under `xvfb-run -a` so that the 3-D
// view renders) it also writes the PNGs of docs/screenshots/: the whole
// window, then the window with single steps selected.
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_list_panel.h"

#include <QDir>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiScreenshots : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    static void settle(StationWindow& w)
    {
        w.planRunner()->flush();
        QTest::qWait(300);  // layout, and a frame of the 3-D view
    }
    static void save(StationWindow& w, const QString& name)
    {
        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (out.isEmpty()) return;
        QDir().mkpath(out);
        const QImage image = w.grab().toImage();
        QVERIFY(!image.isNull());
        QVERIFY(image.save(QDir(out).filePath(name)));
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void plate()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(!w.document()->job().units.empty());
        settle(w);
        QVERIFY(w.planRunner()->fullPlan());
        const int steps = w.stepTable()->rowCount();
        QCOMPARE(steps, static_cast<int>(w.planRunner()->fullPlan()->steps.size()));
        QVERIFY(steps > 4);
        QVERIFY(w.ncView()->text()->toPlainText().startsWith("%") ||
                w.ncView()->text()->toPlainText().contains("G21"));
        save(w, "station-plate.png");

        const int shown[] = {0, 1, steps - 1};
        for (int k : shown) {
            w.stepPanel()->selectStep(k);
            QCOMPARE(w.stepPanel()->selectedStep(), k);
            settle(w);
            save(w, QStringLiteral("station-plate-step%1.png").arg(k + 1));
        }
        // The M2D unit's form with its drawing.
        const auto& units = w.document()->job().units;
        for (std::size_t i = 0; i < units.size(); ++i)
            if (std::holds_alternative<M2DPocket>(units[i].module)) {
                w.unitList()->selectUnit(static_cast<int>(i));
                break;
            }
        w.stepPanel()->selectStep(-1);
        settle(w);
        save(w, "station-plate-m2d.png");
    }

    void japanese()
    {
        qputenv("TAIWA_LANG", "ja");
        QVERIFY(installTranslator(*QCoreApplication::instance()));
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QStringList menus;
        for (QAction* a : w.menuBar()->actions()) menus << a->text();
        QCOMPARE(menus.first(), QString("ファイル(&F)"));
        settle(w);
        save(w, "station-plate-ja.png");
    }
};

QTEST_MAIN(TestGuiScreenshots)
#include "test_gui_screenshots.moc"
