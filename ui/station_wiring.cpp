// The station window's wiring (StationWindow::wire): which signal of the
// document, the plan runner, the forms and the panels reaches which view,
// and in what order an edit's results are shown.
#include "ui/station_window.h"

#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/module_palette.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/section_bar.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/two_path_views.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"
#include "ui/verification_panel.h"

#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace taiwa::ui {

void StationWindow::wire()
{
    wireUnitForms();
    wirePlanRunner();
    wireStepsAndTape();
    wirePreview();
    wireTwoPath();
}

// The document, the palette, the unit list and each module's form: an edit
// typed or committed in a form is an edit of the job.
void StationWindow::wireUnitForms()
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
}

// The plan runner: its diagnostics, the step list at once, the 3-D view, the
// NC text and the step list's times caught up after the view's frame.
void StationWindow::wirePlanRunner()
{
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
    // The full plan: the 3-D view first (its frame at the next pass of the
    // event loop), the NC text and the step list's times after that frame
    // is on screen (catchUp; a 0 ms timer overtook the platform's update), as
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
                    nc_->prepareProgram(nc);  // its text made on the maker's thread, below the 3-D view's
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
}

// The dialect chooser, the step list, the tape and the verification's
// findings, each showing what another chose; the status bar's messages.
void StationWindow::wireStepsAndTape()
{
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
    // A step chosen: its unit's form beside it.
    connect(steps_, &StepPanel::stepChosen, this, [this](int step) {
        const Plan* plan = steps_->plan().get();
        if (!plan || step < 0 || step >= static_cast<int>(plan->steps.size())) return;
        const int unit = plan->steps[static_cast<std::size_t>(step)].unit;
        if (unit >= 0 && unit != units_->currentUnit() && unit < static_cast<int>(doc_->job().units.size()))
            units_->selectUnit(unit);
    });
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
    connect(runner_, &PlanRunner::toolsChangedOnServer, this, [this](const QString& m) {
        statusBar()->showMessage(m, 15000);
        runner_->update(doc_->job());
    });
}

// The 3-D view, when there is one: the step shown, the stock, the view
// buttons, the playhead, a move clicked, the section and the colour map.
void StationWindow::wirePreview()
{
    if (!preview_) return;
    runner_->setSimulateStock(true);
    connect(steps_, &StepPanel::stepSelected, preview_, &PreviewWidget::setSelectedStep);
    preview_->setShowStock(steps_->stockShown());
    preview_->setStockBefore(steps_->stockBefore());
    connect(steps_, &StepPanel::showStockToggled, preview_, &PreviewWidget::setShowStock);
    connect(steps_, &StepPanel::stockBeforeToggled, preview_, &PreviewWidget::setStockBefore);
    preview_->setPathsShown(steps_->pathsShown());
    connect(steps_, &StepPanel::showPathsToggled, preview_, &PreviewWidget::setPathsShown);
    connect(steps_, &StepPanel::viewRequested, preview_, [this](ViewButton v) {
        if (v == ViewButton::Step) return preview_->frameSelectedStep();
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

// A two-path job's views: a step or block chosen in the steps by path or
// the chart reaches the step list, the tapes and the 3-D view; the block
// played, or a roughing line chosen in either tape, reaches them back.
void StationWindow::wireTwoPath()
{
    connect(twoPath_->steps(), &TwoPathSteps::stepChosen, steps_, &StepPanel::selectStep);
    connect(twoPath_, &TwoPathViews::blockChosen, this, [this](int step, int move, int path) {
        steps_->selectStep(step);
        tapes_->setCurrentIndex(path > 0 ? 1 : 0);
        if (path == 0) nc_->selectMove(step, move);
        if (preview_) preview_->highlightMove(step, move);
    });
    connect(steps_, &StepPanel::playheadMoved, twoPath_, &TwoPathViews::followMove);
    connect(nc_, &NcView::moveSelected, twoPath_, &TwoPathViews::followMove);
    connect(twoPath_->tape(), &NcView::moveSelected, twoPath_, &TwoPathViews::followMove);
    if (preview_) {
        connect(twoPath_->tape(), &NcView::moveSelected, preview_, &PreviewWidget::highlightMove);
        connect(preview_, &PreviewWidget::moveClicked, twoPath_, &TwoPathViews::followMove);
    }
}

}  // namespace taiwa::ui
