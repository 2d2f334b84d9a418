// Switching the station's language without a restart (issue 34, item 9):
// View > Language > 日本語 retranslates at once the menus, the panels'
// titles, the unit form's labels and code meanings, the job's form, the
// step table's headings and step names, the step panel's buttons, the
// NC panel's heading, the verification panel (its button and summary), the
// figure panel (its heading and buttons) and a turned profile's editor (its
// tables' headings and buttons); switching back to English brings the
// English words.
#include "support/speak.h"
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/figure_panel.h"
#include "ui/plan_runner.h"
#include "ui/profile_editor.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"
#include "ui/verification_panel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

QString translated(const char* context, const char* source, int n = -1)
{
    return QCoreApplication::translate(context, source, nullptr, n);
}

// The words the operator reads, from every part the switch must reach.
struct Shown {
    QString fileMenu, jobGroup, timeHeading, stepName, stockBox, allSteps, ncLabel, materialLabel, material,
        depthLabel, codeItem, duplicate, palette, verifyButton, verifySummary, figureTitle, reviseChamfer,
        profileHeading, profileAddRow, profileTitle;
};

Shown shown(StationWindow& w)
{
    QCoreApplication::processEvents();
    Shown s;
    s.fileMenu = w.menuBar()->actions().value(0) ? w.menuBar()->actions().value(0)->text() : QString();
    s.jobGroup = w.findChild<QGroupBox*>("group.job")->title();
    s.timeHeading = w.stepTable()->horizontalHeaderItem(StepTable::Time)->text();
    s.stepName = w.stepTable()->item(0, StepTable::StepName)->text();
    s.stockBox = w.findChild<QCheckBox*>("view.stock")->text();
    s.allSteps = w.findChild<QToolButton*>("step.all")->text();
    s.ncLabel = w.findChild<QLabel*>("nc.label")->text();
    s.duplicate = w.findChild<QPushButton*>("unit.duplicate")->text();
    s.palette = w.findChild<QToolButton*>("unit.addM4")->text();
    auto* material = w.findChild<QComboBox*>("job.material");
    s.material = material->currentText();
    if (auto* form = qobject_cast<QFormLayout*>(material->parentWidget()->layout()))
        if (auto* l = qobject_cast<QLabel*>(form->labelForField(material))) s.materialLabel = l->text();
    // The verification panel, the figure panel and the turned profile's
    // editor (in the lathe form, hidden in a milling job: told all the same).
    s.verifyButton = w.findChild<QPushButton*>("verify.run")->text();
    s.verifySummary = w.findChild<QLabel*>("verify.summary")->text();
    s.figureTitle = w.figurePanel()->findChild<QLabel*>("figure.title")
                        ? w.figurePanel()->findChild<QLabel*>("figure.title")->text()
                        : QString();
    s.reviseChamfer = w.findChild<QToolButton*>("figure.reviseChamfer")->text();
    for (UnitForm* f : w.findChildren<UnitForm*>())
        if (ProfileEditor* p = f->profileEditor()) {
            s.profileHeading = p->rowsTable()->horizontalHeaderItem(ProfileEditor::XCol)->text();
            s.profileAddRow = p->findChild<QPushButton*>(QString(p->rowsTable()->objectName()).replace(".rows", ".addRow"))->text();
            if (auto* title = p->findChild<QLabel*>(QString(p->rowsTable()->objectName()).replace(".rows", ".rowsTitle")))
                s.profileTitle = title->text();
        }
    // The M4 form (the first unit of plate.taiwa): its depth's label and a code's meaning.
    for (UnitForm* f : w.findChildren<UnitForm*>()) {
        if (!f->isVisible()) continue;
        for (QLabel* l : f->findChildren<QLabel*>())
            if (l->buddy() && l->buddy()->objectName() == "m4.depth") s.depthLabel = l->text();
        if (auto* code = f->findChild<QComboBox*>("m4.U")) s.codeItem = code->itemText(0);
    }
    return s;
}

}  // namespace

class TestGuiLanguageSwitch : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        test::speak("en");
    }
    void cleanup() { test::speak("en"); }

    void switchesAtOnceAndBack()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.resize(1600, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.planRunner()->flush();
        w.unitList()->selectUnit(0);
        QVERIFY(w.stepTable()->rowCount() > 0);
        const Shown english = shown(w);
        QCOMPARE(english.fileMenu, QString("&File"));
        QCOMPARE(english.timeHeading, QString("Time"));
        QCOMPARE(english.verifySummary, QString("Not verified since the last change."));
        QCOMPARE(english.profileHeading, QString("X (dia.)"));
        QCOMPARE(english.profileAddRow, QString("Add row"));
        QVERIFY2(!english.depthLabel.isEmpty() && !english.codeItem.isEmpty(), qPrintable(english.depthLabel + english.codeItem));

        auto* ja = w.findChild<QAction*>("language.ja");
        QVERIFY(ja);
        ja->trigger();
        QCOMPARE(installedLanguage(), QString("ja"));
        QTRY_VERIFY(shown(w).fileMenu != english.fileMenu);
        const Shown japanese = shown(w);
        // Every part in the translation's words (each differs from the English).
        const std::pair<QString, QString> pairs[] = {
            {japanese.fileMenu, translated("taiwa::ui::StationWindow", "&File")},
            {japanese.jobGroup, translated("taiwa::ui::StationWindow", "Job")},
            {japanese.timeHeading, translated("taiwa::ui::StepTable", "Time")},
            {japanese.stockBox, translated("taiwa::ui::StepPanel", "&Stock")},
            {japanese.allSteps, translated("taiwa::ui::StepPanel", "&All steps")},
            {japanese.ncLabel, translated("taiwa::ui::NcView", "&NC dialect:")},
            {japanese.materialLabel, translated("taiwa::ui::JobProperties", "Material")},
            {japanese.duplicate, translated("taiwa::ui::UnitListPanel", "D&uplicate")},
            {japanese.verifyButton, translated("taiwa::ui::VerificationPanel", "&Verify")},
            {japanese.verifySummary, translated("taiwa::ui::VerificationPanel", "Not verified since the last change.")},
            {japanese.figureTitle, translated("taiwa::ui::FigurePanel", "Figure elements, one statement a line")},
            {japanese.reviseChamfer, translated("taiwa::ui::FigurePanel", "Revise chamfer")},
            {japanese.profileHeading, translated("taiwa::ui::ProfileEditor", "X (dia.)")},
            {japanese.profileAddRow, translated("taiwa::ui::ProfileEditor", "Add row")},
            {japanese.profileTitle,
             translated("taiwa::ui::ProfileEditor", "Profile, in cutting order (X is a diameter; arcs: R, or the centre)")},
        };
        for (const auto& [now, expected] : pairs) QCOMPARE(now, expected);
        const std::pair<QString, QString> changed[] = {
            {japanese.fileMenu, english.fileMenu},     {japanese.jobGroup, english.jobGroup},
            {japanese.timeHeading, english.timeHeading}, {japanese.stepName, english.stepName},
            {japanese.stockBox, english.stockBox},     {japanese.allSteps, english.allSteps},
            {japanese.ncLabel, english.ncLabel},       {japanese.materialLabel, english.materialLabel},
            {japanese.material, english.material},     {japanese.depthLabel, english.depthLabel},
            {japanese.codeItem, english.codeItem},     {japanese.duplicate, english.duplicate},
            {japanese.palette, english.palette},       {japanese.verifyButton, english.verifyButton},
            {japanese.verifySummary, english.verifySummary}, {japanese.figureTitle, english.figureTitle},
            {japanese.reviseChamfer, english.reviseChamfer}, {japanese.profileHeading, english.profileHeading},
            {japanese.profileAddRow, english.profileAddRow}, {japanese.profileTitle, english.profileTitle}};
        for (const auto& [now, before] : changed) QVERIFY2(now != before, qPrintable("still '" + before + "'"));
        // A picture of the switched window to look at (TAIWA_SCREENSHOTS_DIR set).
        if (const QString shots = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR"); !shots.isEmpty())
            QVERIFY(w.grab().save(shots + "/station-switched-ja.png"));
        // The choice is kept for the next start, and the menu shows it.
        QCOMPARE(savedLanguage(), QString("ja"));
        QVERIFY(w.findChild<QAction*>("language.ja")->isChecked());

        w.findChild<QAction*>("language.en")->trigger();
        QCOMPARE(installedLanguage(), QString());
        QTRY_COMPARE(shown(w).fileMenu, english.fileMenu);
        const Shown again = shown(w);
        QCOMPARE(again.timeHeading, english.timeHeading);
        QCOMPARE(again.stepName, english.stepName);
        QCOMPARE(again.depthLabel, english.depthLabel);
        QCOMPARE(again.codeItem, english.codeItem);
        QCOMPARE(again.material, english.material);
        QCOMPARE(again.palette, english.palette);
        QCOMPARE(again.verifySummary, english.verifySummary);
        QCOMPARE(again.figureTitle, english.figureTitle);
        QCOMPARE(again.reviseChamfer, english.reviseChamfer);
        QCOMPARE(again.profileHeading, english.profileHeading);
        QCOMPARE(again.profileTitle, english.profileTitle);
        // The menus made anew: one Edit > Undo, its shortcut not ambiguous.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        int undos = 0;
        for (QAction* a : w.findChildren<QAction*>()) undos += a->shortcut() == QKeySequence(QKeySequence::Undo) ? 1 : 0;
        QCOMPARE(undos, 1);
    }
};

QTEST_MAIN(TestGuiLanguageSwitch)
#include "test_gui_language_switch.moc"
