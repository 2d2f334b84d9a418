// Drawing an area's passes in the Figure tab (passes_bar.h).
#include "ui/passes_bar.h"

#include "figure/figure_eval.h"
#include "modules/named_region.h"
#include "modules/registry.h"
#include "paths/drawn_passes.h"
#include "ui/figure_view.h"
#include "ui/job_document.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace taiwa::ui {

namespace {

constexpr double kChord = 1e-3;  // mm: rings drawn from the exact contours

std::vector<Point2> scaled(std::vector<Point2> points, double f)
{
    for (Point2& p : points) p = f * p;
    return points;
}

}  // namespace

PassesBar::PassesBar(JobDocument* doc, FigureView* view, QWidget* parent) : QWidget(parent), doc_(doc), view_(view)
{
    setObjectName("figure.passes");
    // The buttons, and under them the line (so that the bar is no wider
    // than the figure panel's other rows).
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setSpacing(2);
    auto* row = new QHBoxLayout;
    rows->addLayout(row);
    const auto button = [&](const QString& name) {
        auto* b = new QToolButton(this);
        b->setObjectName(name);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        row->addWidget(b);
        return b;
    };
    draw_ = button("figure.drawPasses");
    draw_->setCheckable(true);
    removeLast_ = button("figure.removePoint");
    clear_ = button("figure.clearPasses");
    nameButtons();
    text_ = new QLabel(this);
    text_->setObjectName("figure.passesText");
    text_->setWordWrap(true);
    row->addStretch(1);
    rows->addWidget(text_);
    hide();

    connect(draw_, &QToolButton::toggled, view_, &FigureView::setDrawing);
    connect(view_, &FigureView::pointDrawn, this, &PassesBar::addPoint);
    connect(removeLast_, &QToolButton::clicked, this, [this] {
        const auto& unit = doc_->job().units[static_cast<std::size_t>(unit_)];
        auto points = moduleKind(unit.module).drawnPasses(unit.module)->points;
        if (points.empty()) return;
        points.pop_back();
        setPoints(std::move(points), tr("Remove the last point of the passes"));
    });
    connect(clear_, &QToolButton::clicked, this, [this] { setPoints({}, tr("Clear the passes")); });
}

void PassesBar::nameButtons()
{
    draw_->setText(tr("Draw passes"));
    draw_->setToolTip(tr("Click in the view: the first point is where the tool starts, each next one ends a pass"));
    removeLast_->setText(tr("Remove last point"));
    removeLast_->setToolTip(tr("Take back the last point drawn"));
    clear_->setText(tr("Clear"));
    clear_->setToolTip(tr("Remove every pass of this unit"));
}

void PassesBar::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange || !clear_) return;
    nameButtons();
    refresh();
}

double PassesBar::grid() const { return doc_->job().lengthUnit == LengthUnit::Inch ? 0.01 : 0.5; }

bool PassesBar::hasPasses() const
{
    const auto& units = doc_->job().units;
    if (unit_ < 0 || unit_ >= static_cast<int>(units.size())) return false;
    const ModuleInput& m = units[static_cast<std::size_t>(unit_)].module;
    const ModuleKind* kind = findModuleKind(m.name());
    return kind && kind->drawnPasses(m);
}

void PassesBar::setUnit(int unit)
{
    unit_ = unit;
    refresh();
}

void PassesBar::addPoint(Point2 at)
{
    if (!hasPasses()) return;
    const double g = grid();
    const Point2 snapped{std::round(at.x / g) * g, std::round(at.y / g) * g};
    const auto& unit = doc_->job().units[static_cast<std::size_t>(unit_)];
    auto points = moduleKind(unit.module).drawnPasses(unit.module)->points;
    if (!points.empty() && distance(points.back(), snapped) < 1e-9) return;  // a double click: no empty pass
    points.push_back(snapped);
    setPoints(std::move(points), points.size() == 1 ? tr("Draw the start point of the passes") : tr("Draw a pass"));
}

void PassesBar::setPoints(std::vector<Point2> points, const QString& what)
{
    Job job = doc_->job();
    ModuleInput& m = job.units[static_cast<std::size_t>(unit_)].module;
    if (!moduleKind(m).setDrawnPoints(m, std::move(points))) return;
    doc_->edit(job, what, {}, unit_);
}

void PassesBar::refresh()
{
    if (!hasPasses()) {
        draw_->setChecked(false);
        view_->setPasses(std::nullopt);
        hide();
        return;
    }
    show();
    const Job& job = doc_->job();
    const ModuleInput& m = job.units[static_cast<std::size_t>(unit_)].module;
    const DrawnPasses passes = *moduleKind(m).drawnPasses(m);
    removeLast_->setEnabled(!passes.points.empty());
    clear_->setEnabled(!passes.points.empty());
    PassesOverlay overlay;
    overlay.points = passes.points;
    overlay.radius = passes.radius;
    // The area from the contours the view draws (in the job's unit).
    const figure::Evaluation& e = view_->evaluation();
    const figure::EvaluatedContour* outline = e.findContour(passes.outline);
    Region region;
    bool whole = outline && outline->contour.closed;
    if (whole) region.outer = outline->contour;
    for (const std::string& name : passes.islands) {
        const figure::EvaluatedContour* island = e.findContour(name);
        if (!island || !island->contour.closed) whole = false;
        else region.islands.push_back(island->contour);
    }
    const int count = std::max(0, static_cast<int>(passes.points.size()) - 1);
    QString line = passes.points.empty() ? tr("No pass drawn: press Draw passes and click where the tool starts.")
                      : count == 0                ? tr("The start point is drawn: click where the first pass ends.")
                      : count == 1                ? tr("1 pass drawn.")
                                                  : tr("%1 passes drawn.").arg(count);
    bool bad = false;
    if (!whole) {
        line += QStringLiteral(" ") + tr("The area %1 is not a closed contour of the figure.")
                                          .arg(QString::fromStdString(passes.outline));
        bad = true;
    } else {
        region = normalised(region);
        overlay.area.push_back(flatten(region.outer, kChord));
        for (const auto& i : region.islands) overlay.area.push_back(flatten(i, kChord));
        // Measured in mm (the unswept threshold is in mm²), shown in the job's unit.
        const double toMm = job.lengthUnit == LengthUnit::Inch ? 25.4 : 1.0;
        Region mm = region;
        convertRegionLengths(mm, [toMm](double v) { return v * toMm; });
        const auto points = scaled(passes.points, toMm);
        const double r = passes.radius * toMm;
        if (r > 0.0 && !points.empty()) {
            if (const auto out = paths::firstExcursion(mm, points, r)) {
                line += QStringLiteral(" ") + (out->pass == 0 ? tr("The start point is too near the walls.")
                                                              : tr("Pass %1 leaves the area.").arg(out->pass));
                bad = true;
            }
            const paths::Unswept u = paths::unsweptArea(mm, points, r);
            for (const auto& ring : u.rings) overlay.unswept.push_back(scaled(ring, 1.0 / toMm));
            if (count > 0) {
                const bool inch = job.lengthUnit == LengthUnit::Inch;
                const QString amount = QString::number(inch ? u.area / (25.4 * 25.4) : u.area, 'f', inch ? 4 : 1) +
                                       (inch ? QStringLiteral(" in²") : QStringLiteral(" mm²"));
                line += QStringLiteral(" ") + (u.pieces == 0   ? tr("The strips sweep the whole area.")
                                               : u.pieces == 1 ? tr("Unswept: %1 in one place.").arg(amount)
                                                               : tr("Unswept: %1 in %2 places.").arg(amount).arg(u.pieces));
            }
        }
    }
    text_->setText(line);
    text_->setStyleSheet(bad ? QStringLiteral("color: #a00000;") : QString());
    view_->setPasses(std::move(overlay));
}

}  // namespace taiwa::ui
