// The ordered list of machining units ("1 M4 Pocket A") with the buttons
// duplicate, up, down and delete, and the add actions the module palette
// calls; each is one undoable edit of the job.
#pragma once

#include <QWidget>

class QListWidget;

namespace taiwa::ui {

class JobDocument;

class UnitListPanel : public QWidget {
    Q_OBJECT
public:
    explicit UnitListPanel(JobDocument* doc, QWidget* parent = nullptr);
    int currentUnit() const;
    void selectUnit(int unit);
    // Refreshes the item texts from the document.
    void refresh();

    // Adds a unit of the module kind named `module` ("M4") with the kind's
    // default values, and selects it.
    void addUnit(const QString& module);
    void duplicate();
    void moveUp() { move(-1); }
    void moveDown() { move(1); }
    void remove();

signals:
    void currentUnitChanged(int unit);

private:
    void move(int delta);
    JobDocument* doc_;
    QListWidget* list_;
};

}  // namespace taiwa::ui
