// Autosave of the edited job into its recovery file.
#include "ui/autosave.h"

#include "io/job_io.h"
#include "job/job_file.h"
#include "ui/job_document.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTimer>

namespace taiwa::ui {

Autosaver::Autosaver(JobDocument* doc, QObject* parent) : QObject(parent), doc_(doc), timer_(new QTimer(this))
{
    timer_->setInterval(kIntervalMs);
    connect(timer_, &QTimer::timeout, this, &Autosaver::saveNow);
    timer_->start();
    connect(doc_, &JobDocument::modifiedChanged, this, [this](bool modified) {
        if (modified) return;
        removeRecovery(doc_->path());  // saved, or a fresh document
        written_.reset();
    });
}

QString Autosaver::recoveryPath(const QString& jobPath)
{
    QString dir = qEnvironmentVariable("TAIWA_AUTOSAVE_DIR");
    if (dir.isEmpty()) dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QString name = QStringLiteral("untitled");
    if (!jobPath.isEmpty()) {
        const QByteArray abs = QFileInfo(jobPath).absoluteFilePath().toUtf8();
        name = QFileInfo(jobPath).completeBaseName() + "-" +
               QString::fromLatin1(QCryptographicHash::hash(abs, QCryptographicHash::Sha1).toHex().left(12));
    }
    return QDir(dir).filePath(QStringLiteral("recovery-%1.taiwa").arg(name));
}

std::optional<Job> Autosaver::pendingRecovery(const QString& jobPath)
{
    const QFileInfo recovery(recoveryPath(jobPath));
    if (!recovery.exists()) return std::nullopt;
    if (!jobPath.isEmpty()) {
        const QFileInfo job(jobPath);
        if (job.exists() && job.lastModified() >= recovery.lastModified()) return std::nullopt;
    }
    return readJobFile(recovery.filePath().toStdString()).job;
}

void Autosaver::removeRecovery(const QString& jobPath) { QFile::remove(recoveryPath(jobPath)); }

void Autosaver::saveNow()
{
    if (writtenFor_ != doc_->path() && written_) {
        removeRecovery(writtenFor_);  // saved under another name since
        written_.reset();
    }
    if (!doc_->isModified() || (written_ && *written_ == doc_->job())) return;
    const QString path = recoveryPath(doc_->path());
    QDir().mkpath(QFileInfo(path).absolutePath());
    if (const auto written = writeFileAtomically(path.toStdString(), writeJob(doc_->job())); !written) {
        qWarning("taiwa: autosave failed: %s", written.error().c_str());
        return;
    }
    written_ = doc_->job();
    writtenFor_ = doc_->path();
}

}  // namespace taiwa::ui
