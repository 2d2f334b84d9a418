// The job being edited: the Job value, its file, the undo stack (one command
// per field edit, merged while the same field is typed; add/remove/move unit)
// and the modified state shown in the title.
#pragma once

#include "model/job.h"

#include <QByteArray>
#include <QObject>
#include <QString>

class QUndoStack;

namespace taiwa::ui {

class JobDocument : public QObject {
    Q_OBJECT
public:
    explicit JobDocument(QObject* parent = nullptr);

    const Job& job() const { return job_; }
    const QString& path() const { return path_; }
    QUndoStack* undoStack() const { return undo_; }
    bool isModified() const;

    // Replaces the job as one undoable edit. mergeKey non-empty: consecutive
    // edits with the same key merge into one undo step. `selection` is the
    // unit selected after the edit (-1: keep).
    void edit(const Job& after, const QString& text, const QString& mergeKey = {}, int selection = -1);
    // Ends the current run of merging edits (the operator left the field):
    // the next edit is a new undo step even with the same merge key.
    void breakMerge() { ++mergeEpoch_; }
    // A new document (undo history cleared); modified = the job is not on disk.
    void reset(const Job& job, const QString& path, bool modified);
    // Writes the job to path atomically; empty string on success, else the error.
    QString saveTo(const QString& path);
    // The job was saved elsewhere than in a file (the shop server's job
    // store, ui/store_actions.h): no file, not modified.
    void markSavedElsewhere();
    // The job's file was changed by someone else (another window, another
    // program) since this document opened or saved it.
    bool changedOnDisk() const;

    // Called by the undo commands only.
    void apply(const Job& job, int selection, bool fromTyping);

signals:
    // The job changed; fromTyping: by a field edit as it is typed (forms keep
    // their text), else by undo/redo/open (forms show the values).
    void changed(bool fromTyping);
    void selectionRequested(int unit);
    void modifiedChanged(bool modified);
    // reset() is about to replace the job by another (opened, new, restored).
    void replacing();

private:
    Job job_;
    QString path_;
    QByteArray diskStamp_;  // hash of the file as this document last read or wrote it
    QUndoStack* undo_;
    bool dirtyWithoutUndo_ = false;
    int mergeEpoch_ = 0;
};

}  // namespace taiwa::ui
