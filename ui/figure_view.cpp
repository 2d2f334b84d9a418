// The 2-D view of the figure elements (figure_view.h): framing, zoom and
// pan, and what a click picks. How it paints the figure:
// figure_view_paint.cpp.
#include "ui/figure_view.h"

#include "figure/figure_text.h"

#include <QEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::ui {

namespace {

constexpr double kMargin = 24.0;      // px around the framed figure
constexpr double kPickPixels = 6.0;   // how near a click must be
constexpr double kDragPixels = 4.0;   // a press moved further is a drag, not a click

double length(QPointF v) { return std::hypot(v.x(), v.y()); }

// Distance from p to the segment a-b, in pixels.
double toSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return length(p - (a + t * ab));
}

double toPolyline(QPointF p, const QPolygonF& poly)
{
    double best = 1e300;
    for (int i = 0; i + 1 < poly.size(); ++i) best = std::min(best, toSegment(p, poly[i], poly[i + 1]));
    return best;
}

void expand(Point2& lo, Point2& hi, Point2 p, bool& any)
{
    lo = any ? Point2{std::min(lo.x, p.x), std::min(lo.y, p.y)} : p;
    hi = any ? Point2{std::max(hi.x, p.x), std::max(hi.y, p.y)} : p;
    any = true;
}

}  // namespace

FigureView::FigureView(QWidget* parent) : QWidget(parent)
{
    setMinimumSize(200, 160);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setCursor(Qt::CrossCursor);
    setToolTip(tr("Click: pick an element. Wheel: zoom. Drag: pan. Double click: fit."));
}

void FigureView::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() == QEvent::LanguageChange) setDrawing(drawing_);  // the tool tip and the hint in the new language
}

void FigureView::setFigure(figure::Evaluation evaluation, const Stock& stock, bool fit)
{
    evaluation_ = std::move(evaluation);
    stock_ = stock;
    if (fit) fitAll();
    update();
}

void FigureView::setSelected(const QString& name)
{
    if (name == selected_) return;
    selected_ = name;
    update();
}

void FigureView::setPasses(std::optional<PassesOverlay> passes)
{
    passes_ = std::move(passes);
    update();
}

void FigureView::setDrawing(bool drawing)
{
    drawing_ = drawing;
    setToolTip(drawing ? tr("Click: the next point of the passes. Wheel: zoom. Drag: pan. Double click: fit.")
                       : tr("Click: pick an element. Wheel: zoom. Drag: pan. Double click: fit."));
    update();
}

void FigureView::setHighlightedCorners(std::vector<CornerRef> corners)
{
    corners_ = std::move(corners);
    update();
}

// The stock, the points, the circles' centres and the contours: the work
// area. Lines are endless and construction circles may be large; both are
// drawn as far as they reach into the view.
void FigureView::fitAll()
{
    Point2 lo{0, 0}, hi{0, 0};
    bool any = false;
    expand(lo, hi, {stock_.x, stock_.y}, any);
    expand(lo, hi, {stock_.x + stock_.width, stock_.y + stock_.length}, any);
    for (const figure::Element& e : evaluation_.elements) {
        if (e.kind == figure::Kind::Point) expand(lo, hi, e.point, any);
        if (e.kind == figure::Kind::Circle) expand(lo, hi, e.circle.centre, any);
    }
    for (const figure::EvaluatedContour& c : evaluation_.contours) {
        if (c.contour.empty()) continue;
        const Box2 b = bounds(c.contour);
        expand(lo, hi, b.min, any);
        expand(lo, hi, b.max, any);
    }
    fitMin_ = lo;
    fitMax_ = hi;
    zoom_ = 1.0;
    pan_ = {};
    update();
}

double FigureView::scale() const
{
    const double w = std::max(1.0, width() - 2 * kMargin), h = std::max(1.0, height() - 2 * kMargin);
    const double fit = std::min(w / std::max(fitMax_.x - fitMin_.x, 1e-6), h / std::max(fitMax_.y - fitMin_.y, 1e-6));
    return fit * zoom_;
}

QPointF FigureView::toPixel(Point2 p) const
{
    const double s = scale();
    const QPointF middle = QPointF(width() / 2.0, height() / 2.0) + pan_;
    return middle + QPointF((p.x - (fitMin_.x + fitMax_.x) / 2) * s, -(p.y - (fitMin_.y + fitMax_.y) / 2) * s);
}

Point2 FigureView::toWork(QPointF pixel) const
{
    const double s = scale();
    const QPointF d = pixel - (QPointF(width() / 2.0, height() / 2.0) + pan_);
    return {(fitMin_.x + fitMax_.x) / 2 + d.x() / s, (fitMin_.y + fitMax_.y) / 2 - d.y() / s};
}

// Arcs through points every 3° (the drawing only; the geometry stays exact).
QPolygonF FigureView::polyline(const ContourSegment& s) const
{
    if (!s.isArc()) return QPolygonF{toPixel(s.start), toPixel(s.end)};
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(s.sweep()) / (3.0 * std::numbers::pi / 180.0))));
    QPolygonF poly;
    for (int i = 0; i <= n; ++i) poly << toPixel(s.at(static_cast<double>(i) / n));
    return poly;
}

std::optional<QLineF> FigureView::clipped(const figure::Line& l) const
{
    const QPointF p = toPixel(l.point);
    const QPointF d(l.dir.x, -l.dir.y);
    double t0 = -1e12, t1 = 1e12;
    const double lo[2] = {-2.0, -2.0}, hi[2] = {width() + 2.0, height() + 2.0};
    const double at[2] = {p.x(), p.y()}, dir[2] = {d.x(), d.y()};
    for (int k = 0; k < 2; ++k) {
        if (std::abs(dir[k]) < 1e-12) {
            if (at[k] < lo[k] || at[k] > hi[k]) return std::nullopt;
            continue;
        }
        double a = (lo[k] - at[k]) / dir[k], b = (hi[k] - at[k]) / dir[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 >= t1) return std::nullopt;
    return QLineF(p + t0 * d, p + t1 * d);
}

QString FigureView::elementAt(QPointF pixel) const
{
    QString best;
    double bestScore = 0;
    const auto offer = [&](const std::string& name, double distance, double penalty) {
        if (distance > kPickPixels) return;
        if (best.isEmpty() || distance + penalty < bestScore) {
            bestScore = distance + penalty;
            best = QString::fromStdString(name);
        }
    };
    for (const figure::Element& e : evaluation_.elements) {
        if (e.kind == figure::Kind::Point) {
            offer(e.name, length(pixel - toPixel(e.point)), -2.0);
        } else if (e.kind == figure::Kind::Line) {
            const QPointF p = toPixel(e.line.point), d(e.line.dir.x, -e.line.dir.y);
            const QPointF v = pixel - p;
            offer(e.name, std::abs(v.x() * d.y() - v.y() * d.x()), 1.0);
        } else {
            const double r = e.circle.radius * scale();
            offer(e.name, std::abs(length(pixel - toPixel(e.circle.centre)) - r), 1.0);
        }
    }
    for (const figure::EvaluatedContour& c : evaluation_.contours)
        for (const ContourSegment& s : c.contour.segments) offer(c.name, toPolyline(pixel, polyline(s)), 0.0);
    return best;
}

std::optional<CornerRef> FigureView::cornerAt(QPointF pixel) const
{
    std::optional<CornerRef> best;
    double bestDistance = kPickPixels + 2;
    for (const CornerRef& ref : corners_) {
        const figure::EvaluatedContour* c = evaluation_.findContour(ref.contour.toStdString());
        if (!c || ref.index < 0 || ref.index >= static_cast<int>(c->corners.size())) continue;
        const int seg = c->corners[static_cast<std::size_t>(ref.index)].segment;
        if (seg < 0 || seg >= static_cast<int>(c->contour.segments.size())) continue;
        const double d = toPolyline(pixel, polyline(c->contour.segments[static_cast<std::size_t>(seg)]));
        if (d < bestDistance) {
            bestDistance = d;
            best = ref;
        }
    }
    return best;
}

void FigureView::mousePressEvent(QMouseEvent* e)
{
    if (e->button() != Qt::LeftButton && e->button() != Qt::MiddleButton) return;
    pressed_ = true;
    dragging_ = false;
    pressAt_ = lastMove_ = e->position();
}

void FigureView::mouseMoveEvent(QMouseEvent* e)
{
    if (!pressed_) return;
    if (!dragging_ && length(e->position() - pressAt_) > kDragPixels) {
        dragging_ = true;
        setCursor(Qt::ClosedHandCursor);
    }
    if (!dragging_) return;
    pan_ += e->position() - lastMove_;
    lastMove_ = e->position();
    update();
}

void FigureView::mouseReleaseEvent(QMouseEvent* e)
{
    if (!pressed_) return;
    pressed_ = false;
    if (dragging_) {
        dragging_ = false;
        setCursor(Qt::CrossCursor);
        return;
    }
    if (e->button() != Qt::LeftButton) return;
    if (drawing_) {
        emit pointDrawn(toWork(e->position()));
        return;
    }
    if (!corners_.empty())
        if (const auto corner = cornerAt(e->position())) {
            emit cornerPicked(corner->contour, corner->index);
            return;
        }
    const QString name = elementAt(e->position());
    setSelected(name);
    emit elementPicked(name);
}

void FigureView::mouseDoubleClickEvent(QMouseEvent*) { fitAll(); }

void FigureView::wheelEvent(QWheelEvent* e)
{
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0) return;
    const QPointF at = e->position();
    const Point2 under = toWork(at);
    zoom_ = std::clamp(zoom_ * std::pow(1.2, steps), 0.02, 2000.0);
    pan_ += at - toPixel(under);  // the point under the pointer stays under it
    update();
    e->accept();
}

}  // namespace taiwa::ui
