// The NC view's documents made and freed on a thread of their own.
#include "ui/nc_document.h"

#include <QPlainTextDocumentLayout>
#include <QTextBlock>
#include <QTextLayout>
#include <QTextDocument>
#include <QThread>

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace taiwa::ui {

std::unique_ptr<QTextDocument> makeNcDocument(const QString& nc, const QFont& font)
{
    auto doc = std::make_unique<QTextDocument>();
    doc->setUndoRedoEnabled(false);
    doc->setDefaultFont(font);
    auto* layout = new QPlainTextDocumentLayout(doc.get());
    doc->setDocumentLayout(layout);
    doc->setPlainText(nc);
    // Each line's layout object made here, not by the view when it sets the
    // document's width (QPlainTextDocumentLayout's relayout asks each block
    // for it).
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) b.layout();
    return doc;
}

NcDocumentMaker::NcDocumentMaker() : thread_([this] { run(); }) {}

NcDocumentMaker::~NcDocumentMaker()
{
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void NcDocumentMaker::prepare(const QString& nc, const QFont& font)
{
    {
        std::lock_guard lock(mutex_);
        if ((made_ && madeFor_ == nc) || (busy_ && making_ == nc)) return;
        next_ = std::make_unique<Job>(Job{nc, font});
    }
    wake_.notify_all();
}

std::unique_ptr<QTextDocument> NcDocumentMaker::take(const QString& nc, const QFont& font)
{
    std::unique_lock lock(mutex_);
    if (next_ && next_->nc == nc) next_.reset();  // not started: quicker made here than waited for
    done_.wait(lock, [&] { return !busy_ || making_ != nc; });
    if (made_ && madeFor_ == nc && made_->defaultFont() == font) {
        ++taken_;
        madeFor_.clear();
        made_->moveToThread(QThread::currentThread());  // a thread-less object may be pulled
        return std::move(made_);
    }
    if (made_) {  // made for a tape not shown after all
        bin_.push_back(std::move(made_));
        madeFor_.clear();
        wake_.notify_all();
    }
    lock.unlock();
    return makeNcDocument(nc, font);
}

bool NcDocumentMaker::ready(const QString& nc)
{
    std::lock_guard lock(mutex_);
    return made_ && madeFor_ == nc;
}

void NcDocumentMaker::dispose(std::unique_ptr<QTextDocument> doc)
{
    if (!doc) return;
    doc->moveToThread(nullptr);  // no thread's object any more: free to be deleted on the maker's
    {
        std::lock_guard lock(mutex_);
        bin_.push_back(std::move(doc));
    }
    wake_.notify_all();
}

void NcDocumentMaker::run()
{
#ifdef __linux__
    // Below the 3-D view's renderer: on two cores Mesa's llvmpipe uses both
    // for a frame, and a document made at the same priority took its share
    // of them (200 units, value typed to the frame shown: 70-81 ms at
    // nice 0, 58-70 ms at nice 10; the NC text as soon or sooner, 86-98
    // against 76-94 ms). Alone it runs at full speed: the NC view waits for
    // it only after the frame, when the renderer is done. (Linux sets the
    // nice value of a thread, given its id.)
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);
#endif
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || next_ || !bin_.empty(); });
        if (stop_) break;
        if (!next_) {  // a document asked for first, the old ones freed after
            auto old = std::move(bin_.front());
            bin_.pop_front();
            lock.unlock();
            old.reset();
            lock.lock();
            continue;
        }
        const auto job = std::move(next_);
        busy_ = true;
        making_ = job->nc;
        std::unique_ptr<QTextDocument> stale = std::move(made_);  // nobody took it
        lock.unlock();
        stale.reset();
        auto doc = makeNcDocument(job->nc, job->font);
        doc->moveToThread(nullptr);
        lock.lock();
        made_ = std::move(doc);
        madeFor_ = job->nc;
        busy_ = false;
        making_.clear();
        done_.notify_all();
    }
    // Left at the end: freed with the maker, on the thread destroying it.
    lock.unlock();
}

}  // namespace taiwa::ui
