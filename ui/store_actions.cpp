// The job store's File menu items (store_actions.h): a connection of their
// own to the shop server, opened on first use, and the lock of the job shown.
#include "ui/store_actions.h"

#include "job/job_file.h"
#include "tools/pg_job_store.h"
#include "tools/tool_library.h"
#include "ui/core_messages.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>

namespace taiwa::ui {

StoreActions::StoreActions(JobDocument* doc, FileActions* files, QWidget* window)
    : QObject(window), doc_(doc), files_(files), window_(window)
{
    // Another job opened (a file, a new one): this one's lock goes back.
    connect(doc_, &JobDocument::replacing, this, [this] {
        if (!opening_) release();
    });
}

StoreActions::~StoreActions() { release(); }

bool StoreActions::available() { return isServerSetting(defaultToolLibraryPath()); }

PgToolStore* StoreActions::server()
{
    if (server_ && !server_->readOnly()) return server_.get();
    if (server_ && server_->reconnect()) return server_.get();
    if (!available()) {
        refuse(tr("Shop server"), tr("The job store needs the shop server: TAIWA_TOOL_DB names the file %1, not a server")
                                      .arg(QString::fromStdString(defaultToolLibraryPath())));
        return nullptr;
    }
    // No copy of the tools kept here: the plan runner keeps the station's.
    auto opened = PgToolStore::open(defaultToolLibraryPath(), {{}, {}, 3});
    if (!opened) {
        refuse(tr("Shop server"), coreMessage(opened.error()));
        return nullptr;
    }
    server_ = std::move(*opened);
    return server_.get();
}

bool StoreActions::refuse(const QString& title, const QString& text)
{
    if (FileActions::promptsDisabled()) qWarning("taiwa: %s", qPrintable(text));
    else QMessageBox::warning(window_, title, text);
    emit message(text);
    return false;
}

void StoreActions::release()
{
    if (held_.isEmpty() || !server_ || server_->readOnly()) return;
    PgJobStore jobs(*server_);
    if (auto r = jobs.unlock(held_.toStdString()); !r) qWarning("taiwa: %s", r.error().c_str());
    held_.clear();
}

bool StoreActions::openFromStore()
{
    if (!files_->maybeSave()) return false;
    PgToolStore* s = server();
    if (!s) return false;
    auto names = PgJobStore(*s).names();
    if (!names) return refuse(tr("Open from the shop server"), coreMessage(names.error()));
    QStringList items;
    for (const auto& n : *names) items << QString::fromStdString(n);
    if (items.isEmpty()) {
        emit message(tr("The shop server holds no jobs yet"));
        return false;
    }
    bool ok = false;
    const QString name = QInputDialog::getItem(window_, tr("Open from the shop server"), tr("Job:"), items, 0, false, &ok);
    return ok && openStored(name);
}

bool StoreActions::openStored(const QString& name)
{
    if (!files_->maybeSave()) return false;
    PgToolStore* s = server();
    if (!s) return false;
    PgJobStore jobs(*s);
    const std::string n = name.toStdString();
    const bool heldAlready = name == held_;
    if (auto locked = jobs.lock(n); !locked) return refuse(tr("Cannot open job"), coreMessage(locked.error()));
    const auto history = jobs.history(n);
    auto text = jobs.load(n);
    const JobReadResult read = text ? readJob(*text) : JobReadResult{};
    if (!text || !history || !read.job) {
        if (!heldAlready) (void)jobs.unlock(n);
        if (!text || !history) return refuse(tr("Cannot open job"), coreMessage(!text ? text.error() : history.error()));
        QString why;
        for (const Diagnostic& d : read.diagnostics) why += diagnosticText(n, d) + "\n";
        return refuse(tr("Cannot open job"), why.trimmed());
    }
    if (!heldAlready) release();
    held_ = name;  // before the document says it changed: the title names the stored job
    opening_ = true;
    doc_->reset(*read.job, {}, false);
    opening_ = false;
    emit message(tr("Opened %1 from the shop server (version %2); this station holds its lock").arg(name).arg(history->empty() ? 0 : history->back().version));
    return true;
}

bool StoreActions::saveToStore()
{
    if (!held_.isEmpty()) return saveStored(held_);
    if (FileActions::promptsDisabled()) return false;
    bool ok = false;
    const QString name = QInputDialog::getText(window_, tr("Save to the shop server"), tr("Name in the job store:"), QLineEdit::Normal,
                                               QString::fromStdString(doc_->job().name), &ok);
    return ok && !name.trimmed().isEmpty() && saveStored(name.trimmed());
}

bool StoreActions::saveStored(const QString& name)
{
    PgToolStore* s = server();
    if (!s) return false;
    PgJobStore jobs(*s);
    const std::string n = name.toStdString();
    // The lock first: a job another station holds is not saved over.
    if (auto locked = jobs.lock(n); !locked) return refuse(tr("Cannot save job"), coreMessage(locked.error()));
    auto version = jobs.save(n, writeJob(doc_->job()));
    if (!version) {
        if (name != held_) (void)jobs.unlock(n);
        return refuse(tr("Cannot save job"), coreMessage(version.error()));
    }
    if (name != held_) release();
    held_ = name;
    doc_->markSavedElsewhere();
    emit message(tr("Saved %1 to the shop server as version %2").arg(name).arg(*version));
    return true;
}

}  // namespace taiwa::ui
