// The balanced roughing of a two-path job as a Gantt-style chart under the
// 3-D view (docs/two-path-lathe.md "In the station"): one lane per path,
// its bars the stretches of the timeline the sheet tabulates
// (export/two_path_sheet.h timelineStretches: a block's way in, its cut,
// its way out, a wait held, the tail), the follower's dwell marked at the
// end of its way in (just before its cut, where the program has it), each
// wait M-code as a line across the lanes at the time the paths go on from
// it, and the block chosen (in the path list, the tapes, the play) outlined.
// A click on a bar chooses its block.
#pragma once

#include "export/two_path_sheet.h"

#include <QWidget>

#include <optional>
#include <string>
#include <vector>

namespace taiwa::ui {

class TwoPathChart : public QWidget {
    Q_OBJECT
public:
    explicit TwoPathChart(QWidget* parent = nullptr);

    // The timeline to draw (none: nothing), each path's name, and the wait
    // all paths meet at after the roughing (BalancedPath::endWait), drawn
    // where the last path ends it.
    void setTimeline(std::optional<Timeline> timeline, std::vector<std::string> pathNames, std::optional<int> endWait);
    const std::optional<Timeline>& timeline() const { return timeline_; }
    // Outlines a block (0: none).
    void selectBlock(int block);
    int selectedBlock() const { return selected_; }

    // What is drawn, for the tests: each path's bars and the wait lines.
    struct Bar {
        std::size_t path = 0;
        TimelineStretch stretch;
        QRectF rect;
    };
    std::vector<Bar> bars() const;
    struct WaitLine {
        int code = 0;
        double seconds = 0.0;  // when the paths go on from it
        double x = 0.0;
    };
    std::vector<WaitLine> waitLines() const;
    double xOf(double seconds) const;
    QRectF laneOf(std::size_t path) const;
    // A lane's label: "Path 2 (lower turret)", the name in the station's language.
    QString laneLabel(std::size_t path) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void blockClicked(int block);

protected:
    void paintEvent(QPaintEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    bool event(QEvent* e) override;  // a bar's tooltip

private:
    QString textOf(const TimelineStretch& s) const;
    std::optional<Timeline> timeline_;
    std::vector<std::string> names_;
    std::optional<int> endWait_;
    int selected_ = 0;
};

}  // namespace taiwa::ui
