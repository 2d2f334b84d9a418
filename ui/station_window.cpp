// The station window: layout and wiring only; the work is done by the
// document, plan runner, forms, panels and file actions.
#include "ui/station_window.h"
#include "ui/core_messages.h"
#include "ui/core_texts.h"
#include "viz/scene.h"

#include "machine/machine.h"

#include "modules/registry.h"

#include <QCoreApplication>

#include "ui/autosave.h"
#include "ui/dxf_import_dialog.h"
#include "ui/figure_panel.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/job_properties.h"
#include "ui/language.h"
#include "ui/module_palette.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/technology_dialog.h"
#include "ui/tool_library_dialog.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"
#include "ui/verification_panel.h"

#include "ui/preview_widget.h"
#include "ui/section_bar.h"

#include <QActionGroup>
#include <QCloseEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTimer>

#include <algorithm>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QOpenGLContext>
#include <QPushButton>
#include <QScrollArea>
#include <QScreen>
#include <QSettings>
#include <QLocale>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QUndoStack>
#include <QVBoxLayout>

namespace taiwa::ui {

StationWindow::StationWindow(const QString& jobPath, QWidget* parent)
    : QMainWindow(parent), doc_(new JobDocument(this)), runner_(new PlanRunner(this)),
      autosave_(new Autosaver(doc_, this)), files_(new FileActions(doc_, runner_, autosave_, this)),
      palette_(new ModulePalette), units_(new UnitListPanel(doc_)), jobProps_(new JobProperties(doc_)),
      forms_(new QStackedWidget), unitMessages_(new QLabel), steps_(new StepPanel), nc_(new NcView),
      verify_(new VerificationPanel)
{
    viz::Scene::setScaleNoteText([](int mm) { return axesNote(mm).toStdString(); }, axesNoteFont().toStdString());
    for (const ModuleKind* kind : moduleKinds()) unitForms_[kind->name()] = new UnitForm(*kind);
    auto* main = new QSplitter(Qt::Horizontal);
    main->addWidget(buildLeft());
    main->addWidget(buildCentre());
    main->addWidget(buildRight());
    main->setStretchFactor(0, 0);
    main->setStretchFactor(1, 0);
    main->setStretchFactor(2, 1);
    setCentralWidget(main);
    buildMenus();
    wire();
    // The size the operator left it at, else 1600 x 940 within the screen's
    // free area; the panels' split as left, else in proportion.
    main->setObjectName("station.split");
    QSettings settings;
    if (!restoreGeometry(settings.value("station/geometry").toByteArray())) {
        const QRect free = screen() ? screen()->availableGeometry() : QRect(0, 0, 1600, 940);
        resize(std::min(1600, free.width()), std::min(940, free.height()));
    }
    if (!main->restoreState(settings.value("station/split").toByteArray()))
        main->setSizes({width() * 22 / 100, width() * 24 / 100, width() * 54 / 100});
    if (!runner_->libraryError().isEmpty())
        statusBar()->showMessage(tr("Tool library: %1 (using the built-in library)")
                                     .arg(coreMessage(runner_->libraryError().toStdString())));

    if (!files_->offerRecovery(jobPath) && !(jobPath.isEmpty() ? files_->newJob() : files_->openPath(jobPath)))
        files_->newJob();
    updateTitle();
}

QWidget* StationWindow::buildLeft()
{
    auto* left = new QWidget;
    auto* box = new QVBoxLayout(left);
    auto* paletteGroup = new QGroupBox(tr("Modules"));
    (new QVBoxLayout(paletteGroup))->addWidget(palette_);
    auto* unitsGroup = new QGroupBox(tr("Machining units, in order"));
    (new QVBoxLayout(unitsGroup))->addWidget(units_);
    auto* jobGroup = new QGroupBox(tr("Job"));
    auto* jobBox = new QVBoxLayout(jobGroup);
    jobBox->addWidget(jobProps_);
    auto* dialogs = new QHBoxLayout;
    auto* technology = new QPushButton(tr("Technology data…"));
    technology->setObjectName("job.technology");
    auto* tools = new QPushButton(tr("Tool library…"));
    tools->setObjectName("job.tools");
    dialogs->addWidget(technology);
    dialogs->addWidget(tools);
    jobBox->addLayout(dialogs);
    connect(technology, &QPushButton::clicked, this, &StationWindow::editTechnology);
    connect(tools, &QPushButton::clicked, this, &StationWindow::showToolLibrary);
    box->addWidget(paletteGroup);
    box->addWidget(unitsGroup, 1);
    box->addWidget(jobGroup);
    // On a low screen (720 pixels) the column scrolls rather than push the
    // window off the screen.
    auto* scroll = new QScrollArea;
    scroll->setObjectName("station.left");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(left);
    scroll->setMinimumWidth(left->minimumSizeHint().width() + 16);  // and its scroll bar
    return scroll;
}

QWidget* StationWindow::buildCentre()
{
    auto* empty = new QLabel(tr("Pick a module on the left to add a machining unit."));
    empty->setAlignment(Qt::AlignCenter);
    empty->setWordWrap(true);
    forms_->addWidget(empty);
    for (const ModuleKind* kind : moduleKinds()) forms_->addWidget(unitForms_.at(kind->name()));
    unitMessages_->setObjectName("unit.messages");
    unitMessages_->setStyleSheet("color: #a00000;");
    unitMessages_->setWordWrap(true);
    auto* formGroup = new QGroupBox(tr("Unit"));
    auto* scroll = new QScrollArea;
    scroll->setObjectName("unit.scroll");
    scroll->setMinimumWidth(300);  // a form's labels and fields stay readable when the window is narrow
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(forms_);
    auto* box = new QVBoxLayout(formGroup);
    box->addWidget(scroll, 1);
    box->addWidget(unitMessages_);
    return formGroup;
}

QWidget* StationWindow::buildRight()
{
    auto* right = new QSplitter(Qt::Vertical);
    // Over the views while they show the last valid plan and the job has errors.
    stale_ = new QLabel;
    stale_->setObjectName("output.stale");
    stale_->setWordWrap(true);
    stale_->setStyleSheet("background: #fff3c4; color: #5a4500; padding: 4px; border: 1px solid #e0c060;");
    stale_->hide();
    // The 3-D view, and beside it (a milling job's) figure elements.
    views_ = new QTabWidget;
    views_->setObjectName("station.views");
    views_->setDocumentMode(true);
    if (QOpenGLContext().create()) {
        preview_ = new PreviewWidget;
        preview_->setObjectName("preview");
        preview_->setMinimumSize(320, 240);
        section_ = new SectionBar;
        section_->setObjectName("section");
        auto* view = new QWidget;
        auto* box = new QVBoxLayout(view);
        box->setContentsMargins(0, 0, 0, 0);
        box->setSpacing(2);
        box->addWidget(preview_, 1);
        box->addWidget(section_);
        views_->addTab(view, tr("3-D view"));
    } else {  // e.g. a remote display or the offscreen platform: everything else still works
        auto* noGl = new QLabel(tr("No 3-D preview: this display has no OpenGL."));
        noGl->setObjectName("preview.unavailable");
        noGl->setAlignment(Qt::AlignCenter);
        noGl->setFrameShape(QFrame::StyledPanel);
        views_->addTab(noGl, tr("3-D view"));
    }
    figure_ = new FigurePanel(doc_);
    figure_->setObjectName("figure");
    views_->addTab(figure_, tr("Figure"));
    right->addWidget(views_);
    auto* lower = new QSplitter(Qt::Horizontal);
    lower->addWidget(steps_);
    // The tape over the verification's findings.
    auto* tape = new QSplitter(Qt::Vertical);
    tape->addWidget(nc_);
    tape->addWidget(verify_);
    tape->setStretchFactor(0, 3);
    tape->setStretchFactor(1, 1);
    lower->addWidget(tape);
    // The step list's columns (No., unit, step, tool, S, F, depths, time)
    // fit without scrolling sideways on a 1600-pixel screen.
    lower->setStretchFactor(0, 13);
    lower->setStretchFactor(1, 7);
    right->addWidget(lower);
    right->setSizes({500, 440});
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(stale_);
    layout->addWidget(right, 1);
    return box;
}

void StationWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, files_, &FileActions::newJob);
    file->addAction(tr("&Open…"), QKeySequence::Open, files_, &FileActions::open);
    QMenu* recent = file->addMenu(tr("Open &recent"));
    connect(recent, &QMenu::aboutToShow, this, [this, recent] { files_->fillRecentMenu(recent); });
    file->addAction(tr("&Import turned part (STEP)…"), files_, &FileActions::importStep);
    file->addAction(tr("Import &DXF contours…"), this, &StationWindow::importDxf)->setObjectName("action.importDxf");
    file->addAction(tr("&Save"), QKeySequence::Save, files_, &FileActions::save);
    file->addAction(tr("Save &as…"), QKeySequence::SaveAs, files_, &FileActions::saveAs);
    file->addSeparator();
    file->addAction(tr("&Export tape and sheet…"), QKeySequence(tr("Ctrl+E")), files_, &FileActions::exportJob);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* job = menuBar()->addMenu(tr("&Job"));
    for (const ModuleKind* kind : moduleKinds()) {
        const QString name = QString::fromUtf8(kind->name());
        job->addAction(QCoreApplication::translate("taiwa::ui::ModulePalette", kind->paletteText()), this,
                       [this, name] { addUnit(name); });
    }
    job->addSeparator();
    job->addAction(tr("&Technology data…"), QKeySequence(tr("Ctrl+T")), this, &StationWindow::editTechnology);
    job->addAction(tr("Tool &library…"), QKeySequence(tr("Ctrl+L")), this, &StationWindow::showToolLibrary);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QMenu* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(this);
    for (const auto& [code, name] : availableLanguages()) {
        QAction* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(code == savedLanguage());
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = code] {
            saveLanguage(code);
            statusBar()->showMessage(tr("The language changes when Taiwa is started again."), 8000);
        });
    }
    // The grid the 3-D view simulates the stock on: finer shows more, takes
    // longer after each change. Kept across sessions.
    QMenu* grid = view->addMenu(tr("Stock &grid"));
    grid->setObjectName("menu.stockGrid");
    auto* grids = new QActionGroup(this);
    const int saved = std::clamp(QSettings().value("preview/stockGrid", 1).toInt(), 0, int(std::size(sim::kStockGrids)) - 1);
    runner_->setStockGrid(sim::kStockGrids[saved]);
    const QString names[] = {tr("Fine: %1 mm, up to %2 cells"), tr("Standard: %1 mm, up to %2 cells"),
                             tr("Coarse: %1 mm, up to %2 cells")};
    for (int k = 0; k < int(std::size(sim::kStockGrids)); ++k) {
        const sim::StockGrid g = sim::kStockGrids[k];
        QAction* a = grid->addAction(names[k].arg(g.finest).arg(QLocale().toString(qulonglong(g.maxCells))));
        a->setObjectName(QStringLiteral("stockGrid.%1").arg(k));
        a->setCheckable(true);
        a->setChecked(k == saved);
        grids->addAction(a);
        connect(a, &QAction::triggered, this, [this, k, g] {
            QSettings().setValue("preview/stockGrid", k);
            runner_->setStockGrid(g);
            // What this job's stock gets: the grid is coarser on a stock too large for its cells.
            const double cell = sim::HeightField::cellSizeFor(doc_->job().stock, g.maxCells, g.finest);
            statusBar()->showMessage(tr("Stock grid: %1 mm cells on this stock").arg(cell, 0, 'g', 3), 8000);
        });
    }
}

void StationWindow::wire()
{
    connect(doc_, &JobDocument::changed, this, &StationWindow::onDocumentChanged);
    connect(doc_, &JobDocument::selectionRequested, units_, &UnitListPanel::selectUnit);
    connect(doc_, &JobDocument::modifiedChanged, this, &StationWindow::updateTitle);
    connect(palette_, &ModulePalette::addModule, this, &StationWindow::addUnit);
    connect(units_, &UnitListPanel::currentUnitChanged, this, &StationWindow::onUnitSelected);
    for (const auto& [name, f] : unitForms_) {
        connect(f, &UnitForm::edited, this,
                [this, form = f](int field, std::optional<double> v) { onFieldEdited(form, field, v); });
        connect(f, &UnitForm::textEdited, this, [this, form = f](int field, const QString& typed) {
            const int u = units_->currentUnit();
            if (u < 0 || form != currentForm()) return;
            const FieldSpec& spec = form->fields()[static_cast<std::size_t>(field)];
            Job j = doc_->job();
            spec.setText(j.units[static_cast<std::size_t>(u)], typed);
            doc_->edit(j, tr("Edit %1 of unit %2").arg(spec.label).arg(u + 1), QStringLiteral("%1:%2").arg(u).arg(spec.key));
        });
        connect(f, &UnitForm::fieldLeft, doc_, &JobDocument::breakMerge);
        // Enter in a unit's last field: the next unit's first field, or after
        // the last unit the step list.
        connect(f, &UnitForm::lastFieldDone, this, [this] {
            const int next = units_->currentUnit() + 1;
            if (next < static_cast<int>(doc_->job().units.size())) {
                units_->selectUnit(next);
                if (UnitForm* form = currentForm()) form->focusFirstField();
            } else {
                steps_->table()->setFocus(Qt::OtherFocusReason);
            }
        });
        connect(f, &UnitForm::unitEdited, this, [this](const ModuleInput& after, const QString& text, const QString& key) {
            const int u = units_->currentUnit();
            if (u < 0) return;
            Job j = doc_->job();
            j.units[static_cast<std::size_t>(u)].module = after;
            // A table cell is committed whole: each commit is an undo step of
            // its own, kept as typing so that the open cell editor stays.
            doc_->edit(j, tr("%1 of unit %2").arg(text).arg(u + 1), key.isEmpty() ? QString() : QStringLiteral("%1:%2").arg(u).arg(key));
            doc_->breakMerge();
        });
        connect(f, &UnitForm::nameEdited, this, [this](const QString& typed) {
            const int u = units_->currentUnit();
            if (u < 0) return;
            Job j = doc_->job();
            j.units[static_cast<std::size_t>(u)].name = typed.toStdString();
            doc_->edit(j, tr("Rename unit %1").arg(u + 1), QStringLiteral("%1:name").arg(u));
        });
    }
    connect(runner_, &PlanRunner::checked, this, [this](const Diagnostics& ds) {
        diagnostics_ = ds;
        showDiagnostics();
        showStale();
    });
    catchUpTimer_ = new QTimer(this);
    catchUpTimer_->setSingleShot(true);
    connect(catchUpTimer_, &QTimer::timeout, this, &StationWindow::catchUp);
    // An edit: the step list at once; the NC text of an older plan still put
    // off is not wanted any more.
    connect(runner_, &PlanRunner::stepsPlanned, this, [this](std::shared_ptr<const Plan> plan) {
        catchUpTimer_->stop();
        later_.reset();
        catchUpAfterFrame_ = false;
        steps_->setPlan(plan);
    });
    // The full plan: the 3-D view first, the NC text and the step list's
    // times after its frame is on screen (catchUp; the view's frame request
    // waits for the platform's next update, which a 0 ms timer overtook), as
    // soon as the GUI is free when the last catch-up fit in a frame (33 ms);
    // for a job whose tape takes the GUI longer, once the typing pauses for
    // twice that long (at most 1 s), so that keystrokes are not kept waiting
    // for a tape about to be replaced. A view that draws no frame (hidden
    // behind the figure tab, minimised) holds nothing up; one whose frame is
    // lost holds it up for 100 ms at most.
    connect(runner_, &PlanRunner::programReady, this,
            [this](std::shared_ptr<const Plan> plan, const QString& nc, const std::vector<BlockSource>& lines) {
                if (plan) {
                    later_ = Later{plan, nc, lines};
                    nc_->prepareProgram(nc);  // its text made on another core while the 3-D view draws
                    catchUpAfterFrame_ = preview_ && preview_->drawsFrames();
                    if (catchUpAfterFrame_) catchUpTimer_->start(100);
                    else scheduleCatchUp();
                } else if (!hasErrors(diagnostics_)) {
                    nc_->setMessage(nc);  // with input errors the last program stays, marked stale
                }
                onProgram(plan);
                showStale();
            });
    connect(runner_, &PlanRunner::flushed, this, &StationWindow::catchUp);
    if (preview_)
        connect(preview_, &PreviewWidget::frameShown, this, [this] {
            if (!catchUpAfterFrame_) return;
            catchUpAfterFrame_ = false;
            scheduleCatchUp();
        });
    // One dialect, the job's (docs/job-format.md `dialect`): the chooser
    // shows it, the program on view is posted in it, the export offers it.
    // Choosing another is an edit of the job (undoable); a new job takes the
    // one last chosen.
    connect(nc_, &NcView::dialectChanged, this, [this](const QString& d) {
        rememberDialect(d);
        Job after = doc_->job();
        after.dialect = d.toStdString();
        doc_->edit(after, tr("Dialect %1").arg(d));
    });
    connect(steps_, &StepPanel::stepSelected, nc_, &NcView::showStep);
    // The block played in the tape: its line, or (a move the tape writes
    // with the one before it) the last line written up to it.
    connect(steps_, &StepPanel::playheadMoved, nc_, [this](int step, int move) {
        for (int m = move; step >= 0 && m >= 0; --m)
            if (nc_->selectMove(step, m)) break;
    });
    // A finding chosen: its step in the list, its block in the tape, its
    // point marked in the 3-D view.
    connect(verify_, &VerificationPanel::findingSelected, this, [this](int step, int move, Point3 where) {
        if (step >= 0) steps_->selectStep(step);
        if (step >= 0 && move >= 0) nc_->selectMove(step, move);
        else if (step >= 0) nc_->showStep(step);
        if (!preview_) return;
        preview_->highlightMove(step, move);
        // A lathe finding's X is a diameter; the lathe view has the spindle
        // along its X and the radius up, in the section's plane.
        const Plan* shown = preview_->scene().plan();
        preview_->markPoint(shown && shown->mmJob.bar ? Point3{where.z, 0.0, where.x / 2.0} : where);
    });
    // S or F typed in the step list: the unit's speed or feed for steps of
    // that kind, an edit of the job (undoable); an emptied cell removes it.
    connect(steps_->table(), &StepTable::cuttingEdited, this,
            [this](int u, const QString& key, bool speed, std::optional<double> value) {
                Job j = doc_->job();
                if (u < 0 || static_cast<std::size_t>(u) >= j.units.size()) return;
                auto& cutting = j.units[static_cast<std::size_t>(u)].cutting;
                CuttingOverride& o = cutting[key.toStdString()];
                (speed ? o.speed : o.feed) = value;
                if (o.empty()) cutting.erase(key.toStdString());
                doc_->edit(j, (speed ? tr("Spindle speed of %1, unit %2") : tr("Feed of %1, unit %2")).arg(key).arg(u + 1));
            });
    connect(files_, &FileActions::message, this, [this](const QString& m) { statusBar()->showMessage(m, 5000); });
    connect(units_, &UnitListPanel::message, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    if (!preview_) return;
    runner_->setSimulateStock(true);
    connect(steps_, &StepPanel::stepSelected, preview_, &PreviewWidget::setSelectedStep);
    preview_->setShowStock(steps_->stockShown());
    preview_->setStockBefore(steps_->stockBefore());
    connect(steps_, &StepPanel::showStockToggled, preview_, &PreviewWidget::setShowStock);
    connect(steps_, &StepPanel::stockBeforeToggled, preview_, &PreviewWidget::setStockBefore);
    connect(steps_, &StepPanel::viewRequested, preview_, [this](ViewButton v) {
        preview_->setView(v == ViewButton::Top     ? viz::ViewPreset::Top
                          : v == ViewButton::Front ? viz::ViewPreset::Front
                                                   : viz::ViewPreset::Iso);
    });
    connect(nc_, &NcView::moveSelected, preview_, &PreviewWidget::highlightMove);
    // Play block by block: the material coming off in the preview, the
    // block in the tape.
    connect(steps_, &StepPanel::playheadMoved, preview_, &PreviewWidget::setPlayhead);
    connect(preview_, &PreviewWidget::moveClicked, nc_, &NcView::selectMove);
    connect(preview_, &PreviewWidget::moveClicked, preview_, &PreviewWidget::highlightMove);
    connect(section_, &SectionBar::sectionChanged, preview_, &PreviewWidget::setSection);
    connect(verify_, &VerificationPanel::colourMapChanged, preview_, &PreviewWidget::setDeviationMap);
}

StepTable* StationWindow::stepTable() const { return steps_->table(); }

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
    nc_->setDialect(dialect);
    units_->refresh();
    jobProps_->refresh(!fromTyping);
    const Machine* machine = findMachine(doc_->job().machine);
    palette_->setMachineKind(machine ? machine->kind : MachineKind::Mill);
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
    runner_->update(doc_->job());
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
    nc_->setProgram(l.nc, l.lines);  // a milling or a lathe tape
    steps_->setPlan(l.plan);         // the same steps, now with times; re-selects the step in the preview
    catchUpMs_ = took.elapsed();
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
            unitText << (d.field.empty() ? QString() : fieldText(d.field) + ": ") + coreMessage(d.message);
    unitMessages_->setText(unitText.join("\n"));
    jobProps_->showDiagnostics(jobLevel);
    QStringList status;
    for (const Diagnostic& d : jobLevel)
        status << (d.field.empty() ? QString() : fieldText(d.field) + ": ") + coreMessage(d.message);
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
    dialog.exec();
    if (!dialog.changed()) return;
    runner_->reloadLibrary();
    runner_->update(doc_->job());
}

void StationWindow::updateTitle()
{
    const QString name = doc_->path().isEmpty() ? tr("untitled") : QFileInfo(doc_->path()).fileName();
    // An unnamed job's program is named after its file, as export names it.
    runner_->setFileStem(FileActions::exportStem(doc_->path()));
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
