// The shop's tool library (SQLite, ToolLibrary) as a table: id (T number),
// name, type, diameter, corner radius, taper, flute length, holder, life and
// the life already used. The selected tool's wear can be reset (a fresh tool
// was put in); every database error is shown, never hidden.
#pragma once

#include "model/tool.h"

#include <QDialog>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace taiwa::ui {

class ToolLibraryDialog : public QDialog {
    Q_OBJECT
public:
    explicit ToolLibraryDialog(QWidget* parent = nullptr);
    QTableWidget* table() const { return table_; }
    // True when a tool was changed (the window re-plans with the new library).
    bool changed() const { return changed_; }

private:
    void load();
    void resetWear();
    QTableWidget* table_;
    QLabel* status_;
    QPushButton* reset_;
    std::vector<Tool> tools_;
    bool changed_ = false;
};

}  // namespace taiwa::ui
