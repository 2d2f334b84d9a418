// File menu work: open/save, recent files, unsaved-changes prompt, recovery,
// export.
#include "ui/file_actions.h"
#include "ui/core_messages.h"

#include "job/step_job.h"

#include "ui/nc_view.h"

#include "job/job_file.h"
#include "export/export.h"
#include "export/sheet_pictures.h"
#include "export/verification_cache.h"
#include "verify/tape_readback.h"
#include "verify/verify.h"
#include "post/post.h"
#include "ui/autosave.h"
#include "ui/export_dialog.h"
#include "ui/job_document.h"
#include "ui/plan_runner.h"
#include "ui/store_actions.h"
#include "tools/pg_job_store.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include <algorithm>
#include <stdexcept>

namespace taiwa::ui {
namespace {
const char* const kFilter = "Taiwa jobs (*.taiwa);;All files (*)";
const char* const kRecentKey = "recentFiles";
constexpr int kMaxRecent = 8;
}  // namespace

FileActions::FileActions(JobDocument* doc, PlanRunner* runner, Autosaver* autosave, QWidget* window)
    : QObject(window), doc_(doc), autosave_(autosave), runner_(runner), window_(window),
      store_(new StoreActions(doc, this, window))
{
    connect(store_, &StoreActions::message, this, &FileActions::message);
}

QString FileActions::stem() const
{
    if (doc_->path().isEmpty() && !store_->storedName().isEmpty())
        return QString::fromStdString(jobFileStem(store_->storedName().toStdString()));
    return exportStem(doc_->path());
}

QString FileActions::title() const
{
    if (doc_->path().isEmpty() && !store_->storedName().isEmpty()) return tr("%1 (shop server)").arg(store_->storedName());
    return doc_->path().isEmpty() ? tr("untitled") : QFileInfo(doc_->path()).fileName();
}

bool FileActions::promptsDisabled() { return qEnvironmentVariable("TAIWA_NO_PROMPTS") == "1"; }

bool FileActions::maybeSave()
{
    if (!doc_->isModified() || promptsDisabled()) return true;
    const auto answer = QMessageBox::question(window_, tr("Unsaved changes"),
                                              tr("The job has unsaved changes. Save them?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

bool FileActions::newJob()
{
    if (!maybeSave()) return false;
    if (doc_->isModified()) autosave_->removeRecovery(doc_->path());  // the operator discarded the changes
    Job j;
    j.name = tr("New job").toStdString();
    j.dialect = lastChosenDialect().toStdString();
    doc_->reset(j, {}, false);
    return true;
}

bool FileActions::open()
{
    if (!maybeSave()) return false;
    const QString path = QFileDialog::getOpenFileName(window_, tr("Open job"), {}, kFilter);
    return !path.isEmpty() && openPath(path);
}

bool FileActions::importStep()
{
    if (!maybeSave()) return false;
    const QString path = QFileDialog::getOpenFileName(window_, tr("Import a turned part (STEP)"), {},
                                                      tr("STEP models (*.step *.stp *.STEP *.STP)"));
    return !path.isEmpty() && importStepPath(path);
}

bool FileActions::refuseImport(const QString& why)
{
    if (promptsDisabled()) qWarning("taiwa: %s", qPrintable(why));
    else QMessageBox::warning(window_, tr("Cannot import"), why);
    emit message(why);
    return false;
}

void FileActions::takeImported(Job job)
{
    if (doc_->isModified()) autosave_->removeRecovery(doc_->path());  // the operator discarded the changes
    job.dialect = lastChosenDialect().toStdString();
    doc_->reset(job, {}, true);  // untitled and not on disk yet
}

bool FileActions::importStepPath(const QString& path)
{
    auto job = latheJobFromStep(path.toStdString(), "steel-s45c");
    if (!job) return refuseImport(coreMessage(job.error()));
    const std::size_t units = job->units.size();
    takeImported(std::move(*job));
    emit message(tr("Imported %1: %n turned profile(s)", "", static_cast<int>(units)).arg(path));
    return true;
}

bool FileActions::importSurface()
{
    if (!maybeSave()) return false;
    const QString path = QFileDialog::getOpenFileName(window_, tr("Import a surface (STEP face set)"), {},
                                                      tr("STEP models (*.step *.stp *.STEP *.STP)"));
    return !path.isEmpty() && importSurfacePath(path);
}

bool FileActions::importSurfacePath(const QString& path, double spacing)
{
    auto imported = surfaceJobFromStep(path.toStdString(), "aluminium-6061", spacing);
    if (!imported) return refuseImport(coreMessage(imported.error()));
    takeImported(imported->job);
    emit message(tr("Imported %1 as a surface: moved %2 mm in Z to put its top at Z 0; the paths stay within %3 µm of its faces")
                     .arg(path)
                     .arg(-imported->lowered, 0, 'g', 6)
                     .arg(imported->deviation * 1000, 0, 'f', 2));
    return true;
}

bool FileActions::openPath(const QString& path)
{
    const JobReadResult r = readJobFile(path.toStdString());
    if (!r.job) {
        QString why;
        for (const Diagnostic& d : r.diagnostics) why += diagnosticText(path.toStdString(), d) + "\n";
        if (promptsDisabled()) qWarning("taiwa: %s", qPrintable(why));
        else QMessageBox::warning(window_, tr("Cannot open job"), why);
        return false;
    }
    if (doc_->isModified()) autosave_->removeRecovery(doc_->path());  // the operator discarded the changes
    doc_->reset(*r.job, path, false);
    addRecent(path);
    emit message(tr("Opened %1").arg(path));
    return true;
}

bool FileActions::save()
{
    if (doc_->path().isEmpty() && !store_->storedName().isEmpty()) return store_->saveToStore();
    return doc_->path().isEmpty() ? saveAs() : saveTo(doc_->path());
}

bool FileActions::saveAs()
{
    QString path = QFileDialog::getSaveFileName(window_, tr("Save job"), doc_->path(), kFilter);
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += ".taiwa";
    return saveTo(path);
}

bool FileActions::saveTo(const QString& path)
{
    // Never overwrite silently what another window or program saved meanwhile.
    if (path == doc_->path() && doc_->changedOnDisk()) {
        const QString why = tr("%1 was changed on disk since this window opened or saved it (by another window or "
                               "program).").arg(QFileInfo(path).fileName());
        if (promptsDisabled()) {
            qWarning("taiwa: %s Not saved.", qPrintable(why));
            emit message(why + tr(" Not saved: use Save As."));
            return false;
        }
        const auto answer = QMessageBox::question(window_, tr("Save job"), why + tr(" Overwrite it with this window's job?"),
                                                  QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Save) return false;
    }
    const QString err = coreMessage(doc_->saveTo(path).toStdString());
    if (!err.isEmpty()) {
        if (promptsDisabled()) qWarning("taiwa: %s", qPrintable(err));
        else QMessageBox::warning(window_, tr("Cannot save job"), err);
        return false;
    }
    addRecent(path);
    emit message(tr("Saved %1").arg(path));
    return true;
}

QString FileActions::exportStem(const QString& jobPath)
{
    return jobPath.isEmpty() ? QStringLiteral("job") : QFileInfo(jobPath).completeBaseName();
}

void FileActions::exportJob()
{
    runner_->flush();
    const auto plan = runner_->fullPlan();
    if (!plan || !(plan->job == doc_->job())) {
        QMessageBox::warning(window_, tr("Export"), tr("The job has input errors; fix them before exporting."));
        return;
    }
    QStringList dialects;
    for (const auto& d : dialectNames()) dialects << QString::fromStdString(d);
    ExportChoice initial;
    initial.dialect = runner_->dialect();
    initial.resolution = verify::defaultResolution(*plan);
    ExportDialog dialog(ExportDialog::remembered(initial), dialects, window_);
    if (dialog.exec() != QDialog::Accepted) return;
    ExportDialog::remember(dialog.choice());
    exportTo(dialog.choice());
}

bool FileActions::exportTo(const ExportChoice& c)
{
    runner_->flush();
    const auto plan = runner_->fullPlan();
    if (!plan || !(plan->job == doc_->job())) {
        QMessageBox::warning(window_, tr("Export"), tr("The job has input errors; fix them before exporting."));
        return false;
    }
    // Verified first, as `taiwa export` does: a fault is written only when the operator says so.
    std::vector<std::string> faults;
    std::optional<PostedJob> posted;
    const PostOptions post = postOptions(*plan, c.dialect.toStdString(), c.units, ExportOptions{}.programNumber, stem().toStdString());
    try {
        verify::Options v;
        v.resolution = c.resolution;
        // The grid the station would choose is bounded as `taiwa export`'s default is; one typed is kept.
        if (c.resolution == verify::defaultResolution(*plan)) v.maxCellVisits = verify::kDefaultCellVisits;
        // The station's Verify (or a `taiwa verify`) of this very plan stored its report: not run again.
        verify::Report report = verifyPlanCached(*plan, v);
        // The programs posted once and read back (verify/tape_readback.h), as
        // `taiwa export` does; the export writes those very programs.
        try {
            const PostedJob& programs = posted.emplace(postJob(*plan, post));
            verify::placeOnTape(report, programs.tape);
            verify::readBack(report, *plan, programs, post::dialectNamed(post.dialect), post);
        } catch (const Refusal&) {
            posted.reset();  // a dialect that cannot post this job: the export says so
        }
        for (const auto& f : report.findings)
            if (f.fatal()) faults.push_back(verify::describe(f, *plan));
    } catch (const Refusal& e) {
        QMessageBox::warning(window_, tr("Export failed"), coreMessage(e.what()));
        return false;
    }
    if (!faults.empty()) {
        const QString what = tr("The verification found %n faults (the first: %1).", nullptr, static_cast<int>(faults.size()))
                                 .arg(coreMessage(faults.front()));
        if (promptsDisabled()) {
            qWarning("taiwa: %s Nothing was written.", qPrintable(what));
            emit message(what);
            return false;
        }
        if (QMessageBox::question(window_, tr("Export"), what + ' ' + tr("Write the files anyway, with the faults on the sheet?")) !=
            QMessageBox::Yes)
            return false;
    }
    ExportOptions eo;
    eo.dialect = c.dialect.toStdString();
    eo.units = c.units;
    // A stored job: named as `taiwa export --from-store` names it (its fetched file's name).
    eo.jobFile = doc_->path().isEmpty() && !store_->storedName().isEmpty() ? stem().toStdString() + ".taiwa"
                                                                           : QFileInfo(doc_->path()).fileName().toStdString();
    eo.verificationFaults = faults;
    eo.posted = posted ? &*posted : nullptr;
    eo.toolsOrigin = runner_->toolsOrigin();
    // The same drawing as `taiwa export`'s (export/sheet_pictures.h): the same pixels.
    const std::string problem = c.pictures ? addSheetPictures(*plan, eo) : std::string();
    const auto written = exportPlan(*plan, c.folder.toStdString(), stem().toStdString(), eo);
    if (!written) {
        QMessageBox::warning(window_, tr("Export failed"), coreMessage(written.error()));
        return false;
    }
    QString done = tr("Exported %1 files into %2").arg(written->size()).arg(c.folder);
    if (!problem.empty()) done += ' ' + tr("(pictures missing: %1)").arg(QString::fromStdString(problem));
    emit message(done);
    return true;
}

bool FileActions::offerRecovery(const QString& jobPath)
{
    // Only a file whose owner is gone: never the one of a window still editing the job.
    const QString file = Autosaver::pendingRecoveryFile(jobPath);
    if (file.isEmpty()) return false;
    const auto job = readJobFile(file.toStdString()).job;
    if (!job) return false;
    if (!promptsDisabled()) {
        const QString what = jobPath.isEmpty() ? tr("an untitled job") : QFileInfo(jobPath).fileName();
        const auto answer = QMessageBox::question(
            window_, tr("Recover job"),
            tr("Taiwa was not closed properly while editing %1. Its autosaved copy is newer than the file. "
               "Restore the autosaved copy?").arg(what));
        if (answer != QMessageBox::Yes) {
            QFile::remove(file);  // that dead owner's file only
            return false;
        }
    }
    doc_->reset(*job, jobPath, true);
    QFile::remove(file);  // restored: this window's own autosave carries it from here
    if (!jobPath.isEmpty()) addRecent(jobPath);
    emit message(tr("Restored the autosaved job (not saved to a file yet)"));
    return true;
}

void FileActions::addRecent(const QString& path)
{
    QSettings s;
    QStringList files = s.value(kRecentKey).toStringList();
    const QString abs = QFileInfo(path).absoluteFilePath();
    files.removeAll(abs);
    files.prepend(abs);
    while (files.size() > kMaxRecent) files.removeLast();
    s.setValue(kRecentKey, files);
}

void FileActions::fillRecentMenu(QMenu* menu)
{
    menu->clear();
    const QStringList files = QSettings().value(kRecentKey).toStringList();
    for (const QString& f : files)
        menu->addAction(f, this, [this, f] {
            if (maybeSave()) openPath(f);
        });
    if (files.isEmpty()) menu->addAction(tr("(none)"))->setEnabled(false);
}

}  // namespace taiwa::ui
