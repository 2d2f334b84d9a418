// A unit's live figure (model/sketch.h) in the station's form: the marked
// points with their labels, the outlines and the centre, scaled to fit with
// y up, and the sketch's lines of text under it (in red when they say what
// is wrong). Hidden for modules that have no sketch.
#pragma once

#include "model/sketch.h"

#include <QWidget>

#include <optional>

class QLabel;

namespace taiwa::ui {

class SketchView : public QWidget {
    Q_OBJECT
public:
    explicit SketchView(QWidget* parent = nullptr);
    void setSketch(std::optional<Sketch> sketch);
    const std::optional<Sketch>& sketch() const { return sketch_; }

private:
    class Figure;
    Figure* figure_ = nullptr;
    QLabel* text_ = nullptr;
    std::optional<Sketch> sketch_;
};

}  // namespace taiwa::ui
