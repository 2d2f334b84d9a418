// Cells of a table checked as it is typed in (table_cells.h).
#include "ui/table_cells.h"

#include <QApplication>
#include <QLineEdit>

namespace taiwa::ui {

bool cellEditing(const QTableWidget* t, const QTableWidgetItem* item)
{
    const auto* table = dynamic_cast<const EditingTable*>(t);
    if (!item || item != t->currentItem() || !table || !table->editingNow()) return false;
    const auto* editor = qobject_cast<const QLineEdit*>(QApplication::focusWidget());
    return !editor || editor->text() != item->text();
}

void markCell(QTableWidget* t, QTableWidgetItem* item, bool red, const QString& tip)
{
    if (cellEditing(t, item)) return;
    const QBrush want = red ? QBrush(QColor(kRefusedBackground)) : QBrush();
    if (item->background() != want) item->setBackground(want);
    if (item->toolTip() != tip) item->setToolTip(tip);
}

QTableWidgetItem* newCell(const QString& text, bool editable)
{
    auto* item = new QTableWidgetItem(text);
    if (!editable) item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

}  // namespace taiwa::ui
