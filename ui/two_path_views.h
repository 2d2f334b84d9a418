// The station's views of a job on a two-path lathe (docs/two-path-lathe.md
// "In the station"), made from one TwoPathShown (two_path_shown.h) each time
// a full plan arrives: the step list by path (each path's turret and tools,
// every step it runs with its tool and time, the balanced roughing's
// blocks under it), the timeline chart (two_path_chart.h) and path 2's tape
// (an NcView of its own, beside path 1's in the window's tape tabs). A block
// chosen in any of them, or reached by the play, is chosen in the others;
// the window passes the step and move on to the step panel, the 3-D view
// and path 1's tape.
#pragma once

#include "pipeline/pipeline.h"
#include "ui/two_path_shown.h"

#include <QObject>
#include <QTreeWidget>

#include <optional>

namespace taiwa::ui {

class NcView;
class TwoPathChart;

// The steps of each path, path by path.
class TwoPathSteps : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { StepName, ToolName, Time, ColumnCount };
    static constexpr int kStepRole = Qt::UserRole, kBlockRole = Qt::UserRole + 1;
    explicit TwoPathSteps(QWidget* parent = nullptr);
    void setShown(const Plan& plan, const TwoPathShown& shown);
    // Selects the block's row on its path (0: none), without announcing it.
    void selectBlock(int block);

signals:
    void stepChosen(int step);
    void blockChosen(int block);

protected:
    void changeEvent(QEvent* e) override;

private:
    void nameColumns();
    bool filling_ = false;
};

class TwoPathViews : public QObject {
    Q_OBJECT
public:
    explicit TwoPathViews(QObject* parent = nullptr);
    ~TwoPathViews() override;

    TwoPathSteps* steps() const { return steps_; }
    TwoPathChart* chart() const { return chart_; }
    NcView* tape() const { return tape_; }  // path 2's
    // A full plan in the dialect on view: path 1's program to show in the
    // window's tape (nullptr: a job of one path, or no programs, `error`).
    const PostedProgram* setPlan(const Plan& plan, const QString& dialect, const QString& stem);
    const std::optional<TwoPathShown>& shown() const { return shown_; }
    // The roughing's move reached (the play, a tape line, the 3-D view):
    // its block chosen in the list and the chart, its line in path 2's tape.
    void followMove(int step, int move);

signals:
    // A block chosen in the list or the chart: the roughing step and the
    // move before which its wait and dwell stand, on that path.
    void blockChosen(int step, int move, int path);

private:
    void chooseBlock(int block);
    TwoPathSteps* steps_;
    TwoPathChart* chart_;
    NcView* tape_;
    std::optional<TwoPathShown> shown_;
};

}  // namespace taiwa::ui
