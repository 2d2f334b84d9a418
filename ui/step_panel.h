// The step list with what goes with it: the numbers of the selected step, a
// play button that walks through the steps on a timer (with a step
// selected: through its blocks, the material coming off, with a speed and
// single blocks back and forward), the iso/top/front
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
class QSpinBox;
class QToolButton;
class QTimer;

namespace taiwa::ui {

class StepTable;

// The view's camera buttons: the presets, and Step (the selected step framed).
enum class ViewButton { Iso, Top, Front, Step };

class StepPanel : public QWidget {
    Q_OBJECT
public:
    explicit StepPanel(QWidget* parent = nullptr);

    StepTable* table() const { return table_; }
    // A new plan (nullptr: input errors). The selected step stays selected
    // when the plan still has it: the same step of the same unit (after an
    // undo that moved it, at its new row), not the row of that number.
    void setPlan(const std::shared_ptr<const Plan>& plan);
    const std::shared_ptr<const Plan>& plan() const { return plan_; }
    // -1 = all steps.
    int selectedStep() const;
    void selectStep(int index);
    // The switches' states (the preview starts from them).
    bool stockShown() const;
    bool stockBefore() const;
    bool pathsShown() const;
    // The 3-D view's own switches made here (the paths box and the
    // "Zoom" button, objectNames view.paths and view.step), for the
    // station to put in the view's bar beside the section bar: the step
    // list's rows keep the width of a 1280-pixel screen.
    QWidget* viewBar() const { return viewBar_; }
    // The switches set from outside (the View menu), their signals sent as a click's.
    void setStockShown(bool on);
    void setPathsShown(bool on);
    bool isPlaying() const;
    void setPlaying(bool on);
    // Milliseconds per step while playing (blocks: per tick, see blockInterval).
    void setPlayInterval(int ms);
    // Block by block: the move last shown of the step being played (-1:
    // before its first), and the blocks each tick moves on.
    int playStep() const { return playStep_; }
    int playMove() const { return playMove_; }
    void setBlocksPerTick(int n);
    // One block back or forward (starts at the selected step).
    void stepBlock(int delta);
    static constexpr int kBlockInterval = 100;  // ms between ticks while playing blocks

signals:
    void stepSelected(int index);  // -1 = all
    // The operator (or selectStep) chose a step; not a new plan re-selecting it.
    void stepChosen(int index);
    void viewRequested(taiwa::ui::ViewButton view);
    void showStockToggled(bool on);
    void showPathsToggled(bool on);
    void stockBeforeToggled(bool before);
    // Playing block by block: the stock after moves 0..move of step; (-1, -1)
    // when it ends (the selection changed, all steps).
    void playheadMoved(int step, int move);

protected:
    // The language switched: its buttons and the step's numbers in the new one.
    void changeEvent(QEvent* e) override;

private:
    // The buttons' words and tips in the language in force.
    void nameParts();
    void onSelectionChanged();
    void advance();
    void showDetails(int index);

    StepTable* table_;
    QLabel* details_;
    QToolButton* play_;
    QCheckBox* stock_;
    QCheckBox* before_;
    QCheckBox* paths_;
    QWidget* viewBar_;
    QToolButton* zoom_;
    QTimer* timer_;
    QSpinBox* speed_;
    int playStep_ = -1, playMove_ = -1;
    bool advancing_ = false;  // the panel itself moves the selection
    int stepInterval_ = 1200;
    int moveCount(int step) const;
    void setPlayhead(int step, int move);
    std::shared_ptr<const Plan> plan_;
    std::optional<double> lastMinutes_;  // total time of the last plan with times
    int lastEmitted_ = -2;
};

}  // namespace taiwa::ui
