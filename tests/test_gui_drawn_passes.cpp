// Area clearing by drawn passes in the station (QTest on the offscreen
// platform), on the sample area-drawn-passes.taiwa: the passes cleared and
// two passes drawn with the mouse in the Figure tab's view (each point one
// undo step, snapped to the 0.5 mm grid), the unit's points, the form's
// text and the planned step following them, the strips taking the paint
// away in the view's pixels and the unswept rest reported and outlined; a
// pass drawn into the boss refused in red, in the bar and in the form; and
// the corner revision of a chamfer (every chamfer highlighted, one picked,
// its length typed) as one undoable edit of that number only. With
// TAIWA_SCREENSHOTS_DIR set it writes docs/screenshots/station-drawn-passes.png.
#include "modules/area/area.h"
#include "modules/registry.h"
#include "support/gui_fields.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/figure_panel.h"
#include "ui/figure_view.h"
#include "ui/job_document.h"
#include "ui/passes_bar.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/unit_list_panel.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;
using taiwa::test::GuiFields;
using taiwa::test::settle;

namespace {

const char* const kSample = "resources/samples/area-drawn-passes.taiwa";

void open(StationWindow& w)
{
    w.resize(1600, 940);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    w.showFigure(true);
    w.unitList()->selectUnit(0);
    settle(w);
}

std::vector<Point2> drawnPoints(const StationWindow& w)
{
    const ModuleInput& m = w.document()->job().units[0].module;
    return moduleKind(m).drawnPasses(m)->points;
}

// A click in the view where the work point is drawn.
void clickAt(FigureView* view, Point2 p) { QTest::mouseClick(view, Qt::LeftButton, {}, view->toPixel(p).toPoint()); }

}  // namespace

class TestGuiDrawnPasses : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void drawTwoPasses()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        FigurePanel* panel = w.figurePanel();
        FigureView* view = panel->view();
        auto* bar = w.findChild<PassesBar*>("figure.passes");
        QVERIFY(bar && bar->isVisible());
        auto* draw = w.findChild<QToolButton*>("figure.drawPasses");
        auto* clear = w.findChild<QToolButton*>("figure.clearPasses");
        auto* text = w.findChild<QLabel*>("figure.passesText");
        QVERIFY(draw && clear && text);
        QCOMPARE(drawnPoints(w).size(), std::size_t{14});
        QVERIFY(text->text().startsWith("13 passes drawn. Unswept: "));

        QUndoStack* undo = w.document()->undoStack();
        const int before = undo->count();
        QTest::mouseClick(clear, Qt::LeftButton);
        QVERIFY(drawnPoints(w).empty());
        QCOMPARE(text->text(), QString("No pass drawn: press Draw passes and click where the tool starts."));
        QVERIFY(!clear->isEnabled());

        // Drawing: clicks add points instead of picking elements.
        QTest::mouseClick(draw, Qt::LeftButton);
        QVERIFY(draw->isChecked() && view->drawing());
        clickAt(view, {15.1, 14.9});  // snapped to the 0.5 mm grid
        QCOMPARE(text->text(), QString("The start point is drawn: click where the first pass ends."));
        clickAt(view, {105, 15});
        clickAt(view, {105, 15});  // a double click adds no empty pass
        clickAt(view, {104.9, 24.1});
        QCOMPARE(drawnPoints(w), (std::vector<Point2>{{15, 15}, {105, 15}, {105, 24}}));
        QCOMPARE(undo->count(), before + 4);  // the clear and three points
        QVERIFY(panel->selected().isEmpty());  // nothing was picked
        QVERIFY2(text->text().startsWith("2 passes drawn. Unswept: "), qPrintable(text->text()));
        QVERIFY(text->styleSheet().isEmpty());

        // The form shows the points; the plan follows them.
        QLineEdit* points = GuiFields::edit(w, "area.points");
        QVERIFY(points && points->isVisible());
        QCOMPARE(points->text(), QString("15, 15; 105, 15; 105, 24"));
        settle(w);
        const Plan& plan = *w.planRunner()->fullPlan();
        QVERIFY(plan.ok());
        QCOMPARE(plan.steps[0].payload.as<DrawnPoints>().points, drawnPoints(w));

        // The view: the strips white where the passes run, the paint left
        // elsewhere in the area, the rest outlined as unswept.
        QVERIFY(view->passes() && view->passes()->points.size() == 3 && !view->passes()->unswept.empty());
        const QImage image = view->grab().toImage();
        const auto colour = [&](Point2 p) { return image.pixelColor(view->toPixel(p).toPoint()); };
        const QColor strip = colour({60, 18}), paint = colour({40, 45});
        QVERIFY2(strip.red() > 240 && strip.green() > 240 && strip.blue() > 240, qPrintable(strip.name()));
        QVERIFY2(paint.red() > paint.green() + 40, qPrintable(paint.name()));

        // Undo takes back the last point.
        undo->undo();
        QCOMPARE(drawnPoints(w).size(), std::size_t{2});
        QCOMPARE(text->text().left(14), QString("1 pass drawn. "));
        undo->redo();

        // A pass into the boss: refused in red, in the bar and in the form.
        clickAt(view, {80, 24});
        clickAt(view, {80, 40});
        QVERIFY2(text->text().contains("Pass 4 leaves the area."), qPrintable(text->text()));
        QVERIFY(!text->styleSheet().isEmpty());
        settle(w);
        QLabel* message = GuiFields::label(w, "area.points");
        QVERIFY(message->isVisible());
        QVERIFY2(message->text().startsWith("pass 4 takes the tool's edge 13 mm outside the area K1"), qPrintable(message->text()));
        undo->undo();
        settle(w);
        QVERIFY2(GuiFields::label(w, "area.points")->text().startsWith("the passes leave "),  // the warning again
                 qPrintable(GuiFields::label(w, "area.points")->text()));

        // Drawing off: a click picks again.
        QTest::mouseClick(draw, Qt::LeftButton);
        QVERIFY(!view->drawing());
        const std::size_t count = drawnPoints(w).size();
        clickAt(view, {80, 40});
        QCOMPARE(drawnPoints(w).size(), count);

        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (out.isEmpty()) return;
        undo->undo();  // the sample's passes again, for the picture
        while (drawnPoints(w).size() != 14 && undo->canUndo()) undo->undo();
        settle(w);
        QDir().mkpath(out);
        QVERIFY(w.grab().toImage().save(QDir(out).filePath("station-drawn-passes.png")));
    }

    // Corner revision of a chamfer: the area's corners chamfered instead of
    // rounded, every chamfer highlighted, one picked and its length typed.
    void reviseAChamfer()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        Job job = w.document()->job();
        const std::string rounded = "K1 = CONTOUR/L1, ROUND, 5, L2, ROUND, 5, L3, ROUND, 5, L4, ROUND, 5";
        const auto at = job.figure.find(rounded);
        QVERIFY(at != std::string::npos);
        job.figure.replace(at, rounded.size(), "K1 = CONTOUR/L1, CHAMF, 4, L2, ROUND, 5, L3, CHAMF, 2.5, L4, ROUND, 5");
        w.document()->edit(job, "chamfers");
        settle(w);
        FigurePanel* panel = w.figurePanel();
        const std::string before = w.document()->job().figure;
        auto* chamfer = w.findChild<QToolButton*>("figure.reviseChamfer");
        QTest::mouseClick(chamfer, Qt::LeftButton);
        QVERIFY(chamfer->isChecked());
        QCOMPARE(panel->view()->highlightedCorners().size(), std::size_t{2});
        const figure::EvaluatedContour* k1 = panel->evaluation().findContour("K1");
        QVERIFY(k1 && k1->corners.size() == 4);
        const ContourSegment& cut = k1->contour.segments[static_cast<std::size_t>(k1->corners[2].segment)];
        QVERIFY(!cut.isArc());
        QTest::mouseClick(panel->view(), Qt::LeftButton, {}, panel->view()->toPixel(cut.at(0.5)).toPoint());
        QCOMPARE(panel->view()->highlightedCorners(), (std::vector<CornerRef>{{"K1", 2}}));
        auto* value = w.findChild<QDoubleSpinBox*>("figure.cornerValue");
        QVERIFY(value->isEnabled());
        QCOMPARE(value->value(), 2.5);
        QVERIFY(w.findChild<QLabel*>("figure.revisionText")->text().startsWith("K1: chamfer between L3 and L4"));
        const int steps = w.document()->undoStack()->count();
        value->setFocus();
        value->selectAll();
        QTest::keyClicks(value, "3");
        QTest::keyClick(value, Qt::Key_Return);
        std::string expected = before;
        expected.replace(expected.find("CHAMF, 2.5"), 10, "CHAMF, 3");
        QCOMPARE(w.document()->job().figure, expected);
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
        // The chamfer's cut is 3 long on each side of the corner: its chord
        // 3·√2 in the rectangle's right-angled corner.
        const figure::EvaluatedContour* after = panel->evaluation().findContour("K1");
        const ContourSegment& cut3 = after->contour.segments[static_cast<std::size_t>(after->corners[2].segment)];
        QVERIFY(std::abs(distance(cut3.start, cut3.end) - 3 * std::sqrt(2.0)) < 1e-9);
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job().figure, before);
    }
};

QTEST_MAIN(TestGuiDrawnPasses)
#include "test_gui_drawn_passes.moc"
