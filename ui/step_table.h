// The step list: one row per step of the plan in machining order (no., unit,
// step, tool, spindle speed S and feed F, start depth, cut depth, minutes
// once the tool paths exist). S and F are the operator's to change: a value
// typed there is kept in the job as that unit's speed or feed for steps of
// that kind (Job: MachiningUnit::cutting) and shown in bold; an emptied cell
// goes back to the tool's cutting data. Too narrow for every column, it
// hides the start depth, the cut depth and the unit, in that order.
#pragma once

#include "pipeline/pipeline.h"

#include <QTableWidget>

#include <memory>
#include <optional>

namespace taiwa::ui {

class StepTable : public QTableWidget {
    Q_OBJECT
public:
    enum Column { No, Unit, StepName, ToolName, Speed, Feed, Start, Depth, Time, ColumnCount };

    explicit StepTable(QWidget* parent = nullptr);
    // nullptr clears the list (the job has input errors).
    void setPlan(const std::shared_ptr<const Plan>& plan);
    // The step labels in order ("Pilot hole", "Roughing I", ...).
    QStringList stepLabels() const;
    // A cell is being typed into (a new plan waits for it).
    bool editing() const { return state() == QAbstractItemView::EditingState; }

signals:
    // The operator typed S (speed) or F (not speed) for the steps of `key`
    // of unit `unit` (0-based): the value in the job's units, or nothing
    // to go back to the tool's cutting data.
    void cuttingEdited(int unit, const QString& key, bool speed, std::optional<double> value);

protected:
    // A plan that arrives while a cell is being typed into waits for the
    // editor to close (refilling the table would drop what is typed).
    void closeEditor(QWidget* editor, QAbstractItemDelegate::EndEditHint hint) override;
    // The columns fitted to the width the table gets.
    void resizeEvent(QResizeEvent* event) override;
    // The language switched: the headers and the steps' names in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameColumns();
    void onItemChanged(QTableWidgetItem* item);
    // Narrow (a 1280- or 1366-pixel screen): Start, then Depth, then Unit
    // are hidden (the selected step's numbers under the table and its unit's
    // form say them) so that No., step, tool, S, F and time stay whole.
    void fitColumns();

    std::shared_ptr<const Plan> plan_;
    std::optional<std::shared_ptr<const Plan>> waiting_;
    bool filling_ = false;
};

}  // namespace taiwa::ui
