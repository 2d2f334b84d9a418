// The module palette: one button per machining module, each showing the
// module's drawing with the dimension symbols of the part drawing (M4: P1..P4,
// r1, T, S; M2D: L1, L2, θ1, θ2, T, r1). A click adds a unit of that module.
#pragma once

#include <QPixmap>
#include <QWidget>

namespace taiwa::ui {

// The drawing of a module ("m4", "m2d") rendered at `width` pixels wide.
QPixmap moduleDrawing(const QString& module, int width);

class ModulePalette : public QWidget {
    Q_OBJECT
public:
    explicit ModulePalette(QWidget* parent = nullptr);

signals:
    void addModule(const QString& module);  // "m4", "m2d"
};

}  // namespace taiwa::ui
