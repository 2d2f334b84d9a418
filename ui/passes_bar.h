// Drawing the passes of an area cleared by drawn passes (module AREA, seed
// 002's seventh abstract) in the Figure tab: for the station's current unit,
// when its module has drawn passes, a row of buttons over the 2-D view —
// "Draw passes" (each click in the view adds a point: the first is where the
// tool starts, each next one ends a pass), "Remove last point", "Clear" — and
// a line saying how many passes there are, how much of the area they leave
// unswept, or which pass leaves the area. The view paints the area, the
// strips one tool wide and the unswept rest (figure_view.h). Every point
// drawn is one undoable edit of the job.
#pragma once

#include "model/geometry.h"

#include <QWidget>

#include <vector>

class QLabel;
class QToolButton;

namespace taiwa::ui {

class FigureView;
class JobDocument;

class PassesBar : public QWidget {
    Q_OBJECT
public:
    // Widget objectNames: "figure.passes" (this), "figure.drawPasses",
    // "figure.removePoint", "figure.clearPasses", "figure.passesText".
    PassesBar(JobDocument* doc, FigureView* view, QWidget* parent = nullptr);

    // The station's current unit (-1: none): the bar shows when it has drawn passes.
    void setUnit(int unit);
    int unit() const { return unit_; }
    // After the job or the view's figure changed: the overlay and the line anew.
    void refresh();
    // Points snap to this grid in the job's unit (0.5 mm, 0.01 in).
    double grid() const;

protected:
    // The language switched: the buttons and the line in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameButtons();
    void addPoint(Point2 at);
    void setPoints(std::vector<Point2> points, const QString& what);
    bool hasPasses() const;

    JobDocument* doc_;
    FigureView* view_;
    QToolButton* draw_ = nullptr;
    QToolButton* removeLast_ = nullptr;
    QToolButton* clear_ = nullptr;
    QLabel* text_ = nullptr;
    int unit_ = -1;
};

}  // namespace taiwa::ui
