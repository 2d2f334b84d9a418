// The station window end to end on the offscreen platform: adding an M4 unit
// from the palette, typing its form with the keyboard (Tab and Enter), live
// checks (checkJob messages and "not a number"), the step list, code combo
// boxes, undo/redo (one step per field), the NC view <-> step mapping, and
// the save/open round trip, unit conversion, technology and tool library dialogs. Its
// behaviour between edits is in test_gui_station_behaviour.cpp.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "export/export.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "support/gui_fields.h"
#include "support/support.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/length_units.h"
#include "ui/nc_view.h"
#include "ui/number_text.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_list_panel.h"
#include "ui/technology_dialog.h"
#include "ui/tool_library_dialog.h"
#include "ui/core_texts.h"
#include "tools/tool_library.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QListWidget>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QUndoStack>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiStation : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    using Fields = test::GuiFields;
    static QLineEdit* edit(QWidget& w, const QString& name) { return Fields::edit(w, name); }
    static QLabel* label(QWidget& w, const QString& name) { return Fields::label(w, name); }
    static void retype(QLineEdit* e, const QString& text) { Fields::retype(e, text); }
    static bool isRed(QWidget* e) { return Fields::isRed(e); }

private slots:
    // Times as the operator reads a clock, in the step table too.
    void timesAreShownAsMinutesAndSeconds()
    {
        QCOMPARE(clockTime(0), QString("0:00"));
        QCOMPARE(clockTime(0.42), QString("0:25"));
        QCOMPARE(clockTime(12.0833), QString("12:05"));
        QCOMPARE(clockTime(62.5), QString("1:02:30"));
        StepTable table;
        const Plan plan = planJob(*readJobFile(test::sourcePath("resources/samples/m4-standard.taiwa").toStdString()).job,
                                  TechnologyTable::builtIn(), defaultToolLibrary());
        table.setPlan(std::make_shared<const Plan>(plan));
        QCOMPARE(table.horizontalHeaderItem(StepTable::Time)->text(), QString("Time"));
        QCOMPARE(table.item(1, StepTable::Time)->text(), clockTime(*plan.steps[1].minutes));
        QVERIFY(table.item(1, StepTable::Time)->text().contains(':'));
    }
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void editCheckPlanUndoSaveOpen()
    {
        StationWindow w;
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.document()->job().units.empty());
        QVERIFY(!w.windowTitle().contains('*'));

        auto* add = w.findChild<QAbstractButton*>("unit.addM4");
        QVERIFY(add);
        QTest::mouseClick(add, Qt::LeftButton);
        QCOMPARE(w.document()->job().units.size(), std::size_t(1));
        QVERIFY(w.windowTitle().contains('*'));

        // The whole form with the keyboard: type, Tab to the next field.
        const QStringList names{"m4.P1.x", "m4.P1.y", "m4.P2.x", "m4.P2.y", "m4.P3.x",
                                "m4.P3.y", "m4.P4.x", "m4.P4.y", "m4.r1", "m4.depth"};
        const QStringList values{"10", "10", "70", "10", "70", "50", "10", "50", "8", "9"};
        edit(w, names[0])->setFocus();
        for (int i = 0; i < names.size(); ++i) {
            auto* e = qobject_cast<QLineEdit*>(QApplication::focusWidget());
            QVERIFY2(e, qPrintable(names[i]));
            QCOMPARE(e->objectName(), names[i]);
            e->selectAll();
            QTest::keyClicks(e, values[i]);
            QTest::keyClick(e, Qt::Key_Tab);
        }
        const auto& m4 = (w.document()->job().units[0].module).as<M4Pocket>();
        QCOMPARE(m4.corners[2].x, 70.0);
        QCOMPARE(m4.corners[3].y, 50.0);
        QCOMPARE(m4.cornerRadius, 8.0);
        QCOMPARE(m4.depth, 9.0);
        QVERIFY(w.stepTable()->rowCount() > 0);

        // depth 0: refused by checkJob; its message is shown under the field.
        QLineEdit* depth = edit(w, "m4.depth");
        retype(depth, "0");
        QVERIFY(isRed(depth));
        const Diagnostics ds = checkJob(w.document()->job(), TechnologyTable::builtIn(), w.planRunner()->library());
        auto it = std::find_if(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.field == "depth"; });
        QVERIFY(it != ds.end());
        QVERIFY(label(w, "m4.depth")->isVisible());
        QVERIFY2(label(w, "m4.depth")->text().contains(QString::fromStdString(it->message)),
                 qPrintable(label(w, "m4.depth")->text()));
        QCOMPARE(w.stepTable()->rowCount(), 0);

        // Not a number: kept as typed, red, "not a number".
        retype(depth, "12,5x");
        QCOMPARE(depth->text(), QString("12,5x"));
        QVERIFY(isRed(depth));
        QCOMPARE(label(w, "m4.depth")->text(), QString("not a number"));

        // Fixed: not red, the steps of U=1 F=1 H=0.
        retype(depth, "12.5");
        QVERIFY(!isRed(depth));
        QVERIFY(!label(w, "m4.depth")->isVisible());
        QCOMPARE(depth->text(), QString("12.5"));
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().depth, 12.5);
        QCOMPARE(w.stepTable()->stepLabels(),
                 QStringList({"Pilot hole", "Roughing I", "Floor finishing I", "Wall finishing I"}));

        // Undo (Ctrl+Z in the field) goes back to the depth before the typing; redo re-applies.
        QTest::keyClick(depth, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().depth, 9.0);
        QCOMPARE(depth->text(), QString("9"));
        QTest::keyClick(depth, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().depth, 12.5);
        QCOMPARE(depth->text(), QString("12.5"));
        // One undo step per field edit: adding the unit, the five fields typed
        // with a value other than the new unit's (P2.x, P3.x, P3.y, P4.y,
        // depth), and the retyping of depth ("0", "12,5x", "12.5" without
        // leaving the field) as one more.
        QCOMPARE(w.document()->undoStack()->count(), 7);
        QVERIFY(w.document()->undoStack()->text(6).contains("T (depth)"));

        // A code from its combo box with the keyboard: U = 9 (roughing only).
        auto* u = w.findChild<QComboBox*>("m4.U");
        QVERIFY(u);
        QVERIFY(u->currentText().startsWith("1"));
        u->setFocus();
        QTest::keyClick(u, Qt::Key_End);
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().toolUse, 9);
        QCOMPARE(w.stepTable()->stepLabels(), QStringList({"Pilot hole", "Roughing I"}));
        QTest::keyClick(u, Qt::Key_Return);  // Enter moves on, as Tab does
        QCOMPARE(QApplication::focusWidget()->objectName(), QString("m4.F"));
        w.document()->undoStack()->undo();
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().toolUse, 1);
        QCOMPARE(u->currentData().toInt(), 1);

        // The NC program: putting the cursor on a line posted from a step names
        // that step's move (for the preview); selectMove() finds the line back.
        w.planRunner()->flush();
        QPlainTextEdit* nc = w.ncView()->text();
        QVERIFY(nc->toPlainText().size() > 100);
        QSignalSpy moves(w.ncView(), &NcView::moveSelected);
        const QStringList ncLines = nc->toPlainText().split('\n');
        int cutLine = -1;
        for (int i = 0; i < ncLines.size() && cutLine < 0; ++i)
            if (ncLines[i].contains(QRegularExpression("(^|\\s)G1\\s"))) cutLine = i;
        QVERIFY(cutLine > 0);
        nc->setTextCursor(QTextCursor(nc->document()->findBlockByNumber(cutLine)));
        QCOMPARE(moves.count(), 1);
        const int step = moves[0][0].toInt(), move = moves[0][1].toInt();
        QVERIFY(step >= 0 && move >= 0);
        nc->setTextCursor(QTextCursor(nc->document()->findBlockByNumber(0)));
        QVERIFY(w.ncView()->selectMove(step, move));
        QCOMPARE(nc->textCursor().blockNumber(), cutLine);

        // Selecting a step in the list tells the preview and shows its numbers.
        QSignalSpy steps(w.stepPanel(), &StepPanel::stepSelected);
        QTest::mouseClick(w.stepTable()->viewport(), Qt::LeftButton, {},
                          w.stepTable()->visualItemRect(w.stepTable()->item(1, 2)).center());
        QCOMPARE(w.stepPanel()->selectedStep(), 1);
        QCOMPARE(steps.count(), 1);
        QCOMPARE(steps[0][0].toInt(), 1);
        QVERIFY2(w.findChild<QLabel*>("step.details")->text().contains("Roughing I"),
                 qPrintable(w.findChild<QLabel*>("step.details")->text()));

        // Save, open in a new window: the same job.
        const QString path = dir_.filePath("saved.taiwa");
        QVERIFY(w.fileActions()->saveTo(path));
        QVERIFY(!w.windowTitle().contains('*'));
        QVERIFY(w.windowTitle().contains("saved.taiwa"));
        StationWindow w2(path);
        QVERIFY(w2.document()->job() == w.document()->job());
        QCOMPARE(edit(w2, "m4.depth")->text(), QString("12.5"));
        QVERIFY(!w2.document()->isModified());
    }

    void enterMovesToTheNextField()
    {
        StationWindow w;
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        QLineEdit* x = edit(w, "m4.P1.x");
        x->setFocus();
        x->selectAll();
        QTest::keyClicks(x, "12");
        QTest::keyClick(x, Qt::Key_Return);
        QCOMPARE(QApplication::focusWidget(), edit(w, "m4.P1.y"));
        // r1 too big for the 50 x 30 pocket: red, with checkJob's message.
        QLineEdit* r1 = edit(w, "m4.r1");
        retype(r1, "20");
        QVERIFY(isRed(r1));
        QVERIFY2(label(w, "m4.r1")->text().contains("half"), qPrintable(label(w, "m4.r1")->text()));
        QCOMPARE(w.stepTable()->rowCount(), 0);
    }

    void inchSwitchConvertsEveryLength()
    {
        StationWindow w;
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        const Job mm = w.document()->job();
        auto* units = w.findChild<QComboBox*>("job.unit");
        QVERIFY(units);
        units->setFocus();
        QTest::keyClick(units, Qt::Key_Down);  // mm -> inch
        const Job& in = w.document()->job();
        QCOMPARE(in.lengthUnit, LengthUnit::Inch);
        QCOMPARE((in.units[0].module).as<M4Pocket>().corners[1].x, 60 / 25.4);  // exact, not rounded
        QCOMPARE(in.stock.width, mm.stock.width / 25.4);
        QCOMPARE(edit(w, "m4.depth")->text(), QString("0.393701"));  // rounded for display only
        QTest::keyClick(units, Qt::Key_Up);  // back to mm: the values typed come back
        QCOMPARE(w.document()->job(), mm);
        w.document()->undoStack()->undo();
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job(), mm);
    }

    void unitSwitchKeepsThePlan()
    {
        // Converting plate.taiwa to inch must not change what the machine cuts:
        // r1 6 mm once became 0.23622 in (5.99999 mm) and the 12 mm end mill was
        // no longer chosen. Same steps, tools and depths; back in mm, the same job.
        const Job mm = *readJobFile(test::sourcePath("resources/samples/plate.taiwa").toStdString()).job;
        const Job in = convertLengthUnit(mm, LengthUnit::Inch);
        const auto lib = defaultToolLibrary();
        PlanOptions stepsOnly;
        stepsOnly.withToolPaths = false;
        const Plan a = planJob(mm, TechnologyTable::builtIn(), lib, stepsOnly);
        const Plan b = planJob(in, TechnologyTable::builtIn(), lib, stepsOnly);
        QVERIFY(a.ok() && b.ok());
        QCOMPARE(b.steps.size(), a.steps.size());
        for (std::size_t i = 0; i < a.steps.size(); ++i) {
            QCOMPARE(b.steps[i].kind, a.steps[i].kind);
            QCOMPARE(b.steps[i].unit, a.steps[i].unit);
            QCOMPARE(b.steps[i].tool->toolId, a.steps[i].tool->toolId);
            QVERIFY(std::abs(millingOf(b.steps[i]).cutDepth - millingOf(a.steps[i]).cutDepth) < 1e-9);
            QVERIFY(std::abs(millingOf(b.steps[i]).startDepth - millingOf(a.steps[i]).startDepth) < 1e-9);
        }
        QCOMPARE(convertLengthUnit(in, LengthUnit::Millimetre), mm);
    }

    void technologyOverrides()
    {
        Job j;
        TechnologyDialog d(j);
        auto* alpha2 = d.findChild<QLineEdit*>("technology.alpha2");
        QVERIFY(alpha2);
        QTest::keyClicks(alpha2, "0.5");
        QVERIFY(d.overrides());
        QCOMPARE(d.overrides()->alpha2, std::optional<double>(0.5));
        QVERIFY(!d.overrides()->alpha1);
        QTest::keyClicks(alpha2, "x");
        QVERIFY(!d.overrides());  // "0.5x": the dialog refuses to apply it
    }

    void toolLibraryTable()
    {
        ToolLibraryDialog d;
        const auto tools = readToolLibrary(defaultToolLibraryPath());
        QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
        QVERIFY(!tools->empty());
        QCOMPARE(d.table()->rowCount(), static_cast<int>(tools->size()));
        QCOMPARE(d.table()->item(0, 0)->text(), QString::number(tools->front().id));
        QCOMPARE(d.table()->item(0, 1)->text(), QString::fromStdString(tools->front().name));
    }

    // The library is edited in place: a value typed over is checked and
    // saved (a wrong one refused with the reason and put back), a tool is
    // copied and retired, each an undo step; the next plan uses the edited
    // tool; the machine's tool table is exported.
    void toolLibraryIsEdited()
    {
        ToolLibraryDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QTableWidget* table = d.table();
        int row = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->item(r, ToolLibraryDialog::Id)->text() == "27") row = r;
        QVERIFY(row >= 0);
        const auto type = [&](ToolLibraryDialog::Column column, const QString& text) {
            QVERIFY(Fields::typeIntoCell(table, row, column, text));
        };
        const auto t27 = [] {
            const auto tools = readToolLibrary(defaultToolLibraryPath());
            if (!tools) return std::optional<Tool>();
            const std::vector<Tool>& all = *tools;
            const auto it = std::find_if(all.begin(), all.end(), [](const Tool& t) { return t.id == 27; });
            return it == all.end() ? std::optional<Tool>() : std::optional<Tool>(*it);
        };
        QCOMPARE(t27()->diameter, 10.0);
        // Its name states 10 mm: asked first (no job here, so no steps).
        QStringList asked;
        d.setConfirm([&](const QString& q) { return asked << q, true; });
        type(ToolLibraryDialog::Diameter, "11");
        QCOMPARE(asked.size(), 1);
        QVERIFY2(asked[0].contains("T27: Ø mm 10 → 11") && asked[0].contains("T27: the name says 10 mm, the diameter is 11 mm"),
                 qPrintable(asked[0]));
        QCOMPARE(t27()->diameter, 11.0);
        QVERIFY(d.changed());
        const double corner = t27()->cornerRadius;
        type(ToolLibraryDialog::Corner, "6");  // more than half of 11 mm
        QVERIFY2(d.status().contains("T27 not saved: corner radius 6 mm is more than half the diameter (5.5 mm)"),
                 qPrintable(d.status()));
        QCOMPARE(t27()->cornerRadius, corner);
        QVERIFY(table->item(row, ToolLibraryDialog::Corner)->text() != "6");
        type(ToolLibraryDialog::Diameter, "abc");
        QVERIFY2(d.status().contains("'abc' is not a number"), qPrintable(d.status()));
        QCOMPARE(t27()->diameter, 11.0);

        // The next plan takes the 11 mm tool.
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.planRunner()->flush();
        const auto plan = w.planRunner()->fullPlan();
        QVERIFY(plan && plan->tool(27));
        QCOMPARE(plan->tool(27)->diameter, 11.0);

        // Copy, retire, undo.
        const std::size_t count = d.tools().size();
        table->selectRow(row);
        d.findChild<QPushButton*>("tools.copy")->click();
        QCOMPARE(d.tools().size(), count + 1);
        QVERIFY(std::any_of(d.tools().begin(), d.tools().end(), [](const Tool& t) { return t.name == "Flat end mill 10 mm carbide (copy)"; }));
        d.findChild<QPushButton*>("tools.retire")->click();
        QCOMPARE(d.tools().size(), count);
        d.undoStack()->undo();
        QCOMPARE(d.tools().size(), count + 1);
        d.undoStack()->undo();
        QCOMPARE(d.tools().size(), count);
        d.undoStack()->undo();  // the diameter back to 10 mm
        QCOMPARE(t27()->diameter, 10.0);

        const QString tbl = dir_.filePath("tool.tbl");
        QVERIFY(d.exportToolTable(tbl, false));
        QFile f(tbl);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains("\nT27 P27 Z0 D10 ;Flat end mill 10 mm carbide\n"), qPrintable(text.left(400)));
    }

    // A tool edit shows the steps of the open job it changes before it is
    // applied (pipeline/tool_edit_impact.h): left, nothing is saved and the
    // cell is put back; applied, it is one undo step.
    void toolEditShowsTheStepsItChanges()
    {
        const auto read = readJobFile(test::sourcePath("resources/samples/m4-standard.taiwa").toStdString());
        QVERIFY(read.job);
        ToolLibraryDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        d.setImpact([job = *read.job](const std::vector<Tool>& before, const std::vector<Tool>& after) {
            return toolEditImpact(job, before, after);
        });
        // The tool that roughs the sample, and its row.
        const std::vector<Tool> library = d.tools();
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), library);
        QVERIFY(plan.ok());
        const auto roughing = std::find_if(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return s.kind == StepKind::Roughing; });
        QVERIFY(roughing != plan.steps.end() && roughing->tool);
        const int id = roughing->tool->toolId;
        QTableWidget* table = d.table();
        int row = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->item(r, ToolLibraryDialog::Id)->text() == QString::number(id)) row = r;
        QVERIFY(row >= 0);
        const QString diameter = table->item(row, ToolLibraryDialog::Diameter)->text();
        // 60 mm fits no pocket of the sample: its steps go to other tools.
        QStringList asked;
        bool answer = false;
        d.setConfirm([&](const QString& q) { return asked << q, answer; });
        QVERIFY(Fields::typeIntoCell(table, row, ToolLibraryDialog::Diameter, "60"));
        QCOMPARE(asked.size(), 1);
        qInfo().noquote() << asked[0];
        const QString rough = QString("unit %1, %2: T%3 → T").arg(roughing->unit + 1).arg(stepLabel(*roughing)).arg(id);
        QVERIFY2(asked[0].contains("step(s) of the open job") || asked[0].contains("steps of the open job"), qPrintable(asked[0]));
        QVERIFY2(asked[0].contains(rough), qPrintable(asked[0] + "\nexpected: " + rough));
        QVERIFY2(asked[0].contains("the name says"), qPrintable(asked[0]));  // and its name still says the old size
        // Left: nothing saved, the cell as it was, nothing to undo.
        QCOMPARE(table->item(row, ToolLibraryDialog::Diameter)->text(), diameter);
        QVERIFY2(d.status().contains(QString("T%1 not changed").arg(id)), qPrintable(d.status()));
        QVERIFY(!d.changed());
        QCOMPARE(d.undoStack()->count(), 0);
        // Applied: saved, one undo step; undone: as it was, not asked again.
        answer = true;
        QVERIFY(Fields::typeIntoCell(table, row, ToolLibraryDialog::Diameter, "60"));
        QCOMPARE(asked.size(), 2);
        QVERIFY(d.changed());
        QCOMPARE(d.undoStack()->count(), 1);
        QCOMPARE(table->item(row, ToolLibraryDialog::Diameter)->text(), QString("60"));
        d.undoStack()->undo();
        QCOMPARE(table->item(row, ToolLibraryDialog::Diameter)->text(), diameter);
        QCOMPARE(asked.size(), 2);
        // An edit no step of the job sees (a face mill's flutes): not asked.
        int faceMill = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->item(r, ToolLibraryDialog::Id)->text() == "60") faceMill = r;
        QVERIFY(faceMill >= 0);
        QVERIFY(Fields::typeIntoCell(table, faceMill, ToolLibraryDialog::Flutes, "6"));
        QCOMPARE(asked.size(), 2);
        QCOMPARE(d.undoStack()->count(), 1);
        d.undoStack()->undo();
    }

    void addM2DAndMoveUnits()
    {
        StationWindow w;
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM2D"), Qt::LeftButton);
        QCOMPARE(w.document()->job().units.size(), std::size_t(2));
        QVERIFY((w.document()->job().units[1].module).is<M2DPocket>());
        retype(edit(w, "m2d.theta2"), "15");
        QCOMPARE((w.document()->job().units[1].module).as<M2DPocket>().theta2, std::optional<double>(15.0));
        retype(edit(w, "m2d.theta2"), "");
        QVERIFY(!(w.document()->job().units[1].module).as<M2DPocket>().theta2);
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.up"), Qt::LeftButton);
        QVERIFY((w.document()->job().units[0].module).is<M2DPocket>());
        w.document()->undoStack()->undo();
        QVERIFY((w.document()->job().units[0].module).is<M4Pocket>());
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.delete"), Qt::LeftButton);
        QCOMPARE(w.document()->job().units.size(), std::size_t(1));
    }

    // Without OpenGL (the offscreen platform here) the window still opens,
    // plans and posts; the 3-D view's place says why it is empty.
    void noOpenGlShowsAPlaceholder()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(!w.preview());
        auto* note = w.findChild<QLabel*>("preview.unavailable");
        QVERIFY(note && note->isVisible());
        QCOMPARE(note->text(), QString("No 3-D preview: this display has no OpenGL."));
        w.planRunner()->flush();
        QVERIFY(w.planRunner()->fullPlan());
        QVERIFY(w.stepTable()->rowCount() > 0);
        QVERIFY(!w.planRunner()->stockSimulation());  // no preview: no stock simulated for it
    }
};

QTEST_MAIN(TestGuiStation)
#include "test_gui_station.moc"
