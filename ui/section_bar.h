// The section plane of the station's 3-D view, in one row under it: off, or
// a plane across X, Y or Z moved through the stock by a slider; a plane
// across X or Y turned about Z by an angle, so that any vertical plane can be
// had; flipped to look from the other side. It announces the plane
// (viz::SectionPlane) for the preview (viz::Scene::setSection).
#pragma once

#include "model/job.h"
#include "viz/render.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace taiwa::ui {

class SectionBar : public QWidget {
    Q_OBJECT
public:
    explicit SectionBar(QWidget* parent = nullptr);

    // The stock the plane moves through (in mm), shown in `unit`; nothing:
    // a lathe job (its view is a section already) or no plan: the bar is
    // disabled and announces no plane.
    void setStock(std::optional<Stock> stock, LengthUnit unit = LengthUnit::Millimetre);
    // The plane chosen now, if any.
    std::optional<viz::SectionPlane> plane() const;

    QComboBox* axisChooser() const { return axis_; }
    QSlider* slider() const { return position_; }
    QSpinBox* angle() const { return angle_; }
    QToolButton* flip() const { return flip_; }

signals:
    void sectionChanged(std::optional<taiwa::viz::SectionPlane> plane);

private:
    void announce();

    QComboBox* axis_;
    QSlider* position_;
    QSpinBox* angle_;
    QToolButton* flip_;
    QLabel* value_;
    std::optional<Stock> stock_;
    LengthUnit unit_ = LengthUnit::Millimetre;
    std::optional<viz::SectionPlane> announced_;
};

}  // namespace taiwa::ui
