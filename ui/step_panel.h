// The step list with what goes with it: the numbers of the selected step, a
// play button that walks through the steps on a timer, the iso/top/front
// view buttons and the stock switches (simulated stock; before or after
// the step). It only emits what the operator asked
// for; the window passes that on to the 3-D preview.
#pragma once

#include "pipeline/pipeline.h"

#include <QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QLabel;
class QToolButton;
class QTimer;

namespace taiwa::ui {

class StepTable;

enum class ViewButton { Iso, Top, Front };

class StepPanel : public QWidget {
    Q_OBJECT
public:
    explicit StepPanel(QWidget* parent = nullptr);

    StepTable* table() const { return table_; }
    // A new plan (nullptr: input errors). The selected step stays selected
    // when the plan still has it.
    void setPlan(const std::shared_ptr<const Plan>& plan);
    // -1 = all steps.
    int selectedStep() const;
    void selectStep(int index);
    // The switches' states (the preview starts from them).
    bool stockShown() const;
    bool stockBefore() const;
    bool isPlaying() const;
    void setPlaying(bool on);
    // Milliseconds per step while playing.
    void setPlayInterval(int ms);

signals:
    void stepSelected(int index);  // -1 = all
    void viewRequested(taiwa::ui::ViewButton view);
    void showStockToggled(bool on);
    void stockBeforeToggled(bool before);

private:
    void onSelectionChanged();
    void advance();
    void showDetails(int index);

    StepTable* table_;
    QLabel* details_;
    QToolButton* play_;
    QCheckBox* stock_;
    QCheckBox* before_;
    QTimer* timer_;
    std::shared_ptr<const Plan> plan_;
    std::optional<double> lastMinutes_;  // total time of the last plan with times
    int lastEmitted_ = -2;
};

}  // namespace taiwa::ui
