// The selection follows everywhere (issue 34, item 8) and refusals name what
// the operator sees (item 6, the station's part): a chosen step puts the NC
// view on its own heading and shows its unit's form; after an undo the same
// step stays selected; a picked figure element does not scroll the text
// sideways; a turned step's depths are not zeros; a profile cell is named by
// its table, row and column; a Japanese banner names the field in Japanese.
#include "support/gui_fields.h"
#include "support/speak.h"
#include "support/support.h"
#include "ui/core_messages.h"
#include "ui/figure_panel.h"
#include "ui/job_document.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"

#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QUndoStack>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiSelection : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    static void open(StationWindow& w)
    {
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.planRunner()->flush();
    }
    static QString ncLine(StationWindow& w) { return w.ncView()->text()->textCursor().block().text(); }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }
    void cleanup() { test::speak("en"); }

    // Steps 2 and 3 of the plate: the NC band on "(STEP 2: …", not on the
    // G80 that closes step 1; and the step's unit's form beside it.
    void stepShowsItsHeadingAndItsUnit()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        open(w);
        const auto plan = w.stepPanel()->plan();
        QVERIFY(plan && plan->steps.size() > 3);
        for (int k = 1; k < 4; ++k) {
            w.stepPanel()->selectStep(k);
            QVERIFY2(ncLine(w).contains(QStringLiteral("STEP %1:").arg(k + 1)), qPrintable(ncLine(w)));
        }
        // A step of another unit than the one shown: its unit's form.
        w.unitList()->selectUnit(0);
        int other = -1;
        for (std::size_t k = 0; k < plan->steps.size() && other < 0; ++k)
            if (plan->steps[k].unit != 0) other = static_cast<int>(k);
        QVERIFY(other >= 0);
        w.stepPanel()->selectStep(other);
        QCOMPARE(w.unitList()->currentUnit(), plan->steps[static_cast<std::size_t>(other)].unit);
        // A new plan re-selecting the step does not take the form away from the unit being typed in.
        w.unitList()->selectUnit(0);
        Job j = w.document()->job();
        j.units[0].name = "renamed";
        w.document()->edit(j, "rename");
        w.planRunner()->flush();
        QCOMPARE(w.unitList()->currentUnit(), 0);
    }

    // Unit 1 deleted, a step chosen, the deletion undone: the same step of
    // the same unit is selected, at its row now.
    void undoKeepsTheSameStepSelected()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        open(w);
        w.unitList()->selectUnit(0);
        w.unitList()->remove();
        w.planRunner()->flush();
        const auto before = w.stepPanel()->plan();
        QVERIFY(before && !before->steps.empty());
        w.stepPanel()->selectStep(0);
        const Step chosen = before->steps[0];
        const MachiningUnit unit = before->job.units[static_cast<std::size_t>(chosen.unit)];
        w.document()->undoStack()->undo();
        w.planRunner()->flush();
        const auto after = w.stepPanel()->plan();
        const int k = w.stepPanel()->selectedStep();
        QVERIFY2(k >= 0, "no step selected after the undo");
        const Step& now = after->steps[static_cast<std::size_t>(k)];
        QVERIFY2(after->job.units[static_cast<std::size_t>(now.unit)] == unit && now.label() == chosen.label(),
                 qPrintable(QStringLiteral("row %1: unit %2 %3, chose unit %4 %5")
                                .arg(k).arg(now.unit + 1).arg(QString::fromStdString(now.label()))
                                .arg(chosen.unit + 1).arg(QString::fromStdString(chosen.label()))));
    }

    // A statement with a long comment picked: the text stays at its left edge.
    void pickedStatementDoesNotScrollSideways()
    {
        StationWindow w(test::sourcePath("resources/samples/cp-islands.taiwa"));
        open(w);
        w.showFigure(true);
        FigurePanel* panel = w.figurePanel();
        Job j = w.document()->job();
        const std::string figure = j.figure;
        const auto eq = figure.find(" = ");
        QVERIFY(eq != std::string::npos);
        const auto lineStart = figure.rfind('\n', eq) == std::string::npos ? 0 : figure.rfind('\n', eq) + 1;
        const QString name = QString::fromStdString(figure.substr(lineStart, eq - lineStart));
        const auto lineEnd = figure.find('\n', eq);
        j.figure = figure.substr(0, lineEnd) + " $$ " + std::string(300, 'x') + figure.substr(lineEnd);
        w.document()->edit(j, "long comment");
        w.planRunner()->flush();
        QCoreApplication::processEvents();
        panel->select(name);
        QCoreApplication::processEvents();
        QCOMPARE(panel->editor()->horizontalScrollBar()->value(), 0);
        QVERIFY(panel->editor()->textCursor().hasSelection());
    }

    // The step list of a lathe job: no 0 for start and depth.
    void turnedStepsHaveNoZeroDepths()
    {
        StationWindow w(test::sourcePath("resources/samples/lathe-turned-shaft.taiwa"));
        open(w);
        StepTable* t = w.stepTable();
        QVERIFY(t->rowCount() > 0);
        bool someDepth = false;
        for (int r = 0; r < t->rowCount(); ++r) {
            QVERIFY2(t->item(r, StepTable::Start)->text() != "0", qPrintable(QString::number(r)));
            QVERIFY2(t->item(r, StepTable::Depth)->text() != "0", qPrintable(QString::number(r)));
            someDepth = someDepth || t->item(r, StepTable::Depth)->text().toDouble() > 0;
        }
        QVERIFY(someDepth);  // the roughing's depth of cut
    }

    // A profile cell as the tables name it, in English and Japanese.
    void profileCellNamedByRowAndColumn()
    {
        const Diagnostic d{Severity::Error, 1, "TURN", "allowances[2].grooveWidth", "the groove is too wide"};
        QCOMPARE(diagnosticField(d), QString("allowance row 2, Width"));
        QVERIFY(!diagnosticText("shaft.taiwa", d).contains("grooveWidth"));
        const Diagnostic row{Severity::Error, 1, "TURN", "rows[3].radius", "too large"};
        QCOMPARE(diagnosticField(row), QString("profile row 3, R"));
        test::speak("ja");
        QVERIFY2(!diagnosticField(d).contains("allowance") && diagnosticField(d).contains("2"), qPrintable(diagnosticField(d)));
    }

    // A depth of 0 in a Japanese station: the banner over the views names the
    // field as the form does, in Japanese.
    void japaneseBannerNamesTheFieldInJapanese()
    {
        test::speak("ja");
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        open(w);
        QLineEdit* depth = test::GuiFields::edit(w, "m4.depth");
        QVERIFY(depth);
        test::GuiFields::retype(depth, "0");
        auto* banner = w.findChild<QLabel*>("output.stale");
        QTRY_VERIFY(banner->isVisible());
        QVERIFY2(!banner->text().contains("depth"), qPrintable(banner->text()));
        auto* form = depth->parentWidget();
        while (form && !qobject_cast<UnitForm*>(form)) form = form->parentWidget();
        QVERIFY(form);
        QString label;
        for (const FieldSpec& f : static_cast<UnitForm*>(form)->fields())
            if (f.key == "depth") label = QCoreApplication::translate("taiwa::ui::FieldSpec", f.label.toUtf8().constData());
        QVERIFY(!label.isEmpty() && label != "T (depth)");
        QVERIFY2(banner->text().contains(label), qPrintable(banner->text() + " / " + label));
    }
};

QTEST_MAIN(TestGuiSelection)
#include "test_gui_selection.moc"
