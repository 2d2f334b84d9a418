// The 3-D view's section plane (section_bar.h).
#include "ui/section_bar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::ui {

namespace {

constexpr int kSteps = 1000;  // the slider's positions across the stock

enum Axis { Off, AcrossX, AcrossY, AcrossZ };

}  // namespace

SectionBar::SectionBar(QWidget* parent)
    : QWidget(parent), axis_(new QComboBox(this)), position_(new QSlider(Qt::Horizontal, this)), angle_(new QSpinBox(this)),
      flip_(new QToolButton(this)), value_(new QLabel(this))
{
    axis_->setObjectName("section.axis");
    axis_->addItem(tr("No section"));
    axis_->addItem(tr("Section across X"));
    axis_->addItem(tr("Section across Y"));
    axis_->addItem(tr("Section across Z"));
    axis_->setToolTip(tr("Cut the stock open along a plane to see inside it"));
    position_->setObjectName("section.position");
    position_->setRange(0, kSteps);
    position_->setValue(kSteps / 2);
    position_->setToolTip(tr("Where the plane cuts the stock"));
    angle_->setObjectName("section.angle");
    angle_->setRange(-90, 90);
    angle_->setSuffix(QStringLiteral("°"));
    angle_->setToolTip(tr("A plane across X or Y turned about Z"));
    flip_->setObjectName("section.flip");
    flip_->setText(tr("Flip"));
    flip_->setCheckable(true);
    flip_->setToolTip(tr("Take away the material on the other side of the plane"));
    value_->setObjectName("section.value");
    value_->setMinimumWidth(value_->fontMetrics().horizontalAdvance(QStringLiteral("X -0000.00 mm")));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(axis_);
    row->addWidget(position_, 1);
    row->addWidget(value_);
    row->addWidget(angle_);
    row->addWidget(flip_);
    connect(axis_, &QComboBox::currentIndexChanged, this, &SectionBar::announce);
    connect(position_, &QSlider::valueChanged, this, &SectionBar::announce);
    connect(angle_, &QSpinBox::valueChanged, this, &SectionBar::announce);
    connect(flip_, &QToolButton::toggled, this, &SectionBar::announce);
    setStock(std::nullopt);
}

void SectionBar::setStock(std::optional<Stock> stock, LengthUnit unit)
{
    stock_ = stock;
    unit_ = unit;
    setEnabled(stock_.has_value());
    announce();
}

std::optional<viz::SectionPlane> SectionBar::plane() const
{
    const int axis = axis_->currentIndex();
    if (!stock_ || axis == Off) return std::nullopt;
    const Stock& s = *stock_;
    Point3 n{0.0, 0.0, 1.0};
    if (axis != AcrossZ) {
        const double a = (axis == AcrossX ? 0.0 : 90.0) + angle_->value();
        const double r = a * std::numbers::pi / 180.0;
        n = {std::cos(r), std::sin(r), 0.0};
    }
    // The slider runs over the stock's extent along the normal.
    double lo = 1e300, hi = -1e300;
    for (const double x : {s.x, s.x + s.width})
        for (const double y : {s.y, s.y + s.length})
            for (const double z : {-s.height, 0.0}) {
                const double d = n.x * x + n.y * y + n.z * z;
                lo = std::min(lo, d);
                hi = std::max(hi, d);
            }
    const double d = lo + (hi - lo) * position_->value() / kSteps;
    const Point3 centre{s.x + s.width / 2, s.y + s.length / 2, -s.height / 2};
    const double along = d - (n.x * centre.x + n.y * centre.y + n.z * centre.z);
    viz::SectionPlane p;
    p.origin = {centre.x + along * n.x, centre.y + along * n.y, centre.z + along * n.z};
    p.normal = flip_->isChecked() ? Point3{-n.x, -n.y, -n.z} : n;
    return p;
}

void SectionBar::announce()
{
    const int axis = axis_->currentIndex();
    const bool on = stock_ && axis != Off;
    position_->setEnabled(on);
    angle_->setEnabled(on && axis != AcrossZ);
    flip_->setEnabled(on);
    const std::optional<viz::SectionPlane> p = plane();
    if (p) {
        // Where the plane cuts, on its own axis (a turned plane: through the stock's middle).
        const double at = axis == AcrossX ? p->origin.x : axis == AcrossY ? p->origin.y : p->origin.z;
        const QString name = axis == AcrossX ? QStringLiteral("X") : axis == AcrossY ? QStringLiteral("Y") : QStringLiteral("Z");
        value_->setText(QStringLiteral("%1 %2 %3")
                            .arg(name, QLocale().toString(fromMm(at, unit_), 'f', unit_ == LengthUnit::Inch ? 3 : 1),
                                 QString::fromUtf8(unitSymbol(unit_))));
    } else {
        value_->clear();
    }
    if (p == announced_) return;
    announced_ = p;
    emit sectionChanged(p);
}

}  // namespace taiwa::ui
