// The two-path timeline chart (two_path_chart.h).
#include "ui/two_path_chart.h"

#include "ui/two_path_shown.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <map>

namespace taiwa::ui {

namespace {

constexpr int kLabelWidth = 150;  // the lanes' names
constexpr int kLane = 26, kGap = 6, kTop = 18, kAxis = 20, kRight = 28;

QColor colourOf(TimelineStretch::Kind k)
{
    switch (k) {
    case TimelineStretch::Cut: return QColor(40, 110, 200);
    case TimelineStretch::In: return QColor(160, 190, 225);
    case TimelineStretch::Out: return QColor(190, 205, 225);
    case TimelineStretch::Wait: return QColor(220, 60, 50);
    case TimelineStretch::Tail: return QColor(200, 200, 200);
    }
    return Qt::gray;
}

const QColor kDwell(240, 170, 30);

}  // namespace

TwoPathChart::TwoPathChart(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void TwoPathChart::setTimeline(std::optional<Timeline> timeline, std::vector<std::string> pathNames, std::optional<int> endWait)
{
    endWait_ = endWait;
    timeline_ = std::move(timeline);
    names_ = std::move(pathNames);
    updateGeometry();
    update();
}

void TwoPathChart::selectBlock(int block)
{
    if (block == selected_) return;
    selected_ = block;
    update();
}

QSize TwoPathChart::sizeHint() const
{
    const int lanes = static_cast<int>(std::max<std::size_t>(names_.size(), 2));
    return {600, kTop + lanes * (kLane + kGap) + kAxis};
}

QSize TwoPathChart::minimumSizeHint() const { return {300, sizeHint().height()}; }

double TwoPathChart::xOf(double seconds) const
{
    const double end = timeline_ ? std::max(timeline_->seconds(), 1e-3) : 1.0;
    return kLabelWidth + seconds / end * std::max(1, width() - kLabelWidth - kRight);
}

QRectF TwoPathChart::laneOf(std::size_t path) const
{
    return QRectF(kLabelWidth, kTop + static_cast<double>(path) * (kLane + kGap), width() - kLabelWidth - kRight, kLane);
}

std::vector<TwoPathChart::Bar> TwoPathChart::bars() const
{
    std::vector<Bar> out;
    if (!timeline_) return out;
    for (std::size_t p = 0; p < names_.size(); ++p) {
        const QRectF lane = laneOf(p);
        for (const TimelineStretch& s : timelineStretches(*timeline_, p)) {
            // A wait met at once: a thin mark of its own.
            const double x0 = xOf(s.from), x1 = std::max(xOf(s.to), x0 + (s.kind == TimelineStretch::Wait ? 2.0 : 0.5));
            out.push_back({p, s, QRectF(x0, lane.top(), x1 - x0, lane.height())});
        }
    }
    return out;
}

std::vector<TwoPathChart::WaitLine> TwoPathChart::waitLines() const
{
    std::map<int, double> at;  // code: when the paths go on
    if (timeline_)
        for (std::size_t p = 0; p < names_.size(); ++p)
            for (const TimelineStretch& s : timelineStretches(*timeline_, p))
                if (s.kind == TimelineStretch::Wait) at[s.waitCode] = std::max(at[s.waitCode], s.to);
    if (timeline_ && endWait_) at[*endWait_] = timeline_->seconds();
    std::vector<WaitLine> out;
    for (const auto& [code, t] : at) out.push_back({code, t, xOf(t)});
    return out;
}

QString TwoPathChart::laneLabel(std::size_t path) const
{
    return path < names_.size() ? tr("Path %1 (%2)").arg(path + 1).arg(localPathName(names_[path])) : QString();
}

QString TwoPathChart::textOf(const TimelineStretch& s) const
{
    switch (s.kind) {
    case TimelineStretch::In:
        return s.dwell > 0 ? tr("CB%1 in, dwell %2 s").arg(s.block).arg(s.dwell, 0, 'f', 3) : tr("CB%1 in").arg(s.block);
    case TimelineStretch::Cut: return tr("CB%1 cut").arg(s.block);
    case TimelineStretch::Out: return tr("CB%1 out").arg(s.block);
    case TimelineStretch::Wait: return s.to > s.from ? tr("M%1 wait").arg(s.waitCode) : tr("M%1 met").arg(s.waitCode);
    case TimelineStretch::Tail: return tr("back to the safe point, end wait");
    }
    return {};
}

void TwoPathChart::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    if (!timeline_) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter, tr("No balanced roughing on the timeline"));
        return;
    }
    p.setPen(palette().color(QPalette::Text));
    for (std::size_t k = 0; k < names_.size(); ++k) {
        const QRectF lane = laneOf(k);
        // A swatch of the colour the 3-D view draws the path's tool in, then its name.
        const double swatch = std::min(10.0, lane.height() - 4);
        p.fillRect(QRectF(4, lane.center().y() - swatch / 2, swatch, swatch), turretColour(k));
        p.drawText(QRectF(8 + swatch, lane.top(), kLabelWidth - 12 - swatch, lane.height()), Qt::AlignVCenter | Qt::AlignLeft,
                   laneLabel(k));
    }
    const std::vector<Bar> all = bars();
    const QFontMetrics fm(font());
    for (const Bar& b : all) {
        if (b.stretch.kind == TimelineStretch::Wait) continue;  // over the others, below
        p.fillRect(b.rect, colourOf(b.stretch.kind));
        if (b.stretch.dwell > 0) {
            // The dwell stands right before the cut: the end of the way in.
            const double x0 = std::max(b.rect.left(), xOf(b.stretch.to - b.stretch.dwell));
            p.fillRect(QRectF(x0, b.rect.top(), std::max(1.5, b.rect.right() - x0), b.rect.height()), kDwell);
        }
        if (b.stretch.kind == TimelineStretch::Cut) {
            const QString label = QStringLiteral("CB%1").arg(b.stretch.block);
            if (fm.horizontalAdvance(label) + 4 < b.rect.width()) {
                p.setPen(Qt::white);
                p.drawText(b.rect, Qt::AlignCenter, label);
            }
        }
    }
    for (const Bar& b : all)
        if (b.stretch.kind == TimelineStretch::Wait) p.fillRect(b.rect, colourOf(TimelineStretch::Wait));
    if (selected_ > 0) {
        p.setPen(QPen(palette().color(QPalette::Highlight), 2.0));
        for (const Bar& b : all)
            if (b.stretch.block == selected_ && b.stretch.kind != TimelineStretch::Wait) p.drawRect(b.rect.adjusted(1, 1, -1, -1));
    }
    // The waits, over the outline: where the paths go on together, across the lanes, with the code.
    const double top = laneOf(0).top() - 2, bottom = laneOf(names_.size() - 1).bottom() + 2;
    for (const WaitLine& w : waitLines()) {
        p.setPen(QPen(colourOf(TimelineStretch::Wait), 1.0, Qt::DashLine));
        p.drawLine(QPointF(w.x, top), QPointF(w.x, bottom));
        p.setPen(colourOf(TimelineStretch::Wait));
        p.drawText(QRectF(w.x - 30, 0, 60, kTop - 2), Qt::AlignHCenter | Qt::AlignBottom, QStringLiteral("M%1").arg(w.code));
    }
    // The time axis: seconds, ticks at a round step.
    const double end = timeline_->seconds();
    const double raw = end / 8.0;
    const double mag = std::pow(10.0, std::floor(std::log10(std::max(raw, 1e-3))));
    const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
    const double axis = bottom + 2;
    p.setPen(palette().color(QPalette::Text));
    p.drawLine(QPointF(xOf(0), axis), QPointF(xOf(end), axis));
    for (double t = 0; t <= end + 1e-9; t += step) {
        p.drawLine(QPointF(xOf(t), axis), QPointF(xOf(t), axis + 3));
        p.drawText(QRectF(xOf(t) - 30, axis + 3, 60, kAxis - 4), Qt::AlignHCenter | Qt::AlignTop, QString::number(t, 'g', 4));
    }
    p.drawText(QRectF(4, axis + 3, kLabelWidth - 8, kAxis - 4), Qt::AlignLeft | Qt::AlignTop,
               tr("%1 s on %2 paths").arg(end, 0, 'f', 2).arg(names_.size()));
}

void TwoPathChart::mousePressEvent(QMouseEvent* e)
{
    for (const Bar& b : bars())
        if (b.stretch.block > 0 && b.rect.contains(e->position())) {
            selectBlock(b.stretch.block);
            emit blockClicked(b.stretch.block);
            return;
        }
    QWidget::mousePressEvent(e);
}

bool TwoPathChart::event(QEvent* e)
{
    if (e->type() == QEvent::ToolTip) {
        const auto* h = static_cast<QHelpEvent*>(e);
        for (const Bar& b : bars())
            if (b.rect.adjusted(-1, 0, 1, 0).contains(h->pos())) {
                QToolTip::showText(h->globalPos(), tr("Path %1: %2, %3–%4 s")
                                                       .arg(b.path + 1)
                                                       .arg(textOf(b.stretch))
                                                       .arg(b.stretch.from, 0, 'f', 2)
                                                       .arg(b.stretch.to, 0, 'f', 2),
                                   this);
                return true;
            }
        QToolTip::hideText();
        return true;
    }
    return QWidget::event(e);
}

}  // namespace taiwa::ui
