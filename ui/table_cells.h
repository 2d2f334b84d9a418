// Cells of an editable table that is checked as it is typed in (the turned
// profile's rows and allowances): a table that says whether a cell's editor
// is open, and marking a cell red with a tooltip without disturbing the
// text being typed in it.
#pragma once

#include <QString>
#include <QTableWidget>

namespace taiwa::ui {

// The background of a cell (or a field) whose value is refused.
inline constexpr const char* kRefusedBackground = "#ffd0d0";

// A table that says whether a cell's editor is open.
class EditingTable : public QTableWidget {
public:
    using QTableWidget::QTableWidget;
    bool editingNow() const { return state() == QAbstractItemView::EditingState; }
};

// Whether the cell's editor is open with text not yet in the item (a
// change of the item would make the view reload the editor from it).
bool cellEditing(const QTableWidget* t, const QTableWidgetItem* item);

// Marks a cell red with a tooltip, or clears it; touches it only when that
// changes something, and never the cell whose editor is open (a changed
// item makes the view reload its editor, losing what is being typed).
void markCell(QTableWidget* t, QTableWidgetItem* item, bool red, const QString& tip);

// A new cell with `text`, read-only unless `editable`.
QTableWidgetItem* newCell(const QString& text, bool editable = true);

}  // namespace taiwa::ui
