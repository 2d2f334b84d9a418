// The NC view's text documents, made on a thread of their own (issue 11).
// A QTextDocument holds one block per line: a 200-unit tape (20,000 lines)
// took 40-60 ms to put in, all of it on the GUI thread after the 3-D view's
// frame. The station asks for a tape's document as soon as the tape is
// posted (prepare); the view takes it when it shows the tape (take), by
// then made on the maker's thread, and old documents are freed there too.
// The maker runs below the 3-D view's renderer (nice 10), which it would
// otherwise slow down on a two-core machine.
#pragma once

#include <QFont>
#include <QString>

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

class QTextDocument;

namespace taiwa::ui {

// A read-only tape's document, laid out as a QPlainTextEdit lays out text
// (QPlainTextDocumentLayout), with `font` as its default font. May be
// called on any thread; the document belongs to that thread.
std::unique_ptr<QTextDocument> makeNcDocument(const QString& nc, const QFont& font);

class NcDocumentMaker {
public:
    NcDocumentMaker();
    ~NcDocumentMaker();
    NcDocumentMaker(const NcDocumentMaker&) = delete;
    NcDocumentMaker& operator=(const NcDocumentMaker&) = delete;

    // Starts making the document of `nc` on the maker's thread; a document
    // asked for before and not yet started is not made.
    void prepare(const QString& nc, const QFont& font);
    // The document of `nc` in the calling thread: the one prepared (waited
    // for if it is being made), else made here and now.
    std::unique_ptr<QTextDocument> take(const QString& nc, const QFont& font);
    // Frees a document on the maker's thread (a large one takes a few ms).
    void dispose(std::unique_ptr<QTextDocument> doc);
    // Whether the document of `nc` is made and waits to be taken.
    bool ready(const QString& nc);
    // How many documents take() found prepared (tests).
    int taken() const { return taken_; }

private:
    struct Job {
        QString nc;
        QFont font;
    };
    void run();

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::unique_ptr<Job> next_;                       // asked for, not started
    QString making_;                                  // being made now (null: none)
    bool busy_ = false;
    QString madeFor_;                                 // the tape `made_` shows
    std::unique_ptr<QTextDocument> made_;             // no thread's object until taken
    std::deque<std::unique_ptr<QTextDocument>> bin_;  // to be freed here
    bool stop_ = false;
    int taken_ = 0;
    std::thread thread_;
};

}  // namespace taiwa::ui
