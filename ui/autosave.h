// Crash recovery. Every 3 s while the job has unsaved changes, the job is
// written atomically (writeFileAtomically) to a recovery file in
// $TAIWA_AUTOSAVE_DIR, else the application data folder; one recovery file
// per job file (named after a hash of its absolute path; "untitled" for a
// job never saved). A clean save or close removes it. At start, a recovery
// file newer than the job file is the sign of a crash or kill -9.
#pragma once

#include "model/job.h"

#include <QObject>
#include <QString>

#include <optional>

class QTimer;

namespace taiwa::ui {

class JobDocument;

class Autosaver : public QObject {
    Q_OBJECT
public:
    Autosaver(JobDocument* doc, QObject* parent = nullptr);

    static constexpr int kIntervalMs = 3000;
    // The recovery file of a job file (empty: an untitled job).
    static QString recoveryPath(const QString& jobPath);
    // The job of a recovery file left by a session that did not close, when
    // it is newer than the job file (or the job was untitled).
    static std::optional<Job> pendingRecovery(const QString& jobPath);
    static void removeRecovery(const QString& jobPath);
    // Writes now when the job has changes the recovery file does not have.
    void saveNow();

private:
    JobDocument* doc_;
    QTimer* timer_;
    QString writtenFor_;  // the job path the recovery file was last written for
    std::optional<Job> written_;
};

}  // namespace taiwa::ui
