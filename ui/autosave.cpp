// Autosave of the edited job into its recovery file.
#include "ui/autosave.h"

#include "io/job_io.h"
#include "job/job_file.h"
#include "ui/job_document.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTimer>

#include <cerrno>
#include <csignal>
#include <set>

namespace taiwa::ui {

namespace {

// The windows of this process whose autosaver lives (GUI thread only).
std::set<int>& liveInstances()
{
    static std::set<int> live;
    return live;
}

QString autosaveDir()
{
    QString dir = qEnvironmentVariable("TAIWA_AUTOSAVE_DIR");
    if (dir.isEmpty()) dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return dir;
}

// "recovery-NAME-HASH" of a job file, "recovery-untitled" of a new job.
QString recoveryStem(const QString& jobPath)
{
    QString name = QStringLiteral("untitled");
    if (!jobPath.isEmpty()) {
        const QByteArray abs = QFileInfo(jobPath).absoluteFilePath().toUtf8();
        name = QFileInfo(jobPath).completeBaseName() + "-" +
               QString::fromLatin1(QCryptographicHash::hash(abs, QCryptographicHash::Sha1).toHex().left(12));
    }
    return QStringLiteral("recovery-%1").arg(name);
}

// Whether the owner named in a recovery file's name ("STEM.PID-N.taiwa") is
// gone: its process dead, or, in this process, its window closed. A file
// naming no owner (written by an older Taiwa) counts as gone.
bool ownerGone(const QString& fileName, const QString& stem)
{
    const QString owner = fileName.mid(stem.size() + 1).chopped(QStringLiteral(".taiwa").size());
    const auto dash = owner.indexOf('-');
    bool pidOk = false, instanceOk = false;
    const qint64 pid = owner.left(dash).toLongLong(&pidOk);
    const int instance = owner.mid(dash + 1).toInt(&instanceOk);
    if (dash < 0 || !pidOk || !instanceOk) return true;
    if (pid == QCoreApplication::applicationPid()) return !liveInstances().count(instance);
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

Autosaver::Autosaver(JobDocument* doc, QObject* parent) : QObject(parent), doc_(doc), timer_(new QTimer(this))
{
    static int instances = 0;
    instance_ = ++instances;
    liveInstances().insert(instance_);
    timer_->setInterval(kIntervalMs);
    connect(timer_, &QTimer::timeout, this, &Autosaver::saveNow);
    timer_->start();
    connect(doc_, &JobDocument::modifiedChanged, this, [this](bool modified) {
        if (modified) return;
        removeRecovery(doc_->path());  // saved, or a fresh document
        written_.reset();
    });
}

// The window is gone: its recovery file stays for the next start (as after a
// kill), unless a clean close removed it; its open mark goes.
Autosaver::~Autosaver()
{
    liveInstances().erase(instance_);
    if (!openMark_.isEmpty()) QFile::remove(openMark_);
}

void Autosaver::markOpen(const QString& jobPath)
{
    const QString mark = jobPath.isEmpty() ? QString()
                                           : QDir(autosaveDir()).filePath(QStringLiteral("open-%1.%2-%3.taiwa")
                                                                              .arg(recoveryStem(jobPath).mid(9))
                                                                              .arg(QCoreApplication::applicationPid())
                                                                              .arg(instance_));
    if (mark == openMark_) return;
    if (!openMark_.isEmpty()) QFile::remove(openMark_);
    openMark_ = mark;
    if (mark.isEmpty()) return;
    QDir().mkpath(autosaveDir());
    QFile f(mark);
    if (f.open(QIODevice::WriteOnly)) f.write(QFileInfo(jobPath).absoluteFilePath().toUtf8());
}

int Autosaver::openElsewhere(const QString& jobPath, const Autosaver* self)
{
    if (jobPath.isEmpty()) return 0;
    const QString stem = QStringLiteral("open-") + recoveryStem(jobPath).mid(9);
    int n = 0;
    for (const QString& f : QDir(autosaveDir()).entryList({stem + ".*.taiwa"}, QDir::Files)) {
        const QString path = QDir(autosaveDir()).filePath(f);
        if (self && path == self->openMark_) continue;
        if (ownerGone(f, stem)) QFile::remove(path);  // a window that died with the job open
        else ++n;
    }
    return n;
}

QString Autosaver::recoveryPath(const QString& jobPath) const
{
    return QDir(autosaveDir())
        .filePath(QStringLiteral("%1.%2-%3.taiwa").arg(recoveryStem(jobPath)).arg(QCoreApplication::applicationPid()).arg(instance_));
}

QStringList Autosaver::recoveryFiles(const QString& jobPath)
{
    const QString stem = recoveryStem(jobPath);
    QStringList out;
    for (const QString& f : QDir(autosaveDir()).entryList({stem + ".*.taiwa", stem + ".taiwa"}, QDir::Files))
        out << QDir(autosaveDir()).filePath(f);
    return out;
}

QString Autosaver::pendingRecoveryFile(const QString& jobPath)
{
    const QString stem = recoveryStem(jobPath);
    QString best;
    QDateTime newest;
    for (const QString& path : recoveryFiles(jobPath)) {
        const QFileInfo recovery(path);
        if (!ownerGone(recovery.fileName(), stem)) continue;  // a window still editing it
        if (!jobPath.isEmpty()) {
            const QFileInfo job(jobPath);
            if (job.exists() && job.lastModified() >= recovery.lastModified()) continue;
        }
        if (best.isEmpty() || recovery.lastModified() > newest) best = path, newest = recovery.lastModified();
    }
    return best;
}

std::optional<Job> Autosaver::pendingRecovery(const QString& jobPath)
{
    const QString file = pendingRecoveryFile(jobPath);
    if (file.isEmpty()) return std::nullopt;
    return readJobFile(file.toStdString()).job;
}

void Autosaver::removeRecovery(const QString& jobPath) const { QFile::remove(recoveryPath(jobPath)); }

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
