// The edited job and its undo commands.
#include "ui/job_document.h"

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>

#include "io/job_io.h"
#include "job/job_file.h"

#include <QUndoCommand>
#include <QUndoStack>

namespace taiwa::ui {
namespace {

// One edit of the job, kept as the job before and after (jobs are small).
class JobEditCommand : public QUndoCommand {
public:
    JobEditCommand(JobDocument* doc, Job before, Job after, const QString& text, QString mergeKey, int selection)
        : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)),
          mergeKey_(std::move(mergeKey)), selection_(selection)
    {
    }
    int id() const override { return mergeKey_.isEmpty() ? -1 : 1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* o = static_cast<const JobEditCommand*>(other);
        if (o->mergeKey_ != mergeKey_) return false;
        after_ = o->after_;
        setObsolete(after_ == before_);  // typed back to where it was: no undo step
        return true;
    }
    void redo() override
    {
        doc_->apply(after_, selection_, first_ && !mergeKey_.isEmpty());
        first_ = false;
    }
    void undo() override { doc_->apply(before_, selection_, false); }

private:
    JobDocument* doc_;
    Job before_, after_;
    QString mergeKey_;
    int selection_;
    bool first_ = true;
};

}  // namespace

JobDocument::JobDocument(QObject* parent) : QObject(parent), undo_(new QUndoStack(this))
{
    connect(undo_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
}

bool JobDocument::isModified() const { return dirtyWithoutUndo_ || !undo_->isClean(); }

void JobDocument::edit(const Job& after, const QString& text, const QString& mergeKey, int selection)
{
    if (after == job_) return;
    const bool wasModified = isModified();
    const QString key = mergeKey.isEmpty() ? QString() : QStringLiteral("%1#%2").arg(mergeKey).arg(mergeEpoch_);
    undo_->push(new JobEditCommand(this, job_, after, text, key, selection));
    if (wasModified != isModified()) emit modifiedChanged(isModified());
}

void JobDocument::apply(const Job& job, int selection, bool fromTyping)
{
    job_ = job;
    emit changed(fromTyping);
    if (selection >= 0) emit selectionRequested(selection);
}

namespace {

// What the file holds now, as a hash; empty when there is no such file.
QByteArray contentStamp(const QString& path)
{
    QFile f(path);
    if (path.isEmpty() || !f.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha1);
}

}  // namespace

bool JobDocument::changedOnDisk() const
{
    if (path_.isEmpty() || !QFileInfo::exists(path_)) return false;
    return contentStamp(path_) != diskStamp_;
}

void JobDocument::reset(const Job& job, const QString& path, bool modified)
{
    emit replacing();
    undo_->clear();
    job_ = job;
    path_ = path;
    diskStamp_ = contentStamp(path);
    dirtyWithoutUndo_ = modified;
    emit changed(false);
    emit selectionRequested(job_.units.empty() ? -1 : 0);
    emit modifiedChanged(isModified());
}

QString JobDocument::saveTo(const QString& path)
{
    const std::string text = writeJob(job_);
    if (const auto written = writeFileAtomically(path.toStdString(), text); !written)
        return QString::fromStdString(written.error());
    diskStamp_ = QCryptographicHash::hash(QByteArray::fromStdString(text), QCryptographicHash::Sha1);
    path_ = path;
    dirtyWithoutUndo_ = false;
    undo_->setClean();
    emit modifiedChanged(isModified());
    return {};
}

void JobDocument::markSavedElsewhere()
{
    path_.clear();
    diskStamp_.clear();
    dirtyWithoutUndo_ = false;
    undo_->setClean();
    emit modifiedChanged(isModified());
}

}  // namespace taiwa::ui
