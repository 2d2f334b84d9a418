// Figure elements in the station (QTest on the offscreen platform), on the
// sample cp-islands.taiwa: a contour built from new points and lines typed
// into the figure editor with the keyboard (one undo step), drawn in the
// 2-D view, and a typo's "line:column" refusal listed and marked, a click on
// it moving the cursor there; elements and contours picked with the mouse in
// the view, their statements selected in the editor; a rounding revised
// (every rounding highlighted, one clicked, its radius typed) as one
// undoable edit that changes only that number of the text; the CP form's
// outline and islands fields, and the check's message on an unknown name.
// The panel at 1280 x 720 keeps its editor and view usable. With
// TAIWA_SCREENSHOTS_DIR set it writes docs/screenshots/station-figure.png.
#include "modules/registry.h"
#include "support/gui_fields.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/figure_panel.h"
#include "ui/figure_view.h"
#include "ui/job_document.h"
#include "ui/station_window.h"
#include "ui/unit_list_panel.h"

#include <QCompleter>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;
using taiwa::test::GuiFields;
using taiwa::test::settle;

namespace {

const char* const kSample = "resources/samples/cp-islands.taiwa";

// The station on the sample with the figure tab shown, active for the keyboard.
void open(StationWindow& w, QSize size = {1600, 940})
{
    w.resize(size);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.showFigure(true);
    QVERIFY(w.figurePanel() && w.figurePanel()->isVisible());
    QCoreApplication::sendPostedEvents();
}

// Where the middle of segment `segment` of contour `name` is drawn.
QPoint middleOf(FigurePanel* panel, const char* name, int segment)
{
    const figure::EvaluatedContour* c = panel->evaluation().findContour(name);
    if (!c) return {};
    const ContourSegment& s = c->contour.segments[static_cast<std::size_t>(segment)];
    return panel->view()->toPixel(s.at(0.5)).toPoint();
}

}  // namespace

class TestGuiFigure : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    // (a) A triangle typed statement by statement after the sample's text.
    void buildAContourWithTheKeyboard()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        FigurePanel* panel = w.figurePanel();
        QPlainTextEdit* editor = w.findChild<QPlainTextEdit*>("figure.text");
        QVERIFY(editor && editor->isVisible());
        const std::string before = w.document()->job().figure;
        QCOMPARE(editor->toPlainText().toStdString(), before);
        QVERIFY(panel->refusals().empty());
        QCOMPARE(panel->evaluation().contours.size(), std::size_t(3));
        const int undoSteps = w.document()->undoStack()->count();

        editor->setFocus();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClick(editor, Qt::Key_Return);
        const char* statements[] = {"P7 = POINT/96, 64", "P8 = POINT/114, 64", "L8 = LINE/P7, P8",
                                    "L9 = LINE/P8, ATANGL, 120", "L10 = LINE/P7, ATANGL, 60", "K4 = CONTOUR/L8, L9, L10"};
        for (const char* s : statements) {
            QTest::keyClicks(editor, s);
            QTest::keyClick(editor, Qt::Key_Return);
        }
        const std::string typed = w.document()->job().figure;
        QVERIFY(typed.rfind(before + "\nP7 = POINT/96, 64\nP8 = POINT/114, 64\n", 0) == 0);
        QVERIFY(typed.find("\nK4 = CONTOUR/L8, L9, L10\n") != std::string::npos);
        QCOMPARE(w.document()->undoStack()->count(), undoSteps + 1);  // one visit, one undo step
        QVERIFY2(panel->refusals().empty(), panel->refusals().empty() ? "" : panel->refusals()[0].text().c_str());
        QCOMPARE(panel->refusalList()->count(), 0);
        // The triangle evaluated: closed, three sides, the base from P7 to P8.
        const figure::EvaluatedContour* k4 = panel->evaluation().findContour("K4");
        QVERIFY(k4);
        QVERIFY(k4->contour.closed);
        QCOMPARE(k4->contour.segments.size(), std::size_t(3));
        QCOMPARE(k4->elements[0], std::string("L8"));
        // ... and drawn: the base's middle in the contours' dark blue.
        FigureView* view = panel->view();
        QVERIFY(view->selected().isEmpty());  // the cursor is on the empty last line
        const QImage image = view->grab().toImage();
        const QPoint base = view->toPixel({105, 64}).toPoint();
        QVERIFY(view->rect().contains(base));
        const QColor c = image.pixelColor(base);
        QVERIFY2(c.blue() > c.red() + 30 && c.red() < 90, qPrintable(c.name()));
        QCOMPARE(view->elementAt(base), QString("K4"));

        // A typo: its refusal listed as line:column, its line marked.
        QTest::keyClicks(editor, "P10 = PIONT/1, 2");
        const int line = editor->textCursor().blockNumber() + 1;
        QCOMPARE(panel->refusals().size(), std::size_t(1));
        const QString refusal =
            QStringLiteral("%1:7: expected POINT, LINE, CIRCLE or CONTOUR after '=', found 'PIONT'").arg(line);
        QCOMPARE(QString::fromStdString(panel->refusals()[0].text()), refusal);
        QListWidget* list = w.findChild<QListWidget*>("figure.refusals");
        QVERIFY(list && list->isVisible());
        QCOMPARE(list->count(), 1);
        QCOMPARE(list->item(0)->text(), refusal);
        bool underlined = false;
        for (const QTextEdit::ExtraSelection& s : editor->extraSelections())
            if (s.cursor.blockNumber() == line - 1 && s.format.underlineStyle() == QTextCharFormat::WaveUnderline)
                underlined = s.cursor.selectedText() == "PIONT";
        QVERIFY(underlined);
        // What is before the typo is still drawn.
        QVERIFY(panel->evaluation().findContour("K4"));
        // A click on the refusal: the cursor at its line and column.
        editor->moveCursor(QTextCursor::Start);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(0)).center());
        QCOMPARE(editor->textCursor().blockNumber(), line - 1);
        QCOMPARE(editor->textCursor().positionInBlock(), 6);
        QVERIFY(editor->hasFocus());

        // Undo: the text as it was, in the editor too.
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job().figure, before);
        QCOMPARE(editor->toPlainText().toStdString(), before);
        QVERIFY(!panel->evaluation().findContour("K4"));
    }

    // (b) Picking in the view selects the statement in the editor.
    void pickElementsInTheView()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        FigurePanel* panel = w.figurePanel();
        FigureView* view = w.findChild<FigureView*>("figure.view");
        QVERIFY(view && view->isVisible());
        QPlainTextEdit* editor = panel->editor();
        QSignalSpy picked(panel, &FigurePanel::selectionChanged);
        const struct {
            Point2 at;
            const char* name;
            const char* statement;
        } picks[] = {
            {{35, 35}, "P4", "P4 = POINT/35, 35"},  // the island's centre
            {{100, 28}, "L4", "L4 = LINE/P5, P6"},  // the line beyond the square island
            {{82, 28}, "K3", "K3 = CONTOUR/L4, ROUND, 3, L5, ROUND, 3, L6, ROUND, 3, L7, ROUND, 3"},  // on the island
            {{35, 43}, "K2", "K2 = CONTOUR/CLW, C2"},
        };
        for (const auto& p : picks) {
            QTest::mouseClick(view, Qt::LeftButton, {}, view->toPixel(p.at).toPoint());
            QCOMPARE(view->selected(), QString(p.name));
            QCOMPARE(panel->selected(), QString(p.name));
            QCOMPARE(editor->textCursor().selectedText(), QString(p.statement));
            QCOMPARE(picked.last().at(0).toString(), QString(p.name));
        }
        // Nothing near: nothing picked.
        QTest::mouseClick(view, Qt::LeftButton, {}, view->toPixel({60, 45}).toPoint());
        QVERIFY(view->selected().isEmpty());
        // The cursor put on a statement picks its element.
        QTextCursor c(editor->document()->findBlockByNumber(6));  // C1 = CIRCLE/...
        editor->setTextCursor(c);
        QCOMPARE(view->selected(), QString("C1"));
        QCOMPARE(picked.last().at(0).toString(), QString("C1"));
        // The wheel zooms about the pointer: the point under it stays, and
        // (35, 35), a fraction of a pixel from it, moves 1.2 times as far.
        const QPointF exact = view->toPixel({35, 35});
        const QPoint at = exact.toPoint();
        QWheelEvent wheel(at, view->mapToGlobal(at), {}, {0, 120}, Qt::NoButton, {}, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(view, &wheel);
        QVERIFY(view->zoom() > 1.1);
        QVERIFY((view->toPixel({35, 35}) - (QPointF(at) + 1.2 * (exact - QPointF(at)))).manhattanLength() < 1e-6);
        // A drag pans, and picks nothing.
        const QPointF before = view->toPixel({35, 35});
        QTest::mousePress(view, Qt::LeftButton, {}, at);
        QTest::mouseMove(view, at + QPoint(40, 10));
        QTest::mouseRelease(view, Qt::LeftButton, {}, at + QPoint(40, 10));
        QVERIFY((view->toPixel({35, 35}) - before - QPointF(40, 10)).manhattanLength() < 1.0);
    }

    // (c) The corner revision of a rounding as one undoable edit.
    void reviseARounding()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        FigurePanel* panel = w.figurePanel();
        FigureView* view = panel->view();
        const std::string before = w.document()->job().figure;
        auto* rounding = w.findChild<QToolButton*>("figure.reviseRounding");
        QVERIFY(rounding && rounding->isVisible() && rounding->isCheckable());
        QTest::mouseClick(rounding, Qt::LeftButton);
        QVERIFY(rounding->isChecked());
        QCOMPARE(view->highlightedCorners().size(), std::size_t(8));  // K1's four and K3's four
        QVERIFY(w.findChild<QWidget*>("figure.revision")->isVisible());
        auto* value = w.findChild<QDoubleSpinBox*>("figure.cornerValue");
        QVERIFY(value && !value->isEnabled());
        // K1's first corner, ROUND 8 between L1 and L2: its arc clicked.
        const figure::EvaluatedContour* k1 = panel->evaluation().findContour("K1");
        QVERIFY(k1);
        QTest::mouseClick(view, Qt::LeftButton, {}, middleOf(panel, "K1", k1->corners[0].segment));
        QCOMPARE(view->highlightedCorners(), (std::vector<CornerRef>{{"K1", 0}}));
        QVERIFY(value->isEnabled());
        QCOMPARE(value->value(), 8.0);
        QCOMPARE(value->text(), QString("8 mm"));
        QCOMPARE(panel->editor()->textCursor().selectedText(), QString("8"));  // the number revised, in K1's statement
        QCOMPARE(panel->editor()->textCursor().blockNumber(), 8);
        QVERIFY(w.findChild<QLabel*>("figure.revisionText")->text().startsWith("K1: rounding between L1 and L2"));
        // The radius typed: 10.
        const int steps = w.document()->undoStack()->count();
        value->setFocus();
        value->selectAll();
        QTest::keyClicks(value, "10");
        QTest::keyClick(value, Qt::Key_Return);
        std::string expected = before;
        const std::size_t at = expected.find("L1, ROUND, 8, L2");
        QVERIFY(at != std::string::npos);
        expected.replace(at, 16, "L1, ROUND, 10, L2");
        QCOMPARE(w.document()->job().figure, expected);  // that number only
        QCOMPARE(panel->editor()->toPlainText().toStdString(), expected);
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
        QCOMPARE(panel->evaluation().findContour("K1")->corners[0].value, 10.0);
        QCOMPARE(view->highlightedCorners(), (std::vector<CornerRef>{{"K1", 0}}));  // still the one picked
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job().figure, before);
        QCOMPARE(value->value(), 8.0);
        w.document()->undoStack()->redo();
        QCOMPARE(w.document()->job().figure, expected);
        // Chamfers instead: the sample has none; off again: nothing highlighted.
        QTest::mouseClick(w.findChild<QToolButton*>("figure.reviseChamfer"), Qt::LeftButton);
        QVERIFY(!rounding->isChecked());
        QVERIFY(view->highlightedCorners().empty());
        QTest::mouseClick(w.findChild<QToolButton*>("figure.reviseChamfer"), Qt::LeftButton);
        QVERIFY(!w.findChild<QWidget*>("figure.revision")->isVisible());
    }

    // (d) The CP form names the contours; an unknown name gets the check's message.
    void outlineAndIslandsInTheForm()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        w.unitList()->selectUnit(0);
        settle(w);
        QLineEdit* outline = GuiFields::edit(w, "cp.outline");
        QLineEdit* islands = GuiFields::edit(w, "cp.islands");
        QVERIFY(outline && islands && outline->isVisible());
        QCOMPARE(outline->text(), QString("K1"));
        QCOMPARE(islands->text(), QString("K2, K3"));
        QVERIFY(outline->completer());
        QCOMPARE(outline->completer()->model()->rowCount(), 3);  // K1, K2, K3
        QVERIFY(!GuiFields::label(w, "cp.outline")->isVisible());

        GuiFields::retype(outline, "K9");
        const auto& cp = w.document()->job().units[0].module;
        QCOMPARE(moduleKind(cp).fields()[0].getText(cp), std::string("K9"));
        settle(w);
        QLabel* message = GuiFields::label(w, "cp.outline");
        QVERIFY(message->isVisible());
        QCOMPARE(message->text(), QString("K9 is not a contour of the job's figure elements (its contours: K1, K2, K3)"));
        QVERIFY(GuiFields::isRed(outline));
        w.document()->undoStack()->undo();
        QCOMPARE(outline->text(), QString("K1"));
        settle(w);
        QVERIFY(!GuiFields::label(w, "cp.outline")->isVisible());

        // Islands typed with blanks: the names, kept as typed.
        GuiFields::retype(islands, "K3 K2");
        const auto& after = w.document()->job().units[0].module;
        QCOMPARE(moduleKind(after).fields()[1].getText(after), std::string("K3, K2"));
        QCOMPARE(islands->text(), QString("K3 K2"));
        settle(w);
        QVERIFY(!GuiFields::label(w, "cp.islands")->isVisible());
    }

    // At 1280 x 720 the editor and the view keep a usable size; the figure
    // tab is not offered for a lathe job.
    void smallScreenAndLathe()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w, {1280, 720});
        QVERIFY2(w.figurePanel()->editor()->width() >= 180 && w.figurePanel()->editor()->height() >= 100,
                 qPrintable(QStringLiteral("%1x%2").arg(w.figurePanel()->editor()->width()).arg(w.figurePanel()->editor()->height())));
        QVERIFY2(w.figurePanel()->view()->width() >= 240 && w.figurePanel()->view()->height() >= 150,
                 qPrintable(QStringLiteral("%1x%2").arg(w.figurePanel()->view()->width()).arg(w.figurePanel()->view()->height())));
        QVERIFY(w.fileActions()->openPath(test::sourcePath("resources/samples/lathe-shaft-grinding.taiwa")));
        QVERIFY(!w.figurePanel()->isVisible());
    }

    void screenshot()
    {
        StationWindow w(test::sourcePath(kSample));
        open(w);
        w.unitList()->selectUnit(0);
        settle(w);
        FigurePanel* panel = w.figurePanel();
        QTest::mouseClick(w.findChild<QToolButton*>("figure.reviseRounding"), Qt::LeftButton);
        const figure::EvaluatedContour* k3 = panel->evaluation().findContour("K3");
        QVERIFY(k3);
        QTest::mouseClick(panel->view(), Qt::LeftButton, {}, middleOf(panel, "K3", k3->corners[1].segment));
        QCOMPARE(panel->view()->highlightedCorners(), (std::vector<CornerRef>{{"K3", 1}}));
        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (out.isEmpty()) return;
        QDir().mkpath(out);
        QVERIFY(w.grab().toImage().save(QDir(out).filePath("station-figure.png")));
    }
};

QTEST_MAIN(TestGuiFigure)
#include "test_gui_figure.moc"
