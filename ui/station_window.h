// The station's main window: wires the module palette, unit list, job
// properties, module forms, step panel, 3-D preview and NC view to the job
// document, the plan runner, autosave and the file actions. It owns no
// logic of its own beyond passing signals on.
#pragma once

#include "model/diagnostic.h"
#include "pipeline/pipeline.h"

#include <QMainWindow>

#include <map>
#include <memory>
#include <string>
#include <optional>
#include <vector>

class QLabel;
class QStackedWidget;
class QTimer;
class QTabWidget;

namespace taiwa::ui {

class Autosaver;
class FigurePanel;
class FileActions;
class JobDocument;
class JobProperties;
class ModulePalette;
class NcView;
class PlanRunner;
class PreviewWidget;
class SectionBar;
class StepPanel;
class StepTable;
class TwoPathViews;
class UnitForm;
class UnitListPanel;
class VerificationPanel;

class StationWindow : public QMainWindow {
    Q_OBJECT
public:
    // jobPath empty: a new job. Either way a newer recovery file of that job
    // (left by a crash) is offered first.
    explicit StationWindow(const QString& jobPath = {}, QWidget* parent = nullptr);

    JobDocument* document() const { return doc_; }
    PlanRunner* planRunner() const { return runner_; }
    FileActions* fileActions() const { return files_; }
    Autosaver* autosaver() const { return autosave_; }
    UnitListPanel* unitList() const { return units_; }
    StepPanel* stepPanel() const { return steps_; }
    StepTable* stepTable() const;
    NcView* ncView() const { return nc_; }
    VerificationPanel* verificationPanel() const { return verify_; }
    PreviewWidget* preview() const { return preview_; }
    SectionBar* sectionBar() const { return section_; }
    // A two-path job's step list by path, timeline chart and path 2's tape
    // (shown only for a job on a two-path lathe; docs/two-path-lathe.md).
    TwoPathViews* twoPathViews() const { return twoPath_; }
    // The figure elements of a milling job, in a tab beside the 3-D view.
    FigurePanel* figurePanel() const { return figure_; }
    // Shows the figure tab (true) or the 3-D view.
    void showFigure(bool figure);
    // File > Import DXF contours: the dialog (ui/dxf_import_dialog.h); what
    // it gives is appended to the job's figure by replaceFigure, one
    // undoable edit that shows the Figure tab.
    void importDxf();
    void replaceFigure(const std::string& figure, const QString& what);

protected:
    void closeEvent(QCloseEvent* e) override;
    // The language switched (View > Language): menus, panels' titles, and
    // what the window shows from the core in the new language.
    void changeEvent(QEvent* e) override;

private:
    QWidget* buildLeft();
    QWidget* buildCentre();
    QWidget* buildRight();
    void buildMenus();
    // The window's own words on its panels (group titles, tabs, buttons), in
    // the language in force: at construction and on a language switch.
    void nameParts();
    // The signals wired to the views (station_wiring.cpp), in this order:
    // the document and the unit forms, the plan runner, the step list, tape
    // and findings, the 3-D view.
    void wire();
    void wireUnitForms();
    void wirePlanRunner();
    void wireStepsAndTape();
    void wirePreview();
    void wireTwoPath();
    // The two-path views shown (a job on a two-path lathe) or hidden.
    void showTwoPath(bool on);
    void onDocumentChanged(bool fromTyping);
    void onUnitSelected(int unit);
    void onFieldEdited(UnitForm* form, int field, std::optional<double> value);
    void onProgram(std::shared_ptr<const Plan> plan);
    // The NC text and the step list's times of the newest plan, put off
    // until the 3-D view has it (docs/station.md, "From a keystroke to the views").
    void catchUp();
    // catchUp() at the next pass when the last one fit in a frame, else
    // once the typing pauses.
    void scheduleCatchUp();
    void showDiagnostics();
    void editTechnology();
    void showToolLibrary();
    void updateTitle();
    UnitForm* currentForm() const;
    // The banner over the views while they show the last valid plan.
    void showStale();
    // Adds a unit of that module kind and puts the focus into its first field.
    void addUnit(const QString& module);

    JobDocument* doc_;
    PlanRunner* runner_;
    Autosaver* autosave_;
    FileActions* files_;
    ModulePalette* palette_;
    UnitListPanel* units_;
    JobProperties* jobProps_;
    class FormStack* forms_;
    std::map<std::string, UnitForm*> unitForms_;  // one per module kind, by name
    QLabel* stale_ = nullptr;
    QString openPath_;  // the job file this window has marked open
    QLabel* unitMessages_;
    StepPanel* steps_;
    PreviewWidget* preview_ = nullptr;
    SectionBar* section_ = nullptr;  // under the preview, when there is one
    QTabWidget* views_ = nullptr;     // the 3-D view, the figure
    FigurePanel* figure_ = nullptr;
    NcView* nc_;
    VerificationPanel* verify_;
    TwoPathViews* twoPath_;
    QTabWidget* stepTabs_ = nullptr;  // the step list; by path
    QTabWidget* tapes_ = nullptr;     // the tape (path 1's); path 2's
    Diagnostics diagnostics_;
    struct Later {
        std::shared_ptr<const Plan> plan;
        QString nc;
        std::vector<BlockSource> lines;
    };
    std::optional<Later> later_;  // what catchUp() shows
    QTimer* catchUpTimer_ = nullptr;
    qint64 catchUpMs_ = 0;  // how long the last catchUp() took
    bool catchUpAfterFrame_ = false;  // waiting for the 3-D view's frame of the plan
};

}  // namespace taiwa::ui
