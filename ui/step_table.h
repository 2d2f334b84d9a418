// The step list: one row per step of the plan in machining order (no., unit,
// step, tool, start depth, cut depth, minutes once the tool paths exist).
#pragma once

#include "pipeline/pipeline.h"

#include <QTableWidget>

#include <memory>

namespace taiwa::ui {

class StepTable : public QTableWidget {
    Q_OBJECT
public:
    explicit StepTable(QWidget* parent = nullptr);
    // nullptr clears the list (the job has input errors).
    void setPlan(const std::shared_ptr<const Plan>& plan);
    // The step labels in order ("Pilot hole", "Roughing I", ...).
    QStringList stepLabels() const;
};

}  // namespace taiwa::ui
