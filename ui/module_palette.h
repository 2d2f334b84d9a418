// The module palette: one button per machining module kind (in the order of
// core/modules/registry.cpp), each showing the module's drawing with the
// dimension symbols of the part drawing. A click adds a unit of that module.
#pragma once

#include "machine/machine.h"

#include <QPixmap>
#include <QWidget>

#include <vector>

class QToolButton;

namespace taiwa::ui {

// A module's drawing (its Qt resource path, ModuleKind::drawing()) rendered
// at `width` pixels wide.
QPixmap moduleDrawing(const QString& resource, int width);
// The same with the symbol of id `highlight` ("sym-T") marked: a yellow
// band behind it and a frame around it; unmarked when the id is not there.
QPixmap moduleDrawing(const QString& resource, int width, const QString& highlight);

class ModulePalette : public QWidget {
    Q_OBJECT
public:
    explicit ModulePalette(QWidget* parent = nullptr);
    // Shows the modules of that machine kind only (milling modules on a
    // mill, turning modules on a lathe).
    void setMachineKind(MachineKind kind);

signals:
    void addModule(const QString& module);  // the module kind's name: "M4", "M2D"

protected:
    // The language switched: the buttons' words in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameButtons();
    std::vector<QToolButton*> buttons_;  // one per module kind, in the registry's order
};

}  // namespace taiwa::ui
