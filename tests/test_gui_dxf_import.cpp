// DXF import in the station (QTest on the offscreen platform): a drawing
// written by the test — an outline of lines and an arc on layer OUTLINE, a
// circle on HOLES, an open chain on OPEN with a 0.2 mm gap — read by the
// dialog with every layer ticked, its report (closed and open contours, the
// gap with its position), the figure text named past the job's own names;
// a layer unticked and the gap tolerance widened read the drawing again;
// Import appends the text to the job's figure as one undo step, the Figure
// tab draws the new contours, and a CP unit can name one of them. An inch
// job gets the text in inches.
#include "figure/figure_eval.h"
#include "figure/figure_text.h"
#include "modules/registry.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/dxf_import_dialog.h"
#include "ui/figure_panel.h"
#include "ui/job_document.h"
#include "ui/station_window.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

std::string line(const char* layer, double x1, double y1, double x2, double y2)
{
    return "0\nLINE\n8\n" + std::string(layer) + "\n10\n" + std::to_string(x1) + "\n20\n" + std::to_string(y1) +
           "\n30\n0\n11\n" + std::to_string(x2) + "\n21\n" + std::to_string(y2) + "\n31\n0\n";
}

// A 100 × 60 outline with its top right corner rounded (R20) at (10, 10),
// a circle on HOLES, and on OPEN two lines 0.2 mm apart.
std::string drawing()
{
    return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" +
           line("OUTLINE", 10, 10, 110, 10) + line("OUTLINE", 110, 10, 110, 50) +
           "0\nARC\n8\nOUTLINE\n10\n90\n20\n50\n30\n0\n40\n20\n50\n0\n51\n90\n" + line("OUTLINE", 90, 70, 10, 70) +
           line("OUTLINE", 10, 70, 10, 10) + "0\nCIRCLE\n8\nHOLES\n10\n60\n20\n40\n30\n0\n40\n5\n" +
           line("OPEN", 0, 100, 50, 100) + line("OPEN", 50.2, 100, 80, 120) + "0\nENDSEC\n0\nEOF\n";
}

QListWidgetItem* layer(DxfImportDialog& d, const QString& name)
{
    const auto items = d.findChild<QListWidget*>("dxf.layers")->findItems(name, Qt::MatchExactly);
    return items.isEmpty() ? nullptr : items.front();
}

}  // namespace

class TestGuiDxfImport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        test::writeFile(dir_.filePath("part.dxf"), drawing());
    }

    void importIntoTheFigure()
    {
        StationWindow w(test::sourcePath("resources/samples/cp-islands.taiwa"));
        w.show();
        test::settle(w);
        const std::string before = w.document()->job().figure;
        DxfImportDialog d(w.document()->job(), &w);
        d.setPath(dir_.filePath("part.dxf"));
        auto* import = d.findChild<QDialogButtonBox*>("dxf.buttons")->button(QDialogButtonBox::Ok);
        QCOMPARE(d.findChild<QListWidget*>("dxf.layers")->count(), 3);
        QVERIFY(layer(d, "OUTLINE") && layer(d, "HOLES") && layer(d, "OPEN"));
        QVERIFY2(d.report().startsWith("2 closed and 2 open contours, drawn in mm."), qPrintable(d.report()));
        QVERIFY2(d.report().contains("Gap: "), qPrintable(d.report()));
        QVERIFY2(d.report().contains("Gap: gap of 0.2 mm at (50.000, 100.000)"), qPrintable(d.report()));
        QVERIFY(import->isEnabled());
        // Named past the sample's P1..P6, L1..L7, C1, C2, K1..K3.
        const auto names = figure::parseFigure(d.figureText()).definitions;
        QVERIFY(!names.empty());
        for (const auto& def : names)
            QVERIFY2(before.find("\n" + def.name + " =") == std::string::npos, def.name.c_str());

        // OPEN unticked: two closed contours; a wider tolerance joins the gap.
        layer(d, "OPEN")->setCheckState(Qt::Unchecked);
        QVERIFY2(d.report().startsWith("2 closed and 0 open contours"), qPrintable(d.report()));
        QVERIFY(!d.report().contains("Gap: "));
        layer(d, "OPEN")->setCheckState(Qt::Checked);
        d.findChild<QDoubleSpinBox*>("dxf.gap")->setValue(0.3);
        QVERIFY2(d.report().startsWith("2 closed and 1 open contours"), qPrintable(d.report()));
        layer(d, "OPEN")->setCheckState(Qt::Unchecked);

        // Import: one undo step; the figure evaluates with the new contours.
        const int steps = w.document()->undoStack()->count();
        w.replaceFigure(d.appendedTo(before), "Import DXF contours");
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
        const std::string after = w.document()->job().figure;
        QVERIFY(after.starts_with(before));
        const figure::Evaluation e = figure::evaluate(figure::parseFigure(after).definitions);
        QVERIFY(e.errors.empty());
        QCOMPARE(e.contours.size(), std::size_t{5});  // K1..K3 and the drawing's two
        const figure::EvaluatedContour& outline = e.contours[3];
        QVERIFY(outline.contour.closed);
        QVERIFY(std::abs(area(Region{outline.contour, {}}) - (100 * 60 - 400 + 100 * 3.14159265358979)) < 1e-3);
        QVERIFY(w.figurePanel()->isVisible());
        QCOMPARE(w.figurePanel()->evaluation().contours.size(), std::size_t{5});
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job().figure, before);
    }

    void inchJobGetsInches()
    {
        StationWindow w(test::sourcePath("resources/samples/bracket-inch.taiwa"));
        w.show();
        test::settle(w);
        DxfImportDialog d(w.document()->job(), &w);
        d.setPath(dir_.filePath("part.dxf"));
        layer(d, "OPEN")->setCheckState(Qt::Unchecked);
        layer(d, "OUTLINE")->setCheckState(Qt::Unchecked);
        // The circle at (60, 40) mm of radius 5 mm, in inches.
        const figure::Evaluation e = figure::evaluate(figure::parseFigure(d.figureText()).definitions);
        QCOMPARE(e.contours.size(), std::size_t{1});
        const ContourSegment& c = e.contours[0].contour.segments.front();
        QVERIFY(std::abs(c.radius() - 5 / 25.4) < 1e-6);
        QVERIFY(distance(c.centre, {60 / 25.4, 40 / 25.4}) < 1e-6);
    }
};

QTEST_MAIN(TestGuiDxfImport)
#include "test_gui_dxf_import.moc"
