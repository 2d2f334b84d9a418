// The 2-D view of a turned profile (module TURN): the half-section with Z to
// the right and X (a diameter) upward, the bar, the axis, the profile as
// drawn with its edge ids, and the deformed profile the lathe must cut
// (grinding allowances and relief grooves). A click picks the nearest edge;
// a picked edge and the corners under revision are highlighted. The wheel
// zooms about the pointer (a 0.5 mm grinding allowance is seen at the edge
// it is on; the form around does not scroll), a double click on an edge
// frames it (zoomToEdge), elsewhere or zoomed in fits the whole. Painted with
// QPainter (docs/turning.md "The profile view" says why not VTK).
#pragma once

#include "model/job.h"
#include "model/plan.h"
#include "model/turned.h"

#include <QImage>
#include <QStringList>
#include <QWidget>

#include <optional>

namespace taiwa::ui {

class ProfileView : public QWidget {
    Q_OBJECT
public:
    explicit ProfileView(QWidget* parent = nullptr);

    // The profile as drawn (edges the table could build), the deformed one
    // (nullopt: none yet, or input errors) and the bar (lathe jobs).
    void setProfile(turning::ResolvedProfile profile, std::optional<turning::DeformedProfile> deformed,
                    std::optional<BarStock> bar);
    void setSelectedEdge(const QString& id);
    QString selectedEdge() const { return selected_; }
    // Corners under revision, drawn in their own colour; empty: none.
    void setHighlightedCorners(const QStringList& ids);
    const QStringList& highlightedCorners() const { return corners_; }
    const turning::ResolvedProfile& profile() const { return profile_; }
    const std::optional<turning::DeformedProfile>& deformed() const { return deformed_; }

    // Where a point of the half-section (Z, diameter) is drawn, in widget pixels.
    QPointF toPixel(double z, double diameter) const;
    // The edge nearest to a pixel within a few pixels; empty when none.
    QString edgeAt(QPointF pixel) const;

    QSize sizeHint() const override { return {520, 260}; }

    // The allowances and grooves drawn `factor` times as far from the
    // profile as they are (1: true to scale): each drawn point of a
    // deformed edge moved away from its nearest point on the profile as
    // drawn. A 0.5 mm grinding allowance is seen at the whole part's scale
    // at 10x. The profile and the bar stay true.
    void setExaggeration(double factor);
    double exaggeration() const { return exaggeration_; }
    // Where a point of a deformed edge is drawn, exaggerated (in the
    // half-section's Z and radius, mm).
    turning::ZR exaggerated(turning::ZR p) const;

    // How far the view is zoomed in (1: the whole fits); back to 1 by fit().
    double zoom() const { return zoom_; }
    void fit();
    // Frames the edge `id` (as drawn and as cut) with a margin; false when the profile has no such edge.
    bool zoomToEdge(const QString& id);

signals:
    void edgePicked(const QString& id);

protected:
    void paintEvent(QPaintEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;

private:
    struct Frame {
        double scale = 1.0, z0 = 0.0, r0 = 0.0, left = 0.0, bottom = 0.0;
    };
    Frame frame() const;
    QPointF px(const Frame& f, turning::ZR p) const;
    QPolygonF polyline(const Frame& f, const turning::Segment& s) const;
    // A deformed edge's polyline, exaggerated (setExaggeration).
    QPolygonF exaggeratedPolyline(const Frame& f, const turning::Segment& s) const;
    double exaggeration_ = 1.0;

    turning::ResolvedProfile profile_;
    std::optional<turning::DeformedProfile> deformed_;
    std::optional<BarStock> bar_;
    QString selected_;
    QStringList corners_;
    // The zoom on the fitted drawing, in pixels: shown = shift_ + zoom_ x fitted.
    double zoom_ = 1.0;
    QPointF shift_;
};

// Every turned unit of a lathe plan in its profile view, one under the
// other, as a picture of width x height pixels (`taiwa render --view
// profile`); needs a QApplication.
QImage profileImage(const Plan& plan, int width, int height);

}  // namespace taiwa::ui
