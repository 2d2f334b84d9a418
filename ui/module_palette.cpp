// The module palette and the module drawings (SVG from each module's folder,
// core/modules/<kind>/<kind>.svg, compiled in as Qt resources).
#include "ui/module_palette.h"

#include "modules/registry.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QPainter>
#include <QSvgRenderer>
#include <QToolButton>

namespace taiwa::ui {

QPixmap moduleDrawing(const QString& resource, int width)
{
    QSvgRenderer svg(resource);
    const QSize base = svg.defaultSize().isValid() ? svg.defaultSize() : QSize(420, 220);
    const QSize size(width, width * base.height() / base.width());
    QPixmap pm(size);
    pm.fill(Qt::white);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    svg.render(&p);
    return pm;
}

ModulePalette::ModulePalette(QWidget* parent) : QWidget(parent)
{
    // Two to a row, whatever the number of modules: the column stays narrow
    // enough for the form beside it on a 1280-pixel screen.
    auto* box = new QGridLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    for (const ModuleKind* kind : moduleKinds()) {
        const QString module = QString::fromUtf8(kind->name());
        const QString text = QCoreApplication::translate("taiwa::ui::ModulePalette", kind->paletteText());
        auto* b = new QToolButton(this);
        b->setObjectName(QStringLiteral("unit.add%1").arg(module));
        b->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
        const QPixmap drawing = moduleDrawing(QString::fromUtf8(kind->drawing()), 120);
        b->setIcon(QIcon(drawing));
        b->setIconSize(drawing.size());
        b->setText(text);
        b->setToolTip(text);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        connect(b, &QToolButton::clicked, this, [this, module] { emit addModule(module); });
        b->setProperty("machineKind", static_cast<int>(kind->machineKind()));
        buttons_.push_back(b);
    }
    setMachineKind(MachineKind::Mill);
}

void ModulePalette::setMachineKind(MachineKind kind)
{
    // The machine's modules, two to a row, in the registry's order.
    auto* grid = static_cast<QGridLayout*>(layout());
    int shown = 0;
    for (QToolButton* b : buttons_) {
        const bool mine = b->property("machineKind").toInt() == static_cast<int>(kind);
        grid->removeWidget(b);
        b->setVisible(mine);
        if (mine) grid->addWidget(b, shown / 2, shown % 2), ++shown;
    }
}

}  // namespace taiwa::ui
