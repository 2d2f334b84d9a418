// Module SURFACE's form in the station, on the offscreen platform (issue 36):
// the sample's curves (one as two projections, one as points), N, M, the
// boundary and the ball end mill are fields of the form; typing into them
// edits the unit, and each refusal of the issue shows under its own field:
// projections whose shared axis does not overlap (curve 2), N >= M (N), a
// boundary that never meets the surface and one that does not read
// (boundary), a pinned ball end mill larger than the smallest concave
// radius with no smaller one in the library (tool); text that reads again
// clears it.
#include "modules/surface/surface.h"
#include "support/support.h"
#include "occt/surface_step.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"

#include <nlohmann/json.hpp>

#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiSurface : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    static const SurfaceUnit& unit(StationWindow& w) { return w.document()->job().units.at(0).module.as<SurfaceUnit>(); }
    static QLineEdit* field(StationWindow& w, const char* key)
    {
        auto* e = w.findChild<QLineEdit*>(QString("surface.") + key);
        if (!e) qWarning("no field surface.%s", key);
        return e;
    }
    // Types `text` over the field's whole text, as the operator does, and
    // leaves the field (the check runs).
    static void type(QLineEdit* e, const QString& text)
    {
        e->setFocus();
        e->selectAll();
        QTest::keyClick(e, Qt::Key_Backspace);
        QTest::keyClicks(e, text);
        QTest::keyClick(e, Qt::Key_Tab);
    }
    // The message under field `key` once the check has run (empty: none shown).
    static QString message(StationWindow& w, const char* key)
    {
        w.planRunner()->flush();
        QCoreApplication::processEvents();
        auto* label = w.findChild<QLabel*>(QString("surface.") + key + ".error");
        return label && label->isVisible() ? label->text() : QString();
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void formShowsAndEditsTheCurvesBoundaryAndTool()
    {
        StationWindow w(test::sourcePath("tests/data/surface-ruled.taiwa"));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        for (const char* key : {"curve1", "curve2", "n", "m", "curveStep", "scallop", "allowance", "boundary", "tool"})
            QVERIFY2(field(w, key), key);
        QCOMPARE(field(w, "curve1")->text(), QString("XY: 5, 5; 60, 10; 115, 5 / ZX: -8, 5; -14, 60; -8, 115"));
        QCOMPARE(field(w, "curve2")->text(), QString("5, 75, -6; 115, 75, -6"));
        QCOMPARE(field(w, "n")->text(), QString("4"));
        QCOMPARE(field(w, "m")->text(), QString("24"));
        QCOMPARE(field(w, "boundary")->text(), QString());
        QCOMPARE(field(w, "tool")->text(), QString());
        QVERIFY(!field(w, "tool")->placeholderText().isEmpty());
        // The sample is clean: no message under any field.
        for (const char* key : {"curve1", "curve2", "n", "boundary", "tool"}) QCOMPARE(message(w, key), QString());

        // Curve 2 typed as straight lines in space: the unit holds them.
        type(field(w, "curve2"), "5, 75, -6; 60, 75, -7; 115, 75, -6 / lines");
        QCOMPARE(unit(w).curve2.points.size(), std::size_t(3));
        QCOMPARE(unit(w).curve2.points[1].z, -7.0);
        QVERIFY(!unit(w).curve2.smooth);
        QCOMPARE(message(w, "curve2"), QString());

        // Projections whose shared axis (Y) does not overlap: refused on curve 2.
        type(field(w, "curve2"), "XY: 5, 60; 115, 70 / YZ: 90, -6; 100, -6");
        QCOMPARE(unit(w).curve2.projections.size(), std::size_t(2));
        QString m = message(w, "curve2");
        QVERIFY2(m.contains("does not overlap") && m.contains("curve 2"), qPrintable(m));
        QCOMPARE(message(w, "curve1"), QString());
        // Text that does not read: refused on its field, the curve kept.
        type(field(w, "curve2"), "5, 75; 115");
        QCOMPARE(unit(w).curve2Bad, std::string("5, 75; 115"));
        m = message(w, "curve2");
        QVERIFY2(m.contains("does not read"), qPrintable(m));
        type(field(w, "curve2"), "5, 75, -6; 115, 75, -6");
        QCOMPARE(message(w, "curve2"), QString());
        QVERIFY(unit(w).curve2Bad.empty());

        // N >= M: refused on N.
        type(field(w, "n"), "24");
        QCOMPARE(unit(w).n, 24);
        m = message(w, "n");
        QVERIFY2(m.contains("not less than M"), qPrintable(m));
        type(field(w, "n"), "4");
        QCOMPARE(message(w, "n"), QString());

        // A boundary beyond the surface (X 200 to 210, the surface ends at
        // X 115): it never meets it; one across it is taken.
        type(field(w, "boundary"), "200, 0, 0; 200, 80, 0 / 210, 0, -40; 210, 80, -40");
        QCOMPARE(unit(w).boundary.size(), std::size_t(2));
        m = message(w, "boundary");
        QVERIFY2(m.contains("never meets"), qPrintable(m));
        type(field(w, "boundary"), "100, 0, 0; 100, 80, 0 / 110, 0, -40; 110, 80, -40");
        QCOMPARE(message(w, "boundary"), QString());
        type(field(w, "boundary"), "100, 0");
        m = message(w, "boundary");
        QVERIFY2(m.contains("does not read"), qPrintable(m));
        type(field(w, "boundary"), "");
        QVERIFY(unit(w).boundary.empty());
        QCOMPARE(message(w, "boundary"), QString());

        // The ball end mill: T47 (D12) pinned fits the sample.
        type(field(w, "tool"), "47");
        QCOMPARE(unit(w).tools.at("surface"), 47);
        QCOMPARE(message(w, "tool"), QString());
        // A sharp valley: its smallest concave radius is under every ball's
        // radius (T41, D2, the smallest): the pinned T47 is refused on the
        // tool field, saying there is no smaller one.
        type(field(w, "curve1"), "5, 5, -1; 60, 5, -35; 115, 5, -1 / lines");
        m = message(w, "tool");
        QVERIFY2(m.contains("T47") && m.contains("no smaller ball end mill"), qPrintable(m));
        QCOMPARE(message(w, "curve1"), QString());
        // Unpinned: the choice finds none either, on the same field.
        type(field(w, "tool"), "");
        QVERIFY(unit(w).tools.empty());
        m = message(w, "tool");
        QVERIFY2(m.contains("no ball end mill with a radius less than"), qPrintable(m));
    }

    // A unit whose surface is a STEP face set (`taiwa import --surface`
    // writes its paths as "surface"): the curve fields are empty and say
    // so, a refusal of the surface shows under curve 1, the plan is made;
    // curves typed in make the curves the surface again.
    void aFaceSetShowsAsSuch()
    {
        nlohmann::json paths = nlohmann::json::array();
        for (int j = 0; j <= 10; ++j) {
            nlohmann::json path = nlohmann::json::array();
            for (int i = 0; i <= 12; ++i) path.push_back({5.0 * i, 4.0 * j, -0.002 * (5.0 * i - 30) * (5.0 * i - 30)});
            paths.push_back(path);
        }
        nlohmann::json job = nlohmann::json::parse(test::readFile(test::dataPath("surface-ruled.taiwa")));
        job["stock"] = {{"shape", "block"}, {"x", 0}, {"y", 0}, {"width", 60}, {"length", 40}, {"height", 10}};
        auto& u = job["units"][0];
        u.erase("curve1");
        u.erase("curve2");
        u.erase("n");
        u.erase("m");
        u["surface"] = paths;
        const QString file = dir_.filePath("face-set.taiwa");
        test::writeFile(file, job.dump(2));
        StationWindow w(file);
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QCOMPARE(unit(w).surface.size(), std::size_t(11));
        QCOMPARE(field(w, "curve1")->text(), QString());
        QVERIFY2(field(w, "curve1")->placeholderText().contains("STEP face set"), qPrintable(field(w, "curve1")->placeholderText()));
        QCOMPARE(message(w, "curve1"), QString());
        w.planRunner()->flush();
        const auto plan = w.planRunner()->fullPlan();
        QVERIFY(plan && plan->ok());
        QCOMPARE(plan->steps.size(), std::size_t(2));
        // Deeper than the block: refused on the surface, shown under curve 1.
        job["stock"]["height"] = 1;
        const QString shallow = dir_.filePath("face-set-shallow.taiwa");
        test::writeFile(shallow, job.dump(2));
        StationWindow w2(shallow);
        w2.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w2));
        const QString m = message(w2, "curve1");
        QVERIFY2(m.contains("through the stock's bottom"), qPrintable(m));
        // Curves typed in: the surface is ruled between them again.
        type(field(w, "curve1"), "5, 5, -3; 55, 5, -3");
        type(field(w, "curve2"), "5, 35, -2; 55, 35, -2");
        QVERIFY(unit(w).surface.empty());
        QCOMPARE(unit(w).curve1.points.size(), std::size_t(2));

        // File > Import surface: a STEP face set (written here from the
        // paths, a smooth face through them) becomes the job's one unit.
        std::vector<std::vector<Point3>> grid;
        for (const auto& path : paths) {
            std::vector<Point3> row;
            for (const auto& p : path) row.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
            grid.push_back(std::move(row));
        }
        const std::string step = dir_.filePath("face-set.step").toStdString();
        QVERIFY(surface::exportSurfaceStep(grid, step).ok());
        StationWindow w3;
        QVERIFY(w3.fileActions()->importSurfacePath(QString::fromStdString(step), 1.0));
        QCOMPARE(w3.document()->job().units.size(), std::size_t(1));
        QCOMPARE(unit(w3).surface.size(), std::size_t(41));  // 40 mm in Y at 1 mm
        QCOMPARE(w3.document()->job().stock.width, 60.0);
        QVERIFY(!w3.fileActions()->importSurfacePath(dir_.filePath("missing.step")));
    }
};

QTEST_MAIN(TestGuiSurface)
#include "test_gui_surface.moc"
