// The ordered list of machining units ("1 M4 Pocket A") with the buttons
// duplicate, up, down and delete, and the add actions the module palette
// calls; each is one undoable edit of the job.
#pragma once

#include "model/job.h"

#include <QWidget>

#include <optional>

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
    // default values, in free stock, and selects it; when the stock has no
    // free place, at the module's default place all the same (the check marks
    // its overlap) and says so.
    void addUnit(const QString& module);
    // A copy of the current unit after it, in free stock (or nothing, said).
    void duplicate();
    void moveUp() { move(-1); }
    void moveDown() { move(1); }
    void remove();

signals:
    void currentUnitChanged(int unit);
    void message(const QString& text);  // for the status bar

protected:
    // The language switched: its buttons in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameButtons();
    void move(int delta);
    // The unit moved to free stock; nullopt, with a message, when there is none.
    std::optional<ModuleInput> place(const Job& job, const ModuleInput& unit);
    JobDocument* doc_;
    QListWidget* list_;
};

}  // namespace taiwa::ui
