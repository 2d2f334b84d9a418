// The module palette and the module drawings (SVG from each module's folder,
// core/modules/<kind>/<kind>.svg, compiled in as Qt resources, their labels
// in the station's language).
#include "ui/module_palette.h"

#include "modules/registry.h"
#include "ui/core_messages.h"

#include <QEvent>
#include <QCoreApplication>
#include <QFile>
#include <QGridLayout>
#include <QPainter>
#include <QSvgRenderer>
#include <QToolButton>

namespace taiwa::ui {

QPixmap moduleDrawing(const QString& resource, int width) { return moduleDrawing(resource, width, QString()); }

QPixmap moduleDrawing(const QString& resource, int width, const QString& highlight)
{
    QFile file(resource);
    QSvgRenderer svg(file.open(QIODevice::ReadOnly) ? translatedDrawing(file.readAll()) : QByteArray());
    const QSize base = svg.defaultSize().isValid() ? svg.defaultSize() : QSize(420, 220);
    const QSize size(width, width * base.height() / base.width());
    QPixmap pm(size);
    pm.fill(Qt::white);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    if (!highlight.isEmpty() && svg.elementExists(highlight)) {
        // The symbol's box in the drawing's coordinates, then in the pixmap's.
        const QRectF box = svg.transformForElement(highlight).mapRect(svg.boundsOnElement(highlight));
        const QRectF view = svg.viewBoxF().isValid() ? svg.viewBoxF() : QRectF(QPointF(0, 0), base);
        const double k = size.width() / view.width();
        const QRectF mark((box.left() - view.left()) * k - 4, (box.top() - view.top()) * k - 3, box.width() * k + 8,
                          box.height() * k + 6);
        p.setPen(QPen(QColor(192, 57, 43), 2));
        p.setBrush(QColor(255, 221, 87, 170));
        p.drawRoundedRect(mark, 4, 4);
    }
    svg.render(&p);
    return pm;
}

ModulePalette::ModulePalette(QWidget* parent) : QWidget(parent)
{
    // Two to a row, whatever the number of modules: the column stays narrow
    // enough for the form beside it on a 1280-pixel screen.
    auto* box = new QGridLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    // Drawings 120 pixels wide while a machine has at most eight modules
    // (four rows); smaller beyond, so that the column's rows still leave
    // the job's fields on a 720-pixel screen.
    int mills = 0;
    for (const ModuleKind* kind : moduleKinds()) mills += kind->machineKind() == MachineKind::Mill ? 1 : 0;
    const int drawingSize = mills > 8 ? 88 : 120;
    for (const ModuleKind* kind : moduleKinds()) {
        const QString module = QString::fromUtf8(kind->name());
        auto* b = new QToolButton(this);
        b->setObjectName(QStringLiteral("unit.add%1").arg(module));
        b->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
        const QPixmap drawing = moduleDrawing(QString::fromUtf8(kind->drawing()), drawingSize);
        b->setIcon(QIcon(drawing));
        b->setIconSize(drawing.size());
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        connect(b, &QToolButton::clicked, this, [this, module] { emit addModule(module); });
        b->setProperty("machineKind", static_cast<int>(kind->machineKind()));
        buttons_.push_back(b);
    }
    nameButtons();
    setMachineKind(MachineKind::Mill);
}

void ModulePalette::nameButtons()
{
    const auto kinds = moduleKinds();
    for (std::size_t i = 0; i < buttons_.size() && i < kinds.size(); ++i) {
        const QString text = QCoreApplication::translate("taiwa::ui::ModulePalette", kinds[i]->paletteText());
        buttons_[i]->setText(text);
        buttons_[i]->setToolTip(text);
    }
}

void ModulePalette::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() == QEvent::LanguageChange) nameButtons();
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
