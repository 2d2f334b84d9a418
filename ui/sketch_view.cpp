// Drawing a Sketch with QPainter: the figure's bounds fitted into the
// widget with a margin, one scale for both axes, y up.
#include "ui/sketch_view.h"

#include "ui/core_messages.h"

#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

class SketchView::Figure : public QWidget {
public:
    explicit Figure(QWidget* parent) : QWidget(parent)
    {
        setMinimumSize(160, 200);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    }
    const Sketch* sketch = nullptr;

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.fillRect(rect(), QColor(250, 251, 253));
        p.setPen(QColor(200, 205, 215));
        p.drawRect(rect().adjusted(0, 0, -1, -1));
        if (!sketch || (sketch->marks.empty() && sketch->outlines.empty())) return;
        double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
        const auto grow = [&](Point2 q) {
            minX = std::min(minX, q.x), maxX = std::max(maxX, q.x);
            minY = std::min(minY, q.y), maxY = std::max(maxY, q.y);
        };
        for (const auto& m : sketch->marks) grow(m.at);
        for (const auto& o : sketch->outlines)
            for (const Point2 q : o) grow(q);
        const double margin = 36;
        const double span = std::max({maxX - minX, maxY - minY, 1e-3});
        const double scale = std::min((width() - 2 * margin) / std::max(maxX - minX, span * 0.2),
                                      (height() - 2 * margin) / std::max(maxY - minY, span * 0.2));
        const QPointF mid(0.5 * (minX + maxX), 0.5 * (minY + maxY));
        const auto at = [&](Point2 q) {
            return QPointF(width() / 2.0 + (q.x - mid.x()) * scale, height() / 2.0 - (q.y - mid.y()) * scale);
        };
        // The outlines: the workpiece solid, the ball centres' path dashed.
        for (std::size_t k = 0; k < sketch->outlines.size(); ++k) {
            QPainterPath path;
            const auto& o = sketch->outlines[k];
            if (o.empty()) continue;
            path.moveTo(at(o.front()));
            for (const Point2 q : o) path.lineTo(at(q));
            path.closeSubpath();
            p.setPen(QPen(QColor(29, 53, 87), k == 0 ? 2.0 : 1.0, k == 0 ? Qt::SolidLine : Qt::DashLine));
            p.setBrush(k == 0 ? QBrush(QColor(232, 238, 246)) : QBrush(Qt::NoBrush));
            p.drawPath(path);
        }
        if (sketch->centre) {
            const QPointF c = at(*sketch->centre);
            p.setPen(QPen(QColor(30, 130, 80), 2));
            p.drawLine(c - QPointF(9, 0), c + QPointF(9, 0));
            p.drawLine(c - QPointF(0, 9), c + QPointF(0, 9));
        }
        for (const auto& m : sketch->marks) {
            const QPointF c = at(m.at);
            p.setPen(Qt::NoPen);
            p.setBrush(m.flagged ? QColor(220, 30, 30) : QColor(192, 57, 43));
            p.drawEllipse(c, m.flagged ? 6 : 4, m.flagged ? 6 : 4);
            p.setPen(m.flagged ? QColor(220, 30, 30) : QColor(29, 53, 87));
            // Labels outward from the figure's middle, inside the widget.
            const QPointF out = c - QPointF(width() / 2.0, height() / 2.0);
            const double len = std::hypot(out.x(), out.y());
            QPointF pos = c + (len > 1 ? QPointF(out.x() / len * 10, out.y() / len * 10) : QPointF(8, -8));
            const QString text = QString::fromStdString(m.label);
            const double w = p.fontMetrics().horizontalAdvance(text);
            if (out.x() < 0) pos.rx() -= w;
            pos.setX(std::clamp(pos.x(), 2.0, width() - w - 2));
            pos.setY(std::clamp(pos.y() + 4, 12.0, height() - 4.0));
            p.drawText(pos, text);
        }
    }
};

SketchView::SketchView(QWidget* parent) : QWidget(parent)
{
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    figure_ = new Figure(this);
    figure_->setObjectName("sketch.figure");
    text_ = new QLabel(this);
    text_->setObjectName("sketch.text");
    text_->setWordWrap(true);
    text_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    box->addWidget(figure_);
    box->addWidget(text_);
    setVisible(false);
}

void SketchView::setSketch(std::optional<Sketch> sketch)
{
    sketch_ = std::move(sketch);
    figure_->sketch = sketch_ ? &*sketch_ : nullptr;
    setVisible(sketch_.has_value());
    if (!sketch_) return;
    QStringList lines;
    for (const auto& l : sketch_->lines) lines << coreMessage(l).toHtmlEscaped();  // in the station's language
    text_->setText(lines.join("<br>"));
    text_->setStyleSheet(sketch_->problem ? "color: #c0392b;" : "");
    figure_->update();
}

}  // namespace taiwa::ui
