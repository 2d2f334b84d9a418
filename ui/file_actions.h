// The File menu's work: new, open, save, save as, recent files (QSettings),
// the unsaved-changes prompt (skipped when TAIWA_NO_PROMPTS=1), recovery of
// an autosaved job at start, and export of the planned job (its dialog:
// ui/export_dialog.h).
#pragma once

#include "model/job.h"

#include <QObject>
#include <QStringList>

class QMenu;
class QWidget;

namespace taiwa::ui {

class JobDocument;
class PlanRunner;
class Autosaver;
class StoreActions;
struct ExportChoice;

class FileActions : public QObject {
    Q_OBJECT
public:
    // The stem of an export's files, and the program name of an unnamed job:
    // the job file's base name, "job" while it has none.
    static QString exportStem(const QString& jobPath);
    FileActions(JobDocument* doc, PlanRunner* runner, Autosaver* autosave, QWidget* window);
    // The job store on the shop server (ui/store_actions.h).
    StoreActions* store() const { return store_; }
    // The stem of the shown job's exports: its file's, else its name in the
    // job store's (as `taiwa export --from-store` names them), else "job".
    QString stem() const;
    // The job's name in the title: its file's, else the stored job's.
    QString title() const;

    bool newJob();
    bool open();
    bool openPath(const QString& path);
    // A new, untitled lathe job from a STEP solid of revolution (its turned
    // profiles and a bar that holds it); a refused file says why.
    bool importStep();
    bool importStepPath(const QString& path);
    // A STEP face set as a milling job of one SURFACE unit, sampled every
    // `spacing` mm (job/step_job.h surfaceJobFromStep).
    bool importSurface();
    bool importSurfacePath(const QString& path, double spacing = 0.5);
    // To the job's file; a job opened from the shop server's store there.
    bool save();
    bool saveAs();
    bool saveTo(const QString& path);
    // Asks with the export dialog (ui/export_dialog.h), then exportTo().
    void exportJob();
    // Verifies the planned job at the choice's resolution (faults written
    // only when the operator agrees; never without prompts), draws the
    // sheet's pictures as `taiwa export` does, and writes the export's
    // files; says what it did in message(). Whether the files were written.
    bool exportTo(const ExportChoice& choice);
    // True when the job may be dropped (saved, discarded, or not modified).
    bool maybeSave();
    // At start: offer the recovery file of jobPath (empty: untitled) left by a
    // session that did not close, when it is newer than the file.
    bool offerRecovery(const QString& jobPath);
    // Fills the "Open recent" menu.
    void fillRecentMenu(QMenu* menu);

    static bool promptsDisabled();

signals:
    void message(const QString& text);

private:
    void addRecent(const QString& path);
    // An import refused: said (a box, or a warning when prompts are off) and
    // on the status line; false.
    bool refuseImport(const QString& why);
    // An imported job as the window's, untitled, in the dialect last chosen.
    void takeImported(Job job);
    JobDocument* doc_;
    Autosaver* autosave_;
    PlanRunner* runner_;
    QWidget* window_;
    StoreActions* store_;
};

}  // namespace taiwa::ui
