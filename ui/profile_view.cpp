// The 2-D profile view of a turned profile (profile_view.h).
#include "ui/profile_view.h"

#include "model/plan.h"
#include "model/turned_geometry.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::ui {

namespace {

constexpr double kMargin = 28.0;   // px around the drawing
constexpr double kPickPixels = 8.0;

const QColor kProfile(0x1d, 0x35, 0x57);
const QColor kDeformed(0xc0, 0x39, 0x2b);
const QColor kSelected(0xff, 0x8c, 0x00);
const QColor kCorner(0xb0, 0x30, 0xc0);
const QColor kBar(0xe6, 0xe9, 0xee);

}  // namespace

ProfileView::ProfileView(QWidget* parent) : QWidget(parent)
{
    setMinimumHeight(180);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);  // as wide as the column, the drawing scaled to it
    setMinimumWidth(200);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setCursor(Qt::CrossCursor);
}

void ProfileView::setProfile(turning::ResolvedProfile profile, std::optional<turning::DeformedProfile> deformed,
                             std::optional<BarStock> bar)
{
    profile_ = std::move(profile);
    deformed_ = std::move(deformed);
    bar_ = bar;
    update();
}

void ProfileView::setSelectedEdge(const QString& id)
{
    if (id == selected_) return;
    selected_ = id;
    update();
}

void ProfileView::setHighlightedCorners(const QStringList& ids)
{
    corners_ = ids;
    update();
}

// The scale fits the profile, its deformation and the bar, keeping aspect.
ProfileView::Frame ProfileView::frame() const
{
    double zMin = 0, zMax = 0, rMax = 1;
    bool any = false;
    const auto grow = [&](turning::ZR p) {
        zMin = any ? std::min(zMin, p.z) : p.z;
        zMax = any ? std::max(zMax, p.z) : p.z;
        rMax = std::max(rMax, p.r);
        any = true;
    };
    for (const auto& e : profile_.edges) {
        grow(e.geometry.a);
        grow(e.geometry.b);
    }
    if (deformed_)
        for (const auto& e : deformed_->edges) {
            grow(e.geometry.a);
            grow(e.geometry.b);
        }
    if (bar_) {
        grow({bar_->face, bar_->diameter / 2});
        grow({bar_->face - bar_->length, bar_->diameter / 2});
    }
    if (!any) zMin = -10, zMax = 0;
    Frame f;
    const double w = std::max(1.0, width() - 2 * kMargin), h = std::max(1.0, height() - 2 * kMargin);
    f.scale = std::min(w / std::max(zMax - zMin, 1e-6), h / std::max(rMax * 1.05, 1e-6));
    f.z0 = zMin;
    f.left = kMargin + (w - f.scale * (zMax - zMin)) / 2;
    f.bottom = height() - kMargin;
    // The operator's zoom about a point of the fitted drawing.
    f.scale *= zoom_;
    f.left = shift_.x() + zoom_ * f.left;
    f.bottom = shift_.y() + zoom_ * f.bottom;
    return f;
}

void ProfileView::fit()
{
    zoom_ = 1.0;
    shift_ = {};
    update();
}

bool ProfileView::zoomToEdge(const QString& id)
{
    fit();
    const Frame f = frame();
    QRectF box;
    const auto add = [&](const turning::Segment& g) { box |= polyline(f, g).boundingRect(); };
    for (const auto& e : profile_.edges)
        if (QString::fromStdString(e.id) == id) add(e.geometry);
    if (deformed_)
        for (const auto& e : deformed_->edges)
            if (QString::fromStdString(e.id) == id || QString::fromStdString(e.from) == id) add(e.geometry);
    if (box.isNull()) return false;
    box.adjust(-8, -8, 8, 8);  // the edge never on the view's border
    const double k = std::clamp(std::min(width() / box.width(), height() / box.height()), 1.0, 2000.0);
    zoom_ = k;
    shift_ = QPointF(width(), height()) / 2 - k * box.center();
    update();
    return true;
}

// A double click on an edge frames it (zoomed in already: the whole again).
void ProfileView::mouseDoubleClickEvent(QMouseEvent* e)
{
    const QString id = edgeAt(e->position());
    if (id.isEmpty() || zoom_ > 1.0 || !zoomToEdge(id)) fit();
}

void ProfileView::wheelEvent(QWheelEvent* e)
{
    e->accept();  // the form around does not scroll under the view
    const double steps = e->angleDelta().y() / 120.0;
    if (steps == 0) return;
    const QPointF at = e->position();
    const double k = std::clamp(zoom_ * std::pow(1.2, steps), 1.0, 2000.0) / zoom_;
    // The point under the pointer stays under it: shown' = at + k (shown - at).
    zoom_ *= k;
    shift_ = at + k * (shift_ - at);
    update();
}

QPointF ProfileView::px(const Frame& f, turning::ZR p) const
{
    return {f.left + (p.z - f.z0) * f.scale, f.bottom - p.r * f.scale};
}

QPointF ProfileView::toPixel(double z, double diameter) const { return px(frame(), {z, diameter / 2}); }

// Arcs are drawn through points every 3° (the drawing only; the geometry
// stays exact).
QPolygonF ProfileView::polyline(const Frame& f, const turning::Segment& s) const
{
    QPolygonF poly;
    if (!s.arc) return QPolygonF{px(f, s.a), px(f, s.b)};
    const double len = turning::length(s);
    const int n = std::max(2, static_cast<int>(std::ceil(turning::sweep(s) / (3.0 * std::numbers::pi / 180.0))));
    for (int i = 0; i <= n; ++i) poly << px(f, turning::pointAt(s, len * i / n));
    return poly;
}

namespace {

// The point of `s` nearest to `p`.
turning::ZR nearestOn(const turning::Segment& s, turning::ZR p)
{
    const auto closer = [&](turning::ZR a, turning::ZR b) { return turning::dist(a, p) <= turning::dist(b, p) ? a : b; };
    if (!s.arc) {
        const double dz = s.b.z - s.a.z, dr = s.b.r - s.a.r, len2 = dz * dz + dr * dr;
        const double t = len2 > 0 ? std::clamp(((p.z - s.a.z) * dz + (p.r - s.a.r) * dr) / len2, 0.0, 1.0) : 0.0;
        return {s.a.z + t * dz, s.a.r + t * dr};
    }
    const double d = turning::dist(p, s.centre);
    if (d > 1e-12) {
        const turning::ZR onCircle{s.centre.z + (p.z - s.centre.z) * s.radius / d, s.centre.r + (p.r - s.centre.r) * s.radius / d};
        if (turning::contains(s, onCircle, 1e-6)) return onCircle;
    }
    return closer(s.a, s.b);
}

}  // namespace

void ProfileView::setExaggeration(double factor)
{
    exaggeration_ = std::max(1.0, factor);
    update();
}

turning::ZR ProfileView::exaggerated(turning::ZR p) const
{
    if (exaggeration_ == 1.0 || profile_.edges.empty()) return p;
    turning::ZR best = p;
    double bestDist = -1;
    for (const auto& e : profile_.edges) {
        const turning::ZR q = nearestOn(e.geometry, p);
        if (const double d = turning::dist(p, q); bestDist < 0 || d < bestDist) best = q, bestDist = d;
    }
    return {best.z + exaggeration_ * (p.z - best.z), std::max(0.0, best.r + exaggeration_ * (p.r - best.r))};
}

QPolygonF ProfileView::exaggeratedPolyline(const Frame& f, const turning::Segment& s) const
{
    if (exaggeration_ == 1.0) return polyline(f, s);
    // Points every 0.2 mm at most (and 48 at least), each moved off the profile.
    const double len = turning::length(s);
    const int n = std::clamp(static_cast<int>(std::ceil(len / 0.2)), 48, 4000);
    QPolygonF poly;
    for (int i = 0; i <= n; ++i) poly << px(f, exaggerated(turning::pointAt(s, len * i / n)));
    return poly;
}

QString ProfileView::edgeAt(QPointF pixel) const
{
    const Frame f = frame();
    QString best;
    double bestDist = kPickPixels;
    for (const auto& e : profile_.edges) {
        const QPolygonF poly = polyline(f, e.geometry);
        for (int i = 0; i + 1 < poly.size(); ++i) {
            const QPointF a = poly[i], b = poly[i + 1], ab = b - a;
            const double len2 = QPointF::dotProduct(ab, ab);
            const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(pixel - a, ab) / len2, 0.0, 1.0) : 0.0;
            const QPointF d = pixel - (a + t * ab);
            const double dist = std::hypot(d.x(), d.y());
            if (dist < bestDist) {
                bestDist = dist;
                best = QString::fromStdString(e.id);
            }
        }
    }
    return best;
}

void ProfileView::mousePressEvent(QMouseEvent* e)
{
    const QString id = edgeAt(e->position());
    if (id.isEmpty()) return;
    setSelectedEdge(id);
    emit edgePicked(id);
}

void ProfileView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), Qt::white);
    const Frame f = frame();
    if (bar_) {
        const QPointF tl = px(f, {bar_->face - bar_->length, bar_->diameter / 2});
        const QPointF br = px(f, {bar_->face, bar_->bore / 2});
        p.fillRect(QRectF(tl, br).normalized(), kBar);
    }
    // The axis, dash-dot.
    p.setPen(QPen(QColor(0x77, 0x77, 0x77), 1, Qt::DashDotLine));
    p.drawLine(QPointF(0, f.bottom), QPointF(width(), f.bottom));
    // The profile as drawn, then the deformed edges that differ from it.
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    p.setFont(small);
    for (const auto& e : profile_.edges) {
        const QString id = QString::fromStdString(e.id);
        const bool picked = id == selected_, corner = corners_.contains(id);
        const QColor c = picked ? kSelected : corner ? kCorner : kProfile;
        p.setPen(QPen(c, picked || corner ? 4 : 2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(polyline(f, e.geometry));
        if (e.corner && !corner && !picked) continue;  // chamfers and roundings keep their id off the drawing
        const QPointF m = px(f, turning::midpoint(e.geometry));
        p.setPen(c);
        p.drawText(m + QPointF(4, -4), id);
    }
    if (deformed_) {
        p.setPen(QPen(kDeformed, 1.5, Qt::DashLine));
        for (const auto& e : deformed_->edges)
            if (e.origin != turning::Origin::Original) p.drawPolyline(exaggeratedPolyline(f, e.geometry));
    }
    // Legend.
    p.setPen(kProfile);
    p.drawText(QPointF(6, 14), tr("Z →   X (diameter) ↑"));
    if (deformed_ && !deformed_->rows.empty()) {
        p.setPen(kDeformed);
        p.drawText(QPointF(6, 28), exaggeration_ == 1.0 ? tr("- - - to cut (grinding allowance)")
                                                        : tr("- - - to cut (grinding allowance, its depth drawn ×%1)").arg(exaggeration_));
    }
}

QImage profileImage(const Plan& plan, int width, int height)
{
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    const int n = std::max<int>(1, static_cast<int>(plan.turned.size()));
    QPainter painter(&image);
    for (int i = 0; i < static_cast<int>(plan.turned.size()); ++i) {
        const TurnedPart& part = plan.turned[static_cast<std::size_t>(i)];
        ProfileView view;
        view.resize(width, height / n);
        view.setProfile(part.profile, part.deformed, plan.mmJob.bar);
        painter.drawImage(0, i * (height / n), view.grab().toImage());
    }
    return image;
}

}  // namespace taiwa::ui
