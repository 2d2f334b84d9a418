// Module SURFACE's refusals in the station's language (issue 36). The
// surface sample in a Japanese station: N typed as large as M (said by the
// module) and curve 2 typed as two projections whose shared axis does not
// overlap (said by core/occt, put after the curve's name by the module) each
// show under their field in Japanese, no English word left; in an English
// station the same refusals in English (the control). And every refusal the
// module and its geometry make, made here by the real functions, comes out in
// Japanese and Chinese with no English word but the names it quotes: a
// template missing from the catalogues, or one the station's matching reads
// wrongly (a nested message taken apart at the wrong colon), leaves one.
#include "check/messages.h"
#include "model/contour.h"
#include "modules/registry.h"
#include "modules/surface/surface.h"
#include "occt/surface_checks.h"
#include "occt/surface_curves.h"
#include "occt/surface_step.h"
#include "support/speak.h"
#include "support/support.h"
#include "ui/core_messages.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"

#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

using test::speak;

QLineEdit* field(StationWindow& w, const char* key)
{
    auto* e = w.findChild<QLineEdit*>(QString("surface.") + key);
    if (!e) qWarning("no field surface.%s", key);
    return e;
}

// Types `text` over the field's whole text, as the operator does, and leaves the field (the check runs).
void type(QLineEdit* e, const QString& text)
{
    e->setFocus();
    e->selectAll();
    QTest::keyClick(e, Qt::Key_Backspace);
    QTest::keyClicks(e, text);
    QTest::keyClick(e, Qt::Key_Tab);
}

// The message under field `key` once the check has run (empty: none shown).
QString message(StationWindow& w, const char* key)
{
    w.planRunner()->flush();
    QCoreApplication::processEvents();
    auto* label = w.findChild<QLabel*>(QString("surface.") + key + ".error");
    return label && label->isVisible() ? label->text() : QString();
}

// The message a refusal puts under field `key`, waited for up to 5 s.
QString refusal(StationWindow& w, const char* key)
{
    QString m = message(w, key);
    for (int i = 0; i < 50 && m.isEmpty(); ++i) {
        QTest::qWait(100);
        m = message(w, key);
    }
    return m;
}

// The runs of three or more ASCII letters in `text`: English words (the
// fields' names N, M, X, Y, Z, XY, YZ, ZX, the mm of a length and T of a
// tool are shorter), but for the names in `quoted` (a file, STEP, OpenCASCADE).
QStringList englishWords(QString text, const QStringList& quoted = {})
{
    for (const QString& q : quoted) text.replace(q, QStringLiteral("#"));
    QStringList out;
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{3,}"));
    for (auto it = word.globalMatch(text); it.hasNext();) out << it.next().captured();
    return out;
}

SurfaceCurve points(std::vector<Point3> p, bool smooth = true) { return SurfaceCurve{std::move(p), {}, smooth}; }

SurfaceCurve projections(SurfaceProjection a, SurfaceProjection b)
{
    return SurfaceCurve{{}, {std::move(a), std::move(b)}, true};
}

// The sample's unit (resources/samples/surface-cover.taiwa).
SurfaceUnit cover()
{
    SurfaceUnit u;
    u.curve1 = points({{5, 5, -7}, {35, 5, -9}, {65, 5, -7}});
    u.curve2 = points({{5, 45, -3}, {65, 45, -3}});
    u.n = 3;
    u.m = 12;
    u.scallop = 0.3;
    u.allowance = 0.3;
    return u;
}

Tool ball(int id, double d)
{
    Tool t;
    t.id = id;
    t.type = ToolType::BallEndMill;
    t.diameter = d;
    return t;
}

// Paths along X whose fourth point goes back under the third (an overhang).
std::vector<std::vector<Point3>> overhang()
{
    std::vector<std::vector<Point3>> paths;
    for (double y : {0.0, 10.0, 20.0}) {
        std::vector<Point3> path;
        for (auto [x, z] : std::vector<std::pair<double, double>>{{0, 0}, {10, -5}, {20, -1}, {15, -3}, {25, -4}})
            path.push_back({x, y, z});
        paths.push_back(std::move(path));
    }
    return paths;
}

// A smooth bowl 60 × 40 mm, 11 paths of 13 points.
std::vector<std::vector<Point3>> bowl()
{
    std::vector<std::vector<Point3>> paths;
    for (int j = 0; j <= 10; ++j) {
        std::vector<Point3> path;
        for (int i = 0; i <= 12; ++i) path.push_back({5.0 * i, 4.0 * j, -3 - 0.002 * (5.0 * i - 30) * (5.0 * i - 30)});
        paths.push_back(std::move(path));
    }
    return paths;
}

}  // namespace

class TestGuiSurfaceLanguages : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // The sample in a station speaking `language`: N typed as M, then curve 2
    // as two projections whose Y ranges do not meet; the two messages shown.
    // A copy of its own for each station (the station would offer the last
    // one's unsaved edits of the same file back).
    std::pair<QString, QString> refusals(const char* language)
    {
        speak(language);
        const QString file = dir_.filePath(QString("surface-cover-%1.taiwa").arg(language));
        test::writeFile(file, test::readFile(test::sourcePath("resources/samples/surface-cover.taiwa")));
        StationWindow w(file);
        w.show();
        w.activateWindow();
        if (!QTest::qWaitForWindowActive(&w)) qWarning("the station did not come up");
        if (!field(w, "n") || !field(w, "curve2")) return {};
        if (!message(w, "n").isEmpty() || !message(w, "curve2").isEmpty())
            qWarning("the sample is refused: %s / %s", qPrintable(message(w, "n")), qPrintable(message(w, "curve2")));
        type(field(w, "n"), "12");
        const QString n = refusal(w, "n");
        type(field(w, "n"), "3");
        type(field(w, "curve2"), "XY: 5, 60; 65, 70 / YZ: 90, -6; 100, -6");
        const QString curve = refusal(w, "curve2");
        if (!message(w, "n").isEmpty()) qWarning("N is still refused");
        return {n, curve};
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }
    void cleanup() { speak("en"); }

    void refusalsOnTheFormInTheStationsLanguage()
    {
        // The control: an English station says them as the core wrote them.
        const auto [nEn, curveEn] = refusals("en");
        QCOMPARE(nEn, QString("N 12 is not less than M 12: the finishing surface must be divided more finely than the "
                              "roughing surface (N < M)"));
        QCOMPARE(curveEn, QString("curve 2: projection 2 (YZ): its Y range 90.0000 to 100.0000 does not overlap "
                                  "projection 1's (XY) 60.0000 to 70.0000"));

        const auto [nJa, curveJa] = refusals("ja");
        QVERIFY2(englishWords(nJa).isEmpty() && englishWords(curveJa).isEmpty(), qPrintable(nJa + "\n" + curveJa));
        QCOMPARE(nJa, QString("N 12 が M 12 より小さくありません: 仕上げの曲面は荒加工の曲面より細かく分けてください (N < M)"));
        QCOMPARE(curveJa, QString("曲線 2: 投影 2 (YZ): Y の範囲 90.0000～100.0000 が投影 1 (XY) の 60.0000～70.0000 と"
                                  "重なりません"));

        const auto [nZh, curveZh] = refusals("zh");
        QVERIFY2(englishWords(nZh).isEmpty() && englishWords(curveZh).isEmpty(), qPrintable(nZh + "\n" + curveZh));
        QVERIFY2(nZh.contains("N 12") && nZh.contains("M 12") && nZh.contains("精加工"), qPrintable(nZh));
        QVERIFY2(curveZh.contains("曲线 2") && curveZh.contains("90.0000") && curveZh.contains("60.0000"),
                 qPrintable(curveZh));
    }

    // Every refusal of the module and its geometry, as the real functions
    // make them, in Japanese and Chinese: no English word but what it quotes.
    void everySurfaceRefusalIsTranslated()
    {
        std::vector<std::string> english;
        const auto built = [&](const SurfaceUnit& u) {
            const std::string p = surfacemod::buildSurfaces(u, LengthUnit::Millimetre).problem;
            if (p.empty()) qWarning("a unit meant to be refused was built");
            english.push_back(p);
        };
        const auto failed = [&](const auto& result, int line) {
            if (result.ok()) qWarning("the call of line %d meant to fail succeeded", line);
            else english.push_back(result.error());
        };
        SurfaceUnit u = cover();
        u.curve1 = points({{5, 5, -7}});
        built(u);  // one point
        u.curve1 = SurfaceCurve{{}, {{"XY", {{5, 5}, {65, 5}}, {}, {}}}, true};
        built(u);  // one projection
        u.curve1 = projections({"XZ", {{5, -7}, {65, -7}}, {}, {}}, {"XY", {{5, 5}, {65, 5}}, {}, {}});
        built(u);  // a plane not XY, YZ, ZX
        // Projections given as contours of the figure: one it does not have, one closed.
        const ModuleKind* kind = findModuleKind("SURFACE");
        QVERIFY(kind);
        ContourTable table;
        table["K1"] = Contour{{{ContourSegment::Kind::Line, {5, -7}, {65, -7}, {}}}, false};
        table["K2"] = Contour{{{ContourSegment::Kind::Line, {0, 0}, {10, 0}, {}},
                               {ContourSegment::Kind::Line, {10, 0}, {0, 10}, {}},
                               {ContourSegment::Kind::Line, {0, 10}, {0, 0}, {}}},
                              true};
        for (const char* name : {"K9", "K2"}) {
            SurfaceUnit c = cover();
            c.curve1 = projections({"XY", {}, "K1", {}}, {"ZX", {}, name, {}});
            ModuleInput in(c);
            kind->resolveContours(in, table);
            built(in.as<SurfaceUnit>());
        }
        u.curve1 = projections({"XY", {{5, 5}, {65, 10}}, {}, {}}, {"YZ", {{90, -6}, {100, -6}}, {}, {}});
        built(u);  // the shared axis does not overlap
        u.curve1 = projections({"XY", {{5, 5}, {35, 5}, {35, 6}, {65, 5}}, {}, {}}, {"ZX", {{-7, 5}, {-7, 65}}, {}, {}});
        built(u);  // X stands still
        u.curve1 = projections({"XY", {{5, 5}, {35, 5}, {25, 6}, {65, 5}}, {}, {}}, {"ZX", {{-7, 5}, {-7, 65}}, {}, {}});
        built(u);  // X turns back
        u.curve1 = projections({"XY", {{5, 5}}, {}, {}}, {"ZX", {{-7, 5}, {-7, 65}}, {}, {}});
        built(u);  // a projection of one point
        u.curve1 = projections({"XY", {{5, 5}, {65, 5}}, {}, {}}, {"XY", {{5, 6}, {65, 6}}, {}, {}});
        built(u);  // both in one plane
        u = cover();
        u.curve2Bad = "5, 45; 65";
        built(u);  // does not read
        u = cover();
        u.surface = {{{0, 0, -1}, {10, 0, -1}}};
        built(u);  // one path
        u.surface = {{{0, 0, -1}, {10, 0, -1}}, {{0, 10, -1}, {5, 10, -1}, {10, 10, -1}}};
        built(u);  // paths of unequal points
        u = cover();
        u.surface = overhang();
        built(u);  // an undercut
        u = cover();
        u.n = 0;
        built(u);
        u = cover();
        u.m.reset();
        built(u);  // neither M nor the step along the curves
        u.curveStep = 0.0;
        built(u);  // a step along the curves of 0
        u = cover();
        u.m = 12;
        u.n = 12;
        built(u);  // N ≥ M
        u = cover();
        u.curve1 = points({{5, 5, -7}, {5, 5, -7}, {65, 5, -7}});
        built(u);  // two points in one place
        u = cover();
        u.curve1 = points({{5, 5, 2}, {65, 5, 2}});
        built(u);  // above the stock top

        // The checks with the stock and the tool library.
        const Stock stock{0, 0, 70, 50, 5};
        const std::vector<Tool> balls{ball(41, 2), ball(47, 12)};
        Tool flat = ball(20, 10);
        flat.type = ToolType::FlatEndMill;
        const std::vector<Tool> withFlat{flat, ball(47, 12)};
        const std::vector<Tool> none{flat};
        const auto checked = [&](const SurfaceUnit& c, const std::vector<Tool>& library) {
            check::Context ctx;
            ctx.stock = &stock;
            ctx.library = &library;
            const check::UnitReport report = checkSurface(c, 1, ctx);
            if (report.diagnostics.empty()) qWarning("a unit meant to be refused was checked clean");
            for (const Diagnostic& d : report.diagnostics) english.push_back(d.message);
        };
        u = cover();
        u.scallop = 0;
        u.allowance = -1;
        u.curve1 = points({{5, 5, -7}, {35, 5, -9}, {65, 5, -7}});
        u.boundaryBad = "100, 0";
        checked(u, balls);  // scallop, allowance, the stock's bottom, a boundary that does not read
        u = cover();
        u.boundary = {{{100, 0, 0}, {100, 80, 0}}};
        checked(u, balls);  // a boundary of one path
        u.boundary = {{{200, 0, 0}, {200, 80, 0}}, {{210, 0, -40}, {210, 80, -40}}};
        checked(u, balls);  // one that never meets the surface
        u = cover();
        u.tools["surface"] = 20;
        checked(u, withFlat);  // pinned, not a ball
        u.tools["surface"] = 99;
        checked(u, withFlat);  // pinned, not in the library
        u = cover();
        u.curve1 = points({{5, 5, -1}, {35, 5, -20}, {65, 5, -1}}, false);
        u.tools["surface"] = 47;
        checked(u, balls);  // pinned, too large, no smaller one
        u.curve1 = cover().curve1;
        checked(u, std::vector<Tool>{ball(41, 2), ball(47, 200)});  // pinned, too large, a smaller one fits
        u.tools.clear();
        checked(u, none);  // no ball end mill at all
        // The reason of a choice, shown with the step's tool.
        const surfacemod::ToolPick pick = surfacemod::chooseTool(cover(), 30.0, "path 2, point 3 (X 1.000 Y 2.000 Z -3.000)",
                                                                 balls, LengthUnit::Millimetre);
        QVERIFY(pick.tool);
        english.push_back(pick.reason);

        // core/occt by itself.
        const surface::SpaceCurve line{{{0, 0, 0}, {10, 0, 0}}, true}, dot{{{0, 0, 0}}, true};
        const surface::SpaceCurve bent{{{0, 0, 0}, {5, 0, -2}, {10, 0, 0}}, true};
        failed(surface::spaceCurveFromProjections({surface::ProjectionPlane::XY, {{0, 0}, {1, 1}}, true},
                                                  {surface::ProjectionPlane::ZX, {{0, 0}, {1, 1}}, true}, 0.0), __LINE__);
        failed(surface::divideByLength(line, 0), __LINE__);
        failed(surface::divideByLength(dot, 2), __LINE__);
        failed(surface::piecesForStepOver(line, line, 0.0), __LINE__);
        failed(surface::piecesForStepOver(line, dot, 1.0), __LINE__);
        failed(surface::roughAndFinishSurfaces(line, line, 0, 4), __LINE__);
        failed(surface::roughAndFinishSurfaces(line, line, 4, 4), __LINE__);
        failed(surface::planeOf(surface::RuledSurface{{{0, 0, 0}}, {{0, 1, 0}}}, 1e-3), __LINE__);
        failed(surface::planeOf(*surface::ruledSurface(bent, surface::SpaceCurve{{{0, 10, 0}, {10, 10, 0}}, true}, 4),
                                1e-3), __LINE__);
        const std::string missing = dir_.filePath("missing.step").toStdString();
        const std::string nowhere = dir_.filePath("no/such/folder/out.step").toStdString();
        const std::string text = dir_.filePath("note.step").toStdString();
        const std::string bowlStep = dir_.filePath("bowl.step").toStdString();
        test::writeFile(QString::fromStdString(text), "not a STEP file\n");
        failed(surface::exportSurfaceStep({{{0, 0, 0}, {1, 0, 0}}}, nowhere), __LINE__);
        failed(surface::exportSurfaceStep({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}}}, nowhere), __LINE__);
        failed(surface::exportSurfaceStep(bowl(), nowhere), __LINE__);
        failed(surface::importStepFaces(missing, 0.01), __LINE__);
        failed(surface::importStepFaces(text, 0.01), __LINE__);
        QVERIFY(surface::exportSurfaceStep(bowl(), bowlStep).ok());
        failed(surface::sampleStepFaces(bowlStep, 0.0), __LINE__);
        failed(surface::sampleStepFaces(bowlStep, 0.01), __LINE__);  // too many points
        QVERIFY(english.size() >= 45);

        // The file, the format, the library, the figure's contours and the pin's key ("surface", as the job file has it).
        const QStringList quoted{QString::fromStdString(nowhere), QString::fromStdString(missing),
                                 QString::fromStdString(text), QString::fromStdString(bowlStep), "STEP", "OpenCASCADE", "K1", "K2", "K9", "\"surface\""};
        for (const char* language : {"ja", "zh"}) {
            speak(language);
            for (const std::string& e : english) {
                const QString shown = coreMessage(e);
                QVERIFY2(!e.empty() && englishWords(shown, quoted).isEmpty(),
                         qPrintable(QString(language) + ": " + QString::fromStdString(e) + "\n  → " + shown));
            }
        }
        // The control: English as it was written.
        speak("en");
        for (const std::string& e : english) QCOMPARE(coreMessage(e), QString::fromStdString(e));
    }
};

QTEST_MAIN(TestGuiSurfaceLanguages)
#include "test_gui_surface_languages.moc"
