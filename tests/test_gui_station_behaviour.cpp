// The station's behaviour an operator relies on between edits, on the
// offscreen platform: stale views marked while the job has errors, totals
// kept while times are recomputed, new and duplicated units placed in free
// stock, the focus after adding a unit, one undo step per visit to a field,
// a dialect change re-posting the same plan, and an unnamed job's NC view
// equal to its exported tape.
#include "export/export.h"
#include "job/job_check.h"
#include "modules/m4/m4.h"
#include "sheet/sheet.h"
#include "support/gui_fields.h"
#include "support/support.h"
#include "ui/file_actions.h"
#include "ui/language.h"
#include "ui/core_texts.h"
#include "ui/job_document.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_list_panel.h"
#include "modules/registry.h"
#include "ui/unit_form.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QAction>
#include <algorithm>
#include <QStatusBar>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QScrollBar>
#include <QTranslator>
#include <QSplitter>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiStationBehaviour : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    using Fields = test::GuiFields;
    static QLineEdit* edit(QWidget& w, const QString& name) { return Fields::edit(w, name); }
    static void retype(QLineEdit* e, const QString& text) { Fields::retype(e, text); }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    // View > Stock grid: the choice reaches the plan runner, is kept for the
    // next window, and the status bar says what this stock gets.
    void stockGridIsChosenAndKept()
    {
        {
            StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCOMPARE(w.planRunner()->stockGrid(), sim::kStockGrids[1]);  // the default
            auto* fine = w.findChild<QAction*>("stockGrid.0");
            QVERIFY(fine);
            fine->trigger();
            QCOMPARE(w.planRunner()->stockGrid(), sim::kStockGrids[0]);
            QVERIFY2(w.statusBar()->currentMessage().contains("0.1 mm cells"), qPrintable(w.statusBar()->currentMessage()));
        }
        StationWindow again(test::sourcePath("resources/samples/plate.taiwa"));
        QCOMPARE(again.planRunner()->stockGrid(), sim::kStockGrids[0]);
        again.findChild<QAction*>("stockGrid.1")->trigger();  // back to the default for the other tests
    }

    // One dialect, the job's: the chooser shows the one the program on view
    // is posted in (it once said fanuc over a LinuxCNC program); choosing
    // another is an undoable edit of the job, saved with it; a new job takes
    // the one last chosen.
    void theDialectShownIsTheJobsAndIsPosted()
    {
        const QString saved = QDir(dir_.path()).filePath("dialect.taiwa");
        {
            StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.planRunner()->flush();
            auto* chooser = w.findChild<QComboBox*>("nc.dialect");
            QVERIFY(chooser);
            QCOMPARE(chooser->currentText(), QString("linuxcnc"));  // the sample names none: the command line's
            QCOMPARE(w.planRunner()->dialect(), QString("linuxcnc"));
            QVERIFY(!w.ncView()->text()->toPlainText().startsWith("%"));
            chooser->setCurrentText("fanuc");
            w.planRunner()->flush();
            QCOMPARE(w.document()->job().dialect, std::string("fanuc"));
            QVERIFY(w.document()->isModified());
            QCOMPARE(w.planRunner()->dialect(), QString("fanuc"));
            QVERIFY(w.ncView()->text()->toPlainText().startsWith("%\nO1000"));
            w.document()->undoStack()->undo();
            QCOMPARE(chooser->currentText(), QString("linuxcnc"));
            QCOMPARE(w.planRunner()->dialect(), QString("linuxcnc"));
            w.document()->undoStack()->redo();
            QVERIFY(w.document()->saveTo(saved).isEmpty());
        }
        StationWindow again(saved);
        again.planRunner()->flush();
        QCOMPARE(again.findChild<QComboBox*>("nc.dialect")->currentText(), QString("fanuc"));
        QVERIFY(again.ncView()->text()->toPlainText().startsWith("%"));
        StationWindow fresh(QString{});  // a new job: the dialect last chosen
        QCOMPARE(fresh.document()->job().dialect, std::string("fanuc"));
        QCOMPARE(fresh.findChild<QComboBox*>("nc.dialect")->currentText(), QString("fanuc"));
        rememberDialect("linuxcnc");  // as the other tests expect
    }

    void staleViewsAreMarked()
    {
        // An input error leaves the last valid program on view, greyed under a
        // banner naming the first error; the fix brings the new program back.
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.planRunner()->flush();
        auto* banner = w.findChild<QLabel*>("output.stale");
        QVERIFY(banner && !banner->isVisible());
        const QString program = w.ncView()->text()->toPlainText();
        QLineEdit* depth = edit(w, "m4.depth");
        retype(depth, "0");
        w.planRunner()->flush();
        QVERIFY(banner->isVisible());
        QVERIFY2(banner->text().contains("unit 1 (M4) T (depth):"), qPrintable(banner->text()));
        QCOMPARE(w.ncView()->text()->toPlainText(), program);
        QVERIFY(w.ncView()->text()->styleSheet().contains("#9a9a9a"));
        retype(depth, "12");
        w.planRunner()->flush();
        QVERIFY(!banner->isVisible());
        QVERIFY(w.ncView()->text()->styleSheet().isEmpty());
        QVERIFY(w.ncView()->text()->toPlainText() != program);  // the new depth's program
    }

    void totalsAreKeptWhileTimesAreComputed()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.planRunner()->flush();
        auto* details = w.findChild<QLabel*>("step.details");
        QVERIFY(details);
        w.stepTable()->clearSelection();
        const QString timed = details->text();
        QVERIFY2(timed.contains(" min") && !timed.contains("0.0 min"), qPrintable(timed));
        Job j = w.document()->job();
        (j.units[0].module).as<M4Pocket>().depth = 11;
        w.document()->edit(j, "deeper");  // the step list now, the times later
        const QString updating = details->text();
        QVERIFY2(updating.contains("updating") && !updating.contains("0.0 min"), qPrintable(updating));
        QVERIFY(updating.contains(timed.section(" min", 0, 0).section(", ", 1)));
        w.planRunner()->flush();
        QVERIFY(!details->text().contains("updating"));
    }

    void addedAndDuplicatedUnitsLandInFreeStock()
    {
        // plate.taiwa's stock has no room left for another 50 x 30 pocket: Add
        // adds it all the same at the module's default place, marked with its
        // overlap, the focus on its first corner; Duplicate says so and adds nothing.
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        const auto problems = [&] { return checkJob(w.document()->job(), TechnologyTable::builtIn(), w.planRunner()->library()); };
        const std::size_t before = w.document()->job().units.size();
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        QCOMPARE(w.document()->job().units.size(), before + 1);
        QCOMPARE(w.unitList()->currentUnit(), static_cast<int>(before));
        QVERIFY2(w.statusBar()->currentMessage().contains("no free place"), qPrintable(w.statusBar()->currentMessage()));
        const Diagnostics added = problems();
        QVERIFY(std::any_of(added.begin(), added.end(), [&](const Diagnostic& d) {
            return d.severity == Severity::Error && d.unit == static_cast<int>(before) + 1;
        }));
        QVERIFY(QApplication::focusWidget());
        QCOMPARE(QApplication::focusWidget()->objectName(), QString("m4.P1.x"));
        QVERIFY(!w.findChild<QLabel*>("unit.messages")->text().isEmpty() ||
                w.findChild<QLabel*>("m4.P1.x.error")->isVisible());  // its overlap shown with its form
        // Ctrl+4 and Ctrl+3, as the Job menu says; a milling job's menu has no turned profile.
        auto* addM4 = w.findChild<QAction*>("action.addM4");
        QVERIFY(addM4 && addM4->isVisible());
        QCOMPARE(addM4->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_4));
        QVERIFY(!w.findChild<QAction*>("action.addTURN")->isVisible());
        QTest::keyClick(&w, Qt::Key_4, Qt::ControlModifier);
        QCOMPARE(w.document()->job().units.size(), before + 2);
        QTest::keyClick(&w, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(w.document()->job().units.size(), before + 3);
        QCOMPARE(w.document()->job().units.back().module.name(), std::string("M2D"));
        for (int k = 0; k < 3; ++k) w.document()->undoStack()->undo();
        QCOMPARE(w.document()->job().units.size(), before);
        auto* panel = w.findChild<UnitListPanel*>();
        panel->selectUnit(0);
        panel->duplicate();
        QCOMPARE(w.document()->job().units.size(), before);

        // With a stock twice as large, both land where they overlap nothing.
        Job larger = w.document()->job();
        larger.stock.width *= 2;
        larger.stock.length *= 2;
        w.document()->edit(larger, "larger", {}, 0);
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM2D"), Qt::LeftButton);
        panel->selectUnit(0);
        panel->duplicate();
        QCOMPARE(w.document()->job().units.size(), before + 3);
        const Diagnostics ds = problems();
        QVERIFY2(!hasErrors(ds), qPrintable(QString::fromStdString(ds.empty() ? "" : format("plate", ds.front()))));
        // The copy is the same pocket, moved.
        const auto& units = w.document()->job().units;
        const auto& original = units[0].module.as<M4Pocket>();
        const auto& copy = units[1].module.as<M4Pocket>();
        QCOMPARE(copy.depth, original.depth);
        QCOMPARE(copy.corners[2] - copy.corners[0], original.corners[2] - original.corners[0]);
        QVERIFY(!(copy.corners[0] == original.corners[0]));
    }

    void unitNamesAreTypedInTheFormAndReachTheSheet()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QLineEdit* name = edit(w, "m4.name");
        QVERIFY(name);
        QCOMPARE(name->text(), QString("Pocket A"));
        retype(name, "Cover recess");
        QCOMPARE(w.document()->job().units[0].name, std::string("Cover recess"));
        w.document()->undoStack()->undo();  // the whole name typed at once is one step
        QCOMPARE(w.document()->job().units[0].name, std::string("Pocket A"));
        w.document()->undoStack()->redo();
        QVERIFY(w.unitList()->findChild<QListWidget*>()->item(0)->text().endsWith("Cover recess"));
        w.planRunner()->flush();
        const auto plan = w.planRunner()->fullPlan();
        QVERIFY(plan);
        QVERIFY(QString::fromStdString(sheetHtml(*plan, {})).contains("<td>1 Cover recess</td>"));
        // And the NC program's step comments, quoted; parentheses and '%'
        // (which a comment cannot hold) become spaces.
        QVERIFY2(w.ncView()->text()->toPlainText().contains("(STEP 1: UNIT 1 \"Cover recess\" M4 PILOT HOLE T"),
                 qPrintable(w.ncView()->text()->toPlainText().left(600)));
        retype(name, "Recess (B) 50%");
        w.planRunner()->flush();
        QVERIFY(w.ncView()->text()->toPlainText().contains("UNIT 1 \"Recess  B  50 \" M4"));
    }

    // The block's clamping set in the job's panel: the vice on the Y faces
    // at a third of the block's height, the height typed over, one undo
    // step each, a height above the block marked red with the check's
    // message; the sheet says where the jaws grip; none on a lathe job.
    void clampingIsSetInTheJobPanel()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto* vice = w.findChild<QComboBox*>("job.clamping");
        QLineEdit* jaws = edit(w, "clamping.height");
        QVERIFY(vice && jaws);
        QCOMPARE(vice->currentIndex(), 0);
        QVERIFY(!jaws->isEnabled());
        vice->setFocus();
        vice->setCurrentIndex(2);
        emit vice->activated(2);
        QVERIFY(w.document()->job().clamping);
        QCOMPARE(w.document()->job().clamping->grip, Clamping::Grip::Y);
        QCOMPARE(w.document()->job().clamping->height, 10.0);  // a third of 30 mm
        QVERIFY(jaws->isEnabled());
        QCOMPARE(jaws->text(), QString("10"));
        retype(jaws, "12.5");
        QCOMPARE(w.document()->job().clamping->height, 12.5);
        w.planRunner()->flush();
        QVERIFY(QString::fromStdString(sheetHtml(*w.planRunner()->fullPlan(), {})).contains("gripping 12.500 mm up from its bottom"));
        retype(jaws, "31");
        w.planRunner()->flush();
        QTRY_VERIFY(Fields::isRed(jaws));
        QVERIFY2(jaws->toolTip().contains("the top must stand out of the vice"), qPrintable(jaws->toolTip()));
        w.document()->undoStack()->undo();  // the height typed: one step
        QCOMPARE(w.document()->job().clamping->height, 10.0);
        w.document()->undoStack()->undo();  // the vice chosen
        QVERIFY(!w.document()->job().clamping);
        QCOMPARE(vice->currentIndex(), 0);

        StationWindow lathe(test::sourcePath("resources/samples/lathe-turned-shaft.taiwa"));
        lathe.show();
        QVERIFY(!lathe.findChild<QComboBox*>("job.clamping")->isVisible());
    }

    void focusGoesToTheNewUnitsFirstField()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        Job roomy = w.document()->job();
        roomy.stock.width = roomy.stock.length = 400;
        w.document()->edit(roomy, "roomy");
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM2D"), Qt::LeftButton);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit(w, "m2d.X1")));
        QTest::mouseClick(w.findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit(w, "m4.P1.x")));
        // Enter in a unit's last field: the next unit's first field; after
        // the last unit, the step list.
        w.unitList()->selectUnit(0);
        edit(w, "m4.stepOver")->setFocus();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        QCOMPARE(w.unitList()->currentUnit(), 1);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit(w, "m2d.X1")));
        w.unitList()->selectUnit(2);
        edit(w, "m4.stepOver")->setFocus();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(w.stepTable()));
        // Enter in any other field moves to the field below it.
        edit(w, "m4.depth")->setFocus();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        QCOMPARE(QApplication::focusWidget(), static_cast<QWidget*>(edit(w, "m4.taper")));
    }

    void separateVisitsToAFieldAreSeparateUndoSteps()
    {
        // Typing in the job's name or a stock field merges keystrokes into one
        // undo step, but leaving the field and coming back starts a new one.
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QUndoStack* undo = w.document()->undoStack();
        const int start = undo->count();
        for (const char* field : {"job.name", "stock.width"}) {
            QLineEdit* e = edit(w, field);
            QVERIFY(e);
            retype(e, "12");
            QTest::keyClick(e, Qt::Key_3);
            QCOMPARE(undo->count(), start + 1);  // one visit, one step
            QTest::keyClick(e, Qt::Key_Tab);      // leave
            retype(e, "45");                      // a second visit
            QCOMPARE(undo->count(), start + 2);
            undo->undo();
            QCOMPARE(e->text(), QString("123"));
            undo->undo();
            undo->clear();
        }
    }

    void dialectChangeRepostsWithoutReplanning()
    {
        // The tool paths do not depend on the dialect: changing it re-posts the
        // last plan (the very same Plan object) instead of planning again.
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.planRunner()->flush();
        const auto before = w.planRunner()->fullPlan();
        QVERIFY(before);
        w.planRunner()->setDialect("fanuc");
        w.planRunner()->flush();
        QCOMPARE(w.planRunner()->fullPlan().get(), before.get());
        QVERIFY2(w.ncView()->text()->toPlainText().startsWith("%\nO1000"),
                 qPrintable(w.ncView()->text()->toPlainText().left(40)));
    }

    // The core's words the station shows, step kinds and code meanings,
    // are in the station's language: each has its Japanese and Chinese.
    void coreWordsAreTranslated()
    {
        for (const char* language : {"ja", "zh"}) {
            qputenv("TAIWA_LANG", language);
            QVERIFY(installTranslator(*QCoreApplication::instance()));
            for (const QString& s : coreTextSources())
                QVERIFY2(QCoreApplication::translate("taiwa::CoreTexts", s.toUtf8().constData()) != s,
                         qPrintable(QString("%1: %2").arg(language, s)));
            Step rough;
            rough.kind = StepKind::Roughing;
            rough.number = 2;
            QCOMPARE(stepLabel(rough), QString(language == std::string("ja") ? "荒加工 II" : "粗加工 II"));
            QVERIFY(codeMeaning("roughing only") != "roughing only");
            for (auto* t : QCoreApplication::instance()->findChildren<QTranslator*>()) {
                QCoreApplication::removeTranslator(t);
                delete t;
            }
        }
        qunsetenv("TAIWA_LANG");
        Step rough;
        rough.kind = StepKind::Roughing;
        QCOMPARE(stepLabel(rough), QString("Roughing I"));
    }

    // Help on every field: the field being typed in has its line of help
    // under the drawing and its symbol marked in the drawing (the pixels
    // around the symbol turn the marking's yellow); every field of every
    // module has help.
    void fieldHelpFollowsTheFocus()
    {
        for (const ModuleKind* kind : moduleKinds())
            for (const FormField& f : kind->fields())
                QVERIFY2(!f.help.empty(), qPrintable(QString("%1 %2").arg(kind->name(), QString::fromStdString(f.key))));
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto* form = w.findChild<QWidget*>("m4.depth")->parentWidget()->parentWidget();
        auto* unitForm = qobject_cast<UnitForm*>(form);
        QVERIFY(unitForm);
        auto* drawing = w.findChild<QLabel*>("m4.drawing");
        const QImage plain = drawing->pixmap().toImage();
        const auto yellow = [](const QImage& img) {
            int n = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x) {
                    const QColor c = img.pixelColor(x, y);
                    n += c.red() > 230 && c.green() > 210 && c.blue() < 170;
                }
            return n;
        };
        QCOMPARE(yellow(plain), 0);
        w.findChild<QLineEdit*>("m4.depth")->setFocus();
        QCOMPARE(unitForm->highlightedSymbol(), QString("sym-T"));
        QCOMPARE(unitForm->helpText(), QString("Depth of the pocket, down from the top surface"));
        QVERIFY(w.findChild<QLabel*>("m4.help")->isVisible());
        const int depthMark = yellow(drawing->pixmap().toImage());
        QVERIFY2(depthMark > 40, qPrintable(QString::number(depthMark)));
        w.findChild<QLineEdit*>("m4.P3.y")->setFocus();
        QCOMPARE(unitForm->highlightedSymbol(), QString("sym-P3"));
        QVERIFY(unitForm->helpText().startsWith("A corner of the pocket"));
        w.findChild<QComboBox*>("m4.U")->setFocus();
        QCOMPARE(unitForm->highlightedSymbol(), QString());
        QVERIFY(unitForm->helpText().startsWith("Which steps the pocket gets"));
        QCOMPARE(yellow(drawing->pixmap().toImage()), 0);
    }

    // On a 1280 x 720 screen every panel is on it and usable: the window's
    // smallest size fits, the unit form keeps room for its labels and
    // fields, the step list and the NC program show several lines (the left
    // column scrolls rather than push the window off the screen).
    void windowFitsSmallScreens()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        QVERIFY2(w.minimumSizeHint().width() <= 1280 && w.minimumSizeHint().height() <= 720,
                 qPrintable(QString("%1 x %2").arg(w.minimumSizeHint().width()).arg(w.minimumSizeHint().height())));
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.planRunner()->flush();
        QCoreApplication::processEvents();
        QCOMPARE(w.size(), QSize(1280, 720));
        const QRect inside = w.rect();
        const std::pair<const char*, QSize> panels[] = {
            {"units", {200, 60}}, {"unit.scroll", {300, 300}}, {"steps", {220, 120}}, {"nc", {200, 120}}, {"job.name", {120, 15}}};
        for (const auto& [name, least] : panels) {
            auto* p = w.findChild<QWidget*>(name);
            QVERIFY2(p && p->isVisible(), name);
            const QRect at(p->mapTo(&w, QPoint(0, 0)), p->size());
            QVERIFY2(inside.contains(at.topLeft()) && p->width() >= least.width() && p->height() >= least.height(),
                     qPrintable(QString("%1: %2 x %3 at %4, %5").arg(name).arg(p->width()).arg(p->height()).arg(at.x()).arg(at.y())));
        }
        auto* view = w.findChild<QWidget*>(w.preview() ? "preview" : "preview.unavailable");
        QVERIFY(view && view->isVisible() && view->width() >= 320 && view->height() >= 240);
    }

    // S and F typed into the step list: the unit's speed and feed for steps
    // of that kind, kept in the job (one undo step each), in bold in the
    // list, on the tape; an emptied cell goes back to the tool's data.
    void stepListSetsSpeedAndFeed()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.planRunner()->flush();
        StepTable* table = w.stepTable();
        int row = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->item(r, StepTable::StepName)->text() == "Roughing I") row = r;
        QVERIFY(row >= 0);
        const QString toolSpeed = table->item(row, StepTable::Speed)->text();
        QVERIFY(!toolSpeed.isEmpty() && toolSpeed != "7100");
        const auto type = [&](StepTable::Column column, const QString& text) {
            QVERIFY(Fields::typeIntoCell(table, row, column, text));
            w.planRunner()->flush();
        };
        type(StepTable::Speed, "7100");
        type(StepTable::Feed, "1800");
        const auto& cutting = w.document()->job().units[0].cutting;
        QVERIFY(cutting.contains("roughing"));
        QCOMPARE(cutting.at("roughing").speed, std::optional<double>(7100));
        QCOMPARE(cutting.at("roughing").feed, std::optional<double>(1800));
        QCOMPARE(table->item(row, StepTable::Speed)->text(), QString("7100"));
        QVERIFY(table->item(row, StepTable::Speed)->font().bold());
        QVERIFY(!table->item(row + 1, StepTable::Speed)->font().bold());
        const QString tape = w.ncView()->text()->toPlainText();
        QVERIFY2(tape.contains("S7100 M3\n") && tape.contains(QRegularExpression(" F1800\\.?\n")), qPrintable(tape.left(800)));
        // Not a number: nothing changes.
        type(StepTable::Feed, "fast");
        QCOMPARE(w.document()->job().units[0].cutting.at("roughing").feed, std::optional<double>(1800));
        QCOMPARE(table->item(row, StepTable::Feed)->text(), QString("1800"));
        // Emptied: the tool's speed again; undo brings the 7100 back.
        type(StepTable::Speed, "");
        QVERIFY(!w.document()->job().units[0].cutting.at("roughing").speed);
        QCOMPARE(table->item(row, StepTable::Speed)->text(), toolSpeed);
        w.document()->undoStack()->undo();
        w.planRunner()->flush();
        QCOMPARE(w.document()->job().units[0].cutting.at("roughing").speed, std::optional<double>(7100));
    }

    // Every dialect is a choice of the NC view's chooser: HEIDENHAIN shows
    // the Klartext program; a lathe job's view in a milling-only dialect
    // says why there is no program instead of showing a wrong one.
    void everyDialectIsAChoice()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.planRunner()->flush();
        auto* chooser = w.findChild<QComboBox*>("nc.dialect");
        QVERIFY(chooser);
        QStringList offered;
        for (int i = 0; i < chooser->count(); ++i) offered << chooser->itemText(i);
        QCOMPARE(offered, test::shippedDialects());
        chooser->setFocus();
        while (chooser->currentText() != "heidenhain") QTest::keyClick(chooser, Qt::Key_Down);
        w.planRunner()->flush();
        QVERIFY2(w.ncView()->text()->toPlainText().startsWith("0 BEGIN PGM m4-standard MM\n"),
                 qPrintable(w.ncView()->text()->toPlainText().left(60)));
        QVERIFY(w.ncView()->text()->toPlainText().contains("TOOL CALL"));
        QTest::keyClick(chooser, Qt::Key_Up);  // sinumerik
        w.planRunner()->flush();
        QVERIFY(w.ncView()->text()->toPlainText().contains("MCALL CYCLE81("));

        StationWindow lathe(test::sourcePath("resources/samples/lathe-turned-shaft.taiwa"));
        lathe.planRunner()->setDialect("heidenhain");
        lathe.planRunner()->flush();
        QVERIFY2(lathe.ncView()->text()->toPlainText().contains("the heidenhain dialect writes no lathe tapes"),
                 qPrintable(lathe.ncView()->text()->toPlainText().left(200)));
    }

    void unnamedJobTapeEqualsTheExportedOne()
    {
        // One function builds the post options for the NC view and for export:
        // an unnamed job's program is named after the export stem in both.
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        Job j = w.document()->job();
        j.name.clear();
        w.document()->edit(j, "unname", {}, 0);
        w.planRunner()->flush();
        const auto plan = w.planRunner()->fullPlan();
        QVERIFY(plan && plan->job.name.empty());
        QTemporaryDir dir;
        ExportOptions eo;
        eo.dialect = w.planRunner()->dialect().toStdString();
        const auto exported = exportPlan(*plan, dir.path().toStdString(),
                                         FileActions::exportStem(w.document()->path()).toStdString(), eo);
        QVERIFY(exported);
        QFile nc(dir.filePath(FileActions::exportStem(w.document()->path()) + ".nc"));
        QVERIFY(nc.open(QIODevice::ReadOnly));
        const QStringList shown = w.ncView()->text()->toPlainText().split('\n');
        const QStringList written = QString::fromUtf8(nc.readAll()).split('\n');
        for (qsizetype i = 0; i < std::min(shown.size(), written.size()); ++i)
            QVERIFY2(shown[i] == written[i], qPrintable(QString("line %1: %2 | %3").arg(i + 1).arg(shown[i], written[i])));
        QCOMPARE(shown.size(), written.size());
    }

};

QTEST_MAIN(TestGuiStationBehaviour)
#include "test_gui_station_behaviour.moc"
