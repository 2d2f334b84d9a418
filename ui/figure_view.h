// The 2-D view of the job's figure elements (docs/figure-elements.md) in
// work coordinates, X to the right and Y up: the stock's outline, points as
// dots with their names, lines as thin dashed lines clipped to the view,
// circles thin, contours thick with arrows in their direction. The mouse
// wheel zooms about the pointer, a drag pans, a double click fits the
// figure again; a click picks the nearest element or contour (within a few
// pixels), or while corners are under revision the nearest of them. An
// area cleared by drawn passes (seed 002, seventh abstract) is shown over it:
// the area painted, the strips one tool wide taking the paint away, the
// passes numbered, and what stays unswept outlined in red; while passes are
// being drawn a click adds a point instead of picking.
// Painted with QPainter, as the profile view (ui/profile_view.h).
#pragma once

#include "figure/figure_eval.h"
#include "model/job.h"

#include <QPointF>
#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

namespace taiwa::ui {

// A corner of a contour: the contour's name and the corner's index in the
// order its corners are written (figure::EvaluatedContour::corners).
struct CornerRef {
    QString contour;
    int index = -1;
    friend bool operator==(const CornerRef&, const CornerRef&) = default;
};

// What the view shows of an area cleared by drawn passes, in the job's unit.
struct PassesOverlay {
    std::vector<std::vector<Point2>> area;      // the area's rings (outline, islands), painted even-odd
    std::vector<Point2> points;                 // the passes: from each point to the next
    double radius = 0.0;                        // half a strip's width
    std::vector<std::vector<Point2>> unswept;   // rings of what the strips leave
};

class FigureView : public QWidget {
    Q_OBJECT
public:
    explicit FigureView(QWidget* parent = nullptr);

    // What to draw: the evaluated figure and the stock, both in the job's
    // length unit. fit: frame them anew (else zoom and pan stay).
    void setFigure(figure::Evaluation evaluation, const Stock& stock, bool fit);
    const figure::Evaluation& evaluation() const { return evaluation_; }

    // The element or contour picked (highlighted); empty: none.
    void setSelected(const QString& name);
    QString selected() const { return selected_; }

    // Corners drawn in the revision colour (empty: none); picked: the one
    // being edited, drawn highlighted.
    void setHighlightedCorners(std::vector<CornerRef> corners);
    const std::vector<CornerRef>& highlightedCorners() const { return corners_; }

    // The drawn passes shown (nullopt: none); drawing: a click adds a
    // point (pointDrawn) instead of picking an element.
    void setPasses(std::optional<PassesOverlay> passes);
    const std::optional<PassesOverlay>& passes() const { return passes_; }
    void setDrawing(bool drawing);
    bool drawing() const { return drawing_; }

    // Where a point in work coordinates is drawn, in widget pixels, and back.
    QPointF toPixel(Point2 work) const;
    Point2 toWork(QPointF pixel) const;
    // The element or contour nearest to a pixel within a few pixels; empty
    // when none. Points come before contours, contours before the lines and
    // circles they lie on.
    QString elementAt(QPointF pixel) const;
    // The highlighted corner nearest to a pixel, within a few pixels.
    std::optional<CornerRef> cornerAt(QPointF pixel) const;

    // The stock, the points, the circles' centres and the contours framed
    // again, zoom and pan undone.
    void fitAll();
    double zoom() const { return zoom_; }

    QSize sizeHint() const override { return {420, 320}; }

signals:
    // A click: the element or contour under the pointer (empty: none).
    void elementPicked(const QString& name);
    // A click on a highlighted corner.
    void cornerPicked(const QString& contour, int index);
    // A click while drawing passes: where, in work coordinates.
    void pointDrawn(Point2 at);

protected:
    void paintEvent(QPaintEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    // The language switched: the tool tip in the new one.
    void changeEvent(QEvent* e) override;

private:
    double scale() const;  // pixels per unit
    QPolygonF polyline(const ContourSegment& s) const;
    // The part of an infinite line inside the widget, or nothing.
    std::optional<QLineF> clipped(const figure::Line& l) const;
    void drawCorner(class QPainter& p, const figure::EvaluatedContour& c, int index, const QColor& colour) const;
    void drawPasses(class QPainter& p) const;

    figure::Evaluation evaluation_;
    Stock stock_;
    QString selected_;
    std::vector<CornerRef> corners_;
    std::optional<PassesOverlay> passes_;
    bool drawing_ = false;
    Point2 fitMin_{0, 0}, fitMax_{100, 100};  // the framed box
    double zoom_ = 1.0;
    QPointF pan_;  // pixels
    QPointF pressAt_;
    QPointF lastMove_;
    bool pressed_ = false;
    bool dragging_ = false;
};

}  // namespace taiwa::ui
