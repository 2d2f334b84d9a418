// The station window: its construction, the edits it answers (units added,
// selected, edited; a plan shown, the NC text caught up after the 3-D
// view), title and close. Panels and menus: station_layout.cpp; which
// signal reaches which view: station_wiring.cpp.
#include "ui/station_window.h"

#include "machine/machine.h"
#include "modules/registry.h"
#include "ui/autosave.h"
#include "ui/core_messages.h"
#include "ui/core_texts.h"
#include "ui/dxf_import_dialog.h"
#include "ui/figure_panel.h"
#include "ui/file_actions.h"
#include "ui/form_stack.h"
#include "ui/job_document.h"
#include "ui/job_properties.h"
#include "ui/module_palette.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/section_bar.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/technology_dialog.h"
#include "ui/tool_library_dialog.h"
#include "ui/two_path_chart.h"
#include "ui/two_path_views.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"
#include "ui/verification_panel.h"
#include "viz/scene.h"

#include <QEvent>
#include <QAction>
#include <QCloseEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>

#include <algorithm>

namespace taiwa::ui {

StationWindow::StationWindow(const QString& jobPath, QWidget* parent)
    : QMainWindow(parent), doc_(new JobDocument(this)), runner_(new PlanRunner(this)),
      autosave_(new Autosaver(doc_, this)), files_(new FileActions(doc_, runner_, autosave_, this)),
      palette_(new ModulePalette), units_(new UnitListPanel(doc_)), jobProps_(new JobProperties(doc_)),
      forms_(new FormStack), unitMessages_(new QLabel), steps_(new StepPanel), nc_(new NcView),
      verify_(new VerificationPanel), twoPath_(new TwoPathViews(this))
{
    for (const ModuleKind* kind : moduleKinds()) unitForms_[kind->name()] = new UnitForm(*kind);
    auto* main = new QSplitter(Qt::Horizontal);
    main->addWidget(buildLeft());
    main->addWidget(buildCentre());
    main->addWidget(buildRight());
    main->setStretchFactor(0, 0);
    main->setStretchFactor(1, 0);
    main->setStretchFactor(2, 1);
    setCentralWidget(main);
    nameParts();
    buildMenus();
    wire();
    // The size the operator left it at, else 1600 x 940 within the screen's
    // free area; the panels' split as left, else in proportion.
    main->setObjectName("station.split");
    QSettings settings;
    const QRect free = screen() ? screen()->availableGeometry() : QRect(0, 0, 1600, 940);
    if (!restoreGeometry(settings.value("station/geometry").toByteArray()))
        resize(std::min(1600, free.width()), std::min(940, free.height()));
    // Left on a larger screen: never larger than this one, and on it.
    if (width() > free.width() || height() > free.height()) {
        resize(std::min(width(), free.width()), std::min(height(), free.height()));
        move(free.topLeft());
    }
    if (!main->restoreState(settings.value("station/split").toByteArray()))
        main->setSizes({width() * 22 / 100, width() * 24 / 100, width() * 54 / 100});
    if (!runner_->libraryError().isEmpty())
        statusBar()->showMessage(tr("Tool library: %1 (using the built-in library)")
                                     .arg(coreMessage(runner_->libraryError().toStdString())));
    else if (!runner_->libraryStatus().isEmpty())  // the shop server away: its copy (docs/shop-server.md)
        statusBar()->showMessage(runner_->libraryStatus());

    if (!files_->offerRecovery(jobPath) && !(jobPath.isEmpty() ? files_->newJob() : files_->openPath(jobPath)))
        files_->newJob();
    updateTitle();
}

StepTable* StationWindow::stepTable() const { return steps_->table(); }

void StationWindow::changeEvent(QEvent* e)
{
    QMainWindow::changeEvent(e);
    if (e->type() != QEvent::LanguageChange || !views_) return;
    nameParts();
    setMenuBar(new QMenuBar);  // the old one and its actions go (deleteLater)
    buildMenus();
    // What the window shows from the core, said again in the new language;
    // the Job menu's modules as the machine has them.
    onDocumentChanged(false);
    showDiagnostics();
    updateTitle();
}

void StationWindow::importDxf()
{
    if (doc_->job().bar) {
        statusBar()->showMessage(tr("DXF contours become figure elements, which a lathe job does not use."), 8000);
        return;
    }
    DxfImportDialog dialog(doc_->job(), this);
    dialog.show();
    QMetaObject::invokeMethod(dialog.findChild<QPushButton*>("dxf.choose"), "click", Qt::QueuedConnection);
    if (dialog.exec() == QDialog::Accepted) replaceFigure(dialog.appendedTo(doc_->job().figure), tr("Import DXF contours"));
}

void StationWindow::replaceFigure(const std::string& figure, const QString& what)
{
    if (figure == doc_->job().figure) return;
    Job job = doc_->job();
    job.figure = figure;
    doc_->edit(job, what);
    showFigure(true);
}

void StationWindow::showFigure(bool figure)
{
    if (figure && views_->isTabVisible(views_->indexOf(figure_))) views_->setCurrentWidget(figure_);
    else views_->setCurrentIndex(0);
}

void StationWindow::addUnit(const QString& module)
{
    units_->addUnit(module);
    // The operator types the new unit's values next: its first field.
    if (UnitForm* f = currentForm()) f->focusFirstField();
}

UnitForm* StationWindow::currentForm() const
{
    const int u = units_->currentUnit();
    const auto& units = doc_->job().units;
    if (u < 0 || u >= static_cast<int>(units.size())) return nullptr;
    const auto it = unitForms_.find(units[static_cast<std::size_t>(u)].module.name());
    return it == unitForms_.end() ? nullptr : it->second;
}

void StationWindow::onDocumentChanged(bool fromTyping)
{
    // The job's dialect, else what the command line would post: linuxcnc.
    const QString dialect = doc_->job().dialect.empty() ? QStringLiteral("linuxcnc") : QString::fromStdString(doc_->job().dialect);
    runner_->setDialect(dialect);
    runner_->start(doc_->job());  // the full plan under way while the window shows the edit
    nc_->setDialect(dialect);
    units_->refresh();
    jobProps_->refresh(!fromTyping);
    const Machine* machine = findMachine(doc_->job().machine);
    palette_->setMachineKind(machine ? machine->kind : MachineKind::Mill);
    for (QAction* a : findChildren<QAction*>())  // the Job menu's modules, as the palette's
        if (a->objectName().startsWith("action.add") && a->property("machineKind").isValid())
            a->setVisible(a->property("machineKind").toInt() == static_cast<int>(machine ? machine->kind : MachineKind::Mill));
    // Figure elements are for milling jobs; a lathe job's profiles are in its units.
    const bool lathe = doc_->job().bar.has_value();
    if (lathe && views_->currentWidget() == figure_) views_->setCurrentIndex(0);
    views_->setTabVisible(views_->indexOf(figure_), !lathe);
    if (UnitForm* f = currentForm()) {
        const MachiningUnit& unit = doc_->job().units[static_cast<std::size_t>(units_->currentUnit())];
        f->setContext(doc_->job(), runner_->library());
        f->setUnit(unit, !fromTyping);
        f->setSketch(moduleKind(unit.module).sketch(unit.module, doc_->job().lengthUnit, runner_->library()));
    }
    runner_->announce();
}

void StationWindow::onUnitSelected(int unit)
{
    figure_->setCurrentUnit(unit);
    UnitForm* f = currentForm();
    forms_->setCurrentWidget(f ? static_cast<QWidget*>(f) : forms_->widget(0));
    if (f) {
        const MachiningUnit& u = doc_->job().units[static_cast<std::size_t>(unit)];
        f->setContext(doc_->job(), runner_->library());
        f->setUnit(u, true);
        f->setSketch(moduleKind(u.module).sketch(u.module, doc_->job().lengthUnit, runner_->library()));
    }
    showDiagnostics();
}

void StationWindow::onFieldEdited(UnitForm* form, int field, std::optional<double> value)
{
    const int u = units_->currentUnit();
    if (u < 0 || form != currentForm()) return;
    const FieldSpec& spec = form->fields()[static_cast<std::size_t>(field)];
    Job j = doc_->job();
    spec.set(j.units[static_cast<std::size_t>(u)], value);
    if (j == doc_->job()) {
        showDiagnostics();  // same value retyped: clear "not a number"
        return;
    }
    doc_->edit(j, tr("Edit %1 of unit %2").arg(spec.label).arg(u + 1), QStringLiteral("%1:%2").arg(u).arg(spec.key));
}

void StationWindow::onProgram(std::shared_ptr<const Plan> plan)
{
    if (!plan) return;
    verify_->setPlan(plan);  // the findings of the plan before are gone with it
    if (preview_) {
        preview_->setPlan(plan, runner_->stockSimulation());  // published together with the plan
        preview_->setSelectedStep(steps_->selectedStep());     // the step panel gets the plan later
        preview_->markPoint(std::nullopt);
        // A lathe job's view is a section already.
        section_->setStock(plan->mmJob.bar ? std::nullopt : std::optional<Stock>(plan->mmJob.stock), plan->job.lengthUnit);
    }
}

void StationWindow::scheduleCatchUp()
{
    catchUpTimer_->start(catchUpMs_ < 33 ? 0 : static_cast<int>(std::min<qint64>(2 * catchUpMs_, 1000)));
}

void StationWindow::catchUp()
{
    catchUpTimer_->stop();
    catchUpAfterFrame_ = false;
    if (!later_) return;
    QElapsedTimer took;
    took.start();
    const Later l = std::move(*later_);
    later_.reset();
    // A two-path job: path 1's program here, path 2's in its tab.
    const PostedProgram* path1 = twoPath_->setPlan(*l.plan, runner_->dialect(), files_->stem());
    showTwoPath(twoPath_->shown().has_value());
    if (preview_) {  // both turrets' tools where the timeline has them (none: a job of one path)
        std::optional<viz::TurretTools> turrets;
        if (const auto& s = twoPath_->shown(); s && !s->sides.empty())
            turrets = viz::TurretTools{static_cast<int>(s->balanced.step), s->sides, s->places};
        preview_->setTurretTools(std::move(turrets));
    }
    if (path1) nc_->setProgram(QString::fromStdString(path1->nc), path1->lines);
    else nc_->setProgram(l.nc, l.lines);  // a milling or a lathe tape
    steps_->setPlan(l.plan);         // the same steps, now with times; re-selects the step in the preview
    catchUpMs_ = took.elapsed();
}

void StationWindow::showTwoPath(bool on)
{
    if (on == twoPath_->chart()->isVisibleTo(this)) return;
    twoPath_->chart()->setVisible(on);
    for (QTabWidget* tabs : {stepTabs_, tapes_}) {
        tabs->setTabVisible(1, on);
        tabs->tabBar()->setVisible(on);
    }
    // Opened on a two-path job: its steps by path.
    stepTabs_->setCurrentIndex(on ? 1 : 0);
    tapes_->setCurrentIndex(0);
}

void StationWindow::showStale()
{
    const auto first = std::find_if(diagnostics_.begin(), diagnostics_.end(),
                                    [](const Diagnostic& d) { return d.severity == Severity::Error; });
    const bool stale = first != diagnostics_.end() && runner_->fullPlan();
    stale_->setVisible(stale);
    nc_->setStale(stale);
    if (stale)
        stale_->setText(tr("Not up to date: the job has input errors. The 3-D view and the NC program show the last "
                           "valid job. First error: %1")
                            .arg(diagnosticText(doc_->path().isEmpty() ? tr("job").toStdString()
                                                                       : QFileInfo(doc_->path()).fileName().toStdString(),
                                                *first)));
}

void StationWindow::showDiagnostics()
{
    const int u = units_->currentUnit();
    Diagnostics ofUnit, jobLevel;
    int otherUnits = 0;
    for (const Diagnostic& d : diagnostics_) {
        if (!d.unit) jobLevel.push_back(d);
        else if (*d.unit == u + 1) ofUnit.push_back(d);
        else ++otherUnits;
    }
    QStringList unitText;
    if (UnitForm* f = currentForm())
        for (const Diagnostic& d : f->showDiagnostics(ofUnit))
            unitText << (d.field.empty() ? QString() : diagnosticField(d) + ": ") + coreMessage(d.message);
    unitMessages_->setText(unitText.join("\n"));
    jobProps_->showDiagnostics(jobLevel);
    QStringList status;
    for (const Diagnostic& d : jobLevel)
        status << (d.field.empty() ? QString() : diagnosticField(d) + ": ") + coreMessage(d.message);
    if (otherUnits > 0) status << tr("%n problem(s) in other units", "", otherUnits);
    if (status.isEmpty()) statusBar()->clearMessage();
    else statusBar()->showMessage(status.join("  •  "));
}

void StationWindow::editTechnology()
{
    TechnologyDialog dialog(doc_->job(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    Job j = doc_->job();
    j.technology = *dialog.overrides();
    doc_->edit(j, tr("Edit technology data"));
}

void StationWindow::showToolLibrary()
{
    ToolLibraryDialog dialog(this);
    // An edit shows the steps of this job it changes before it is applied.
    dialog.setImpact([job = doc_->job()](const std::vector<Tool>& before, const std::vector<Tool>& after) {
        return toolEditImpact(job, before, after);
    });
    dialog.exec();
    if (!dialog.changed()) return;
    runner_->reloadLibrary();
    runner_->update(doc_->job());
}

void StationWindow::updateTitle()
{
    const QString name = files_->title();
    // An unnamed job's program is named after its file (or stored name), as export names it.
    runner_->setFileStem(files_->stem());
    if (doc_->path() != openPath_) {
        // Another window editing the same file: say so once, on opening it.
        openPath_ = doc_->path();
        autosave_->markOpen(openPath_);
        if (const int others = Autosaver::openElsewhere(openPath_, autosave_)) {
            const QString warning = tr("%1 is also open in %n other window(s): a save here asks before it overwrites "
                                       "what another window saved.", "", others).arg(name);
            // After the "Opened" message of the same event.
            QTimer::singleShot(0, this, [this, warning] { statusBar()->showMessage(warning, 15000); });
        }
    }
    setWindowTitle(QStringLiteral("%1%2 — Taiwa").arg(name, doc_->isModified() ? "*" : ""));
}

void StationWindow::closeEvent(QCloseEvent* e)
{
    if (!files_->maybeSave()) {
        e->ignore();
        return;
    }
    autosave_->removeRecovery(doc_->path());
    QSettings settings;
    settings.setValue("station/geometry", saveGeometry());
    if (auto* split = findChild<QSplitter*>("station.split")) settings.setValue("station/split", split->saveState());
    e->accept();
}

}  // namespace taiwa::ui
