// The module palette and the module drawings (SVG from resources/modules).
#include "ui/module_palette.h"

#include <QHBoxLayout>
#include <QPainter>
#include <QSvgRenderer>
#include <QToolButton>

namespace taiwa::ui {

QPixmap moduleDrawing(const QString& module, int width)
{
    QSvgRenderer svg(QStringLiteral(":/modules/%1.svg").arg(module));
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
    auto* box = new QHBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    const std::pair<QString, QString> modules[] = {{"m4", tr("Add M4 pocket")}, {"m2d", tr("Add M2D 3-D pocket")}};
    for (const auto& [module, text] : modules) {
        auto* b = new QToolButton(this);
        b->setObjectName(QStringLiteral("unit.add%1").arg(module.toUpper()));
        b->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
        const QPixmap drawing = moduleDrawing(module, 140);
        b->setIcon(QIcon(drawing));
        b->setIconSize(drawing.size());
        b->setText(text);
        b->setToolTip(text);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        connect(b, &QToolButton::clicked, this, [this, module] { emit addModule(module); });
        box->addWidget(b);
    }
}

}  // namespace taiwa::ui
