// Crash recovery. Every 3 s while the job has unsaved changes, the job is
// written atomically (writeFileAtomically) to a recovery file in
// $TAIWA_AUTOSAVE_DIR, else the application data folder: one per job file
// (named after a hash of its absolute path; "untitled" for a job never saved)
// and per window, the file naming its owner (process id and window), so that
// two windows never share one. A clean save or close removes the window's own
// file. At start, a recovery file of an owner that is gone (its process dead,
// or its window closed without saving) and newer than the job file is the
// sign of a crash or kill -9, and only such a file is offered; declining it
// removes it, never a live window's.
#pragma once

#include "model/job.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

class QTimer;

namespace taiwa::ui {

class JobDocument;

class Autosaver : public QObject {
    Q_OBJECT
public:
    Autosaver(JobDocument* doc, QObject* parent = nullptr);

    static constexpr int kIntervalMs = 3000;
    Autosaver(const Autosaver&) = delete;
    Autosaver& operator=(const Autosaver&) = delete;
    ~Autosaver() override;

    // This window's recovery file of a job file (empty: an untitled job).
    QString recoveryPath(const QString& jobPath) const;
    // Every recovery file of a job file, whoever owns it.
    static QStringList recoveryFiles(const QString& jobPath);
    // The newest recovery file of the job whose owner is gone, when it is
    // newer than the job file (or the job was untitled); empty when none.
    static QString pendingRecoveryFile(const QString& jobPath);
    // Its job, when it can be read.
    static std::optional<Job> pendingRecovery(const QString& jobPath);
    // Removes this window's recovery file of the job.
    void removeRecovery(const QString& jobPath) const;
    // Marks the job file as open in this window (an empty path: none), so
    // that another window opening it can warn; the mark goes with the window.
    void markOpen(const QString& jobPath);
    // How many other live windows have the job file open.
    static int openElsewhere(const QString& jobPath, const Autosaver* self);
    // Writes now when the job has changes the recovery file does not have.
    void saveNow();

private:
    JobDocument* doc_;
    QTimer* timer_;
    int instance_;  // this window's number in the process
    QString openMark_;  // this window's mark of the job it has open
    QString writtenFor_;  // the job path the recovery file was last written for
    std::optional<Job> written_;
};

}  // namespace taiwa::ui
