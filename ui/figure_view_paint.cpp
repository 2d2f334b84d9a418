// How the figure view paints (figure_view.h): the stock from above and the
// work origin, lines and circles thin under the contours, the passes drawn
// through an area, the contours thick with arrows in their direction of
// travel, the corners under revision, the points, and how to move about.
#include "ui/figure_view.h"

#include "figure/figure_text.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

namespace {

const QColor kStockFill(0xee, 0xf1, 0xf5);
const QColor kStockEdge(0x9a, 0xa5, 0xb1);
const QColor kConstruction(0x6f, 0x82, 0x96);
const QColor kPoint(0x2c, 0x3e, 0x50);
const QColor kContour(0x1d, 0x35, 0x57);
const QColor kSelected(0xff, 0x8c, 0x00);
const QColor kCorner(0xb0, 0x30, 0xc0);
const QColor kPaint(0xf2, 0xb8, 0xb8);      // the area before the passes take the paint away
const QColor kStrip(0xff, 0xff, 0xff, 235);  // what a strip sweeps
const QColor kPass(0x1d, 0x35, 0x57);
const QColor kUnswept(0xd0, 0x10, 0x10);

double length(QPointF v) { return std::hypot(v.x(), v.y()); }

}  // namespace

void FigureView::drawCorner(QPainter& p, const figure::EvaluatedContour& c, int index, const QColor& colour) const
{
    const figure::ContourCorner& corner = c.corners[static_cast<std::size_t>(index)];
    if (corner.segment < 0 || corner.segment >= static_cast<int>(c.contour.segments.size())) return;
    const ContourSegment& s = c.contour.segments[static_cast<std::size_t>(corner.segment)];
    p.setPen(QPen(colour, 6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPolyline(polyline(s));
    const QString text = (corner.kind == figure::ContourCorner::Kind::Round ? QStringLiteral("R") : QStringLiteral("C")) +
                         QString::fromStdString(figure::formatNumber(corner.value));
    p.setPen(colour);
    p.drawText(toPixel(s.at(0.5)) + QPointF(6, -6), text);
}

// The area painted, the strips taking the paint away, the passes with their
// numbers and direction, what stays unswept outlined in red.
void FigureView::drawPasses(QPainter& p) const
{
    const PassesOverlay& o = *passes_;
    QPainterPath area;
    area.setFillRule(Qt::OddEvenFill);
    for (const auto& ring : o.area) {
        QPolygonF poly;
        for (const Point2 q : ring) poly << toPixel(q);
        area.addPolygon(poly);
        area.closeSubpath();
    }
    p.fillPath(area, kPaint);
    QPolygonF centre;
    for (const Point2 q : o.points) centre << toPixel(q);
    const double width = 2 * o.radius * scale();
    if (centre.size() == 1) {
        p.setPen(Qt::NoPen);
        p.setBrush(kStrip);
        p.drawEllipse(centre.front(), width / 2, width / 2);
    } else if (centre.size() > 1) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(kStrip, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(centre);
    }
    for (const auto& ring : o.unswept) {
        QPolygonF poly;
        for (const Point2 q : ring) poly << toPixel(q);
        p.setPen(QPen(kUnswept, 1.5));
        p.setBrush(QBrush(kUnswept, Qt::BDiagPattern));
        p.drawPolygon(poly);
    }
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(kPass, 1.2, Qt::DashLine));
    p.drawPolyline(centre);
    for (int i = 0; i < centre.size(); ++i) {
        p.setPen(Qt::NoPen);
        p.setBrush(i == 0 ? QColor(0x27, 0xae, 0x60) : kPass);
        p.drawEllipse(centre[i], 3.5, 3.5);
        if (i == 0) continue;
        // The pass's number at its middle, an arrow at its end.
        const QPointF a = centre[i - 1], b = centre[i], d = (b - a) / std::max(1e-9, length(b - a));
        const QPointF n(-d.y(), d.x());
        QPainterPath arrow;
        arrow.moveTo(b - 4 * d);
        arrow.lineTo(b - 12 * d + 4 * n);
        arrow.lineTo(b - 12 * d - 4 * n);
        arrow.closeSubpath();
        p.fillPath(arrow, kPass);
        p.setPen(kPass);
        p.drawText((a + b) / 2 + 8 * n, QString::number(i));
    }
    p.setBrush(Qt::NoBrush);
}

void FigureView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), Qt::white);
    // The stock from above, and the work origin.
    const QRectF stock = QRectF(toPixel({stock_.x, stock_.y}), toPixel({stock_.x + stock_.width, stock_.y + stock_.length})).normalized();
    p.fillRect(stock, kStockFill);
    p.setPen(QPen(kStockEdge, 1));
    p.drawRect(stock);
    const QPointF origin = toPixel({0, 0});
    p.setPen(QPen(QColor(0xc0, 0x39, 0x2b), 1));
    p.drawLine(origin, origin + QPointF(18, 0));
    p.setPen(QPen(QColor(0x27, 0xae, 0x60), 1));
    p.drawLine(origin, origin + QPointF(0, -18));

    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    p.setFont(small);
    const auto pen = [&](const std::string& name, const QColor& c, double width, Qt::PenStyle style) {
        const bool picked = QString::fromStdString(name) == selected_;
        return QPen(picked ? kSelected : c, picked ? width + 1.5 : width, style, Qt::RoundCap, Qt::RoundJoin);
    };
    // Lines and circles, thin, under the contours.
    for (const figure::Element& e : evaluation_.elements) {
        const QString name = QString::fromStdString(e.name);
        if (e.kind == figure::Kind::Line) {
            const auto seen = clipped(e.line);
            if (!seen) continue;
            p.setPen(pen(e.name, kConstruction, 1, Qt::DashLine));
            p.drawLine(*seen);
            // The name near the end it runs towards, beside the line.
            const QPointF d = seen->p2() - seen->p1();
            const double len = std::max(1.0, length(d));
            const QPointF at = seen->p2() - d * std::min(0.5, 40.0 / len) + QPointF(-d.y(), d.x()) * (6.0 / len);
            p.setPen(name == selected_ ? kSelected : kConstruction);
            p.drawText(at, name);
        } else if (e.kind == figure::Kind::Circle) {
            const QPointF c = toPixel(e.circle.centre);
            const double r = e.circle.radius * scale();
            p.setPen(pen(e.name, kConstruction, 1, Qt::SolidLine));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(c, r, r);
            p.setPen(name == selected_ ? kSelected : kConstruction);
            p.drawText(c + QPointF(r * 0.72 + 3, -r * 0.72 - 3), name);
        }
    }
    if (passes_) drawPasses(p);
    // Contours, thick, with an arrow in the direction of travel on each
    // piece long enough to carry one.
    QFont bold = small;
    bold.setBold(true);
    for (const figure::EvaluatedContour& c : evaluation_.contours) {
        if (c.contour.empty()) continue;
        const QPen line = pen(c.name, kContour, 2.5, Qt::SolidLine);
        for (std::size_t i = 0; i < c.contour.segments.size(); ++i) {
            const ContourSegment& s = c.contour.segments[i];
            const QPolygonF poly = polyline(s);
            p.setPen(line);
            p.drawPolyline(poly);
            double pixels = 0;
            for (int k = 0; k + 1 < poly.size(); ++k) pixels += length(poly[k + 1] - poly[k]);
            if (pixels < 36 || (i < c.elements.size() && c.elements[i].empty())) continue;
            const QPointF tip = toPixel(s.at(0.5)), behind = toPixel(s.at(0.5 - std::min(0.25, 9.0 / pixels)));
            const QPointF d = (tip - behind) / std::max(1e-9, length(tip - behind));
            const QPointF n(-d.y(), d.x());
            QPainterPath arrow;
            arrow.moveTo(tip + 5 * d);
            arrow.lineTo(tip - 5 * d + 4 * n);
            arrow.lineTo(tip - 5 * d - 4 * n);
            arrow.closeSubpath();
            p.fillPath(arrow, line.color());
        }
        p.setFont(bold);
        p.setPen(QString::fromStdString(c.name) == selected_ ? kSelected : kContour);
        p.drawText(toPixel(c.contour.segments.front().at(0.5)) + QPointF(6, 14), QString::fromStdString(c.name));
        p.setFont(small);
    }
    // Corners under revision.
    for (const CornerRef& ref : corners_)
        if (const figure::EvaluatedContour* c = evaluation_.findContour(ref.contour.toStdString()))
            if (ref.index >= 0 && ref.index < static_cast<int>(c->corners.size()))
                drawCorner(p, *c, ref.index, corners_.size() == 1 ? kSelected : kCorner);
    // Points on top, as dots with their names.
    for (const figure::Element& e : evaluation_.elements) {
        if (e.kind != figure::Kind::Point) continue;
        const QString name = QString::fromStdString(e.name);
        const QPointF at = toPixel(e.point);
        const QColor c = name == selected_ ? kSelected : kPoint;
        p.setPen(Qt::NoPen);
        p.setBrush(c);
        p.drawEllipse(at, name == selected_ ? 4.0 : 3.0, name == selected_ ? 4.0 : 3.0);
        p.setPen(c);
        p.drawText(at + QPointF(5, -5), name);
    }
    // How to move about, on a white band over the drawing.
    const QString hint = drawing_ ? tr("Drawing passes: click the start, then the end of each pass; wheel: zoom, drag: pan")
                                  : tr("X →  Y ↑   wheel: zoom, drag: pan, double click: fit");
    const QRectF band(0, height() - p.fontMetrics().height() - 6, p.fontMetrics().horizontalAdvance(hint) + 12,
                      p.fontMetrics().height() + 6);
    p.fillRect(band, QColor(255, 255, 255, 220));
    p.setPen(QColor(0x55, 0x55, 0x55));
    p.drawText(band.adjusted(6, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, hint);
}

}  // namespace taiwa::ui
