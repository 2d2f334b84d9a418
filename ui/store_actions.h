// The File menu's job store on the shop server (docs/shop-server.md, "The
// job store"): Open from the shop server (a stored job's newest version; the
// station takes the job's lock, shop-wide), Save to the shop server (a new
// version in the job's history), and the lock given back when the window
// leaves the job (another job opened, a new one, the window closed).
#pragma once

#include <QObject>
#include <QString>

#include <memory>
#include <string>

class QWidget;

namespace taiwa {
class PgToolStore;
}

namespace taiwa::ui {

class JobDocument;
class FileActions;

class StoreActions : public QObject {
    Q_OBJECT
public:
    StoreActions(JobDocument* doc, FileActions* files, QWidget* window);
    ~StoreActions() override;  // the lock given back

    // Whether the tool setting names a shop server (the menu's items enabled).
    static bool available();
    // Asks which of the store's jobs, then openStored().
    bool openFromStore();
    // The newest version of job `name`, its lock taken (refused, saying who
    // holds it, while another station does); the unsaved changes asked about first.
    bool openStored(const QString& name);
    // A new version of the job the window shows from the store; a job from
    // a file or a new one asks for its name in the store first.
    bool saveToStore();
    bool saveStored(const QString& name);
    // The stored job the window shows and whose lock this station holds; empty: none.
    const QString& storedName() const { return held_; }

signals:
    void message(const QString& text);

private:
    PgToolStore* server();
    bool refuse(const QString& title, const QString& text);
    void release();
    JobDocument* doc_;
    FileActions* files_;
    QWidget* window_;
    std::unique_ptr<PgToolStore> server_;
    QString held_;
    bool opening_ = false;  // the document replaced by openStored itself
};

}  // namespace taiwa::ui
