// The unit list and its buttons.
#include "ui/unit_list_panel.h"

#include "job/placement.h"
#include "modules/registry.h"

#include "ui/job_document.h"

#include <QEvent>
#include <QGridLayout>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace taiwa::ui {

UnitListPanel::UnitListPanel(JobDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc), list_(new QListWidget(this))
{
    list_->setObjectName("units");
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    box->addWidget(list_);
    auto* buttons = new QGridLayout;
    auto add = [&](const char* name, int r, int c, void (UnitListPanel::*slot)()) {
        auto* b = new QPushButton(this);
        b->setObjectName(name);
        connect(b, &QPushButton::clicked, this, slot);
        buttons->addWidget(b, r, c);
    };
    // Two by two: the column stays narrow (a 1280-pixel screen).
    add("unit.duplicate", 0, 0, &UnitListPanel::duplicate);
    add("unit.up", 0, 1, &UnitListPanel::moveUp);
    add("unit.down", 1, 1, &UnitListPanel::moveDown);
    add("unit.delete", 1, 0, &UnitListPanel::remove);
    nameButtons();
    box->addLayout(buttons);
    connect(list_, &QListWidget::currentRowChanged, this, &UnitListPanel::currentUnitChanged);
}

void UnitListPanel::nameButtons()
{
    const std::pair<const char*, QString> names[] = {{"unit.duplicate", tr("D&uplicate")}, {"unit.up", tr("▲ U&p")},
                                                     {"unit.down", tr("▼ Do&wn")}, {"unit.delete", tr("De&lete")}};
    for (const auto& [name, text] : names) findChild<QPushButton*>(QString::fromLatin1(name))->setText(text);
}

void UnitListPanel::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() == QEvent::LanguageChange) nameButtons();
}

int UnitListPanel::currentUnit() const { return list_->currentRow(); }

void UnitListPanel::selectUnit(int unit)
{
    if (unit >= list_->count()) unit = list_->count() - 1;
    list_->setCurrentRow(unit);
    emit currentUnitChanged(list_->currentRow());
}

void UnitListPanel::refresh()
{
    const auto& units = doc_->job().units;
    const int keep = list_->currentRow();
    const QSignalBlocker block(list_);
    while (list_->count() > static_cast<int>(units.size())) delete list_->takeItem(list_->count() - 1);
    for (std::size_t i = 0; i < units.size(); ++i) {
        QString text = QStringLiteral("%1 %2").arg(i + 1).arg(units[i].module.name());
        if (!units[i].name.empty()) text += " " + QString::fromStdString(units[i].name);
        if (static_cast<int>(i) < list_->count()) list_->item(static_cast<int>(i))->setText(text);
        else list_->addItem(text);
    }
    list_->setCurrentRow(std::min(keep, list_->count() - 1));
}

void UnitListPanel::addUnit(const QString& module)
{
    const ModuleKind* kind = findModuleKind(module.toStdString());
    if (!kind) return;
    Job j = doc_->job();
    // The module's default unit is in mm: in the job's own unit, then in free stock.
    ModuleInput unit = kind->makeDefault(toMillimetres(j).stock);
    const LengthUnit lu = j.lengthUnit;
    unit.convertLengths([lu](double v) { return fromMm(v, lu); });
    // A contour unit in a job without figure elements: a first contour for it.
    if (j.figure.empty()) j.figure = kind->defaultFigure(j.stock);
    // No free place (the stock looks full): at the module's default place
    // all the same, its overlap marked by the check; the operator types the
    // real corners next (the window puts the focus on the first).
    const auto free = placeInFreeStock(j, unit);
    j.units.push_back(MachiningUnit{"", free ? *free : unit});
    doc_->edit(j, tr("Add %1 unit").arg(module), {}, static_cast<int>(j.units.size()) - 1);
    if (!free)
        emit message(tr("Added where it overlaps another unit: the stock has no free place for it. Type its corners, "
                        "or make the stock larger."));
}

std::optional<ModuleInput> UnitListPanel::place(const Job& job, const ModuleInput& unit)
{
    auto free = placeInFreeStock(job, unit);
    if (!free)
        emit message(tr("No unit added: the stock has no free place for it. Make the stock larger or a unit smaller, "
                        "or move one."));
    return free;
}

void UnitListPanel::duplicate()
{
    const int u = currentUnit();
    if (u < 0) return;
    Job j = doc_->job();
    MachiningUnit copy = j.units[static_cast<std::size_t>(u)];
    const auto placed = place(j, copy.module);
    if (!placed) return;
    copy.module = *placed;
    j.units.insert(j.units.begin() + u + 1, std::move(copy));
    doc_->edit(j, tr("Duplicate unit %1").arg(u + 1), {}, u + 1);
}

void UnitListPanel::move(int delta)
{
    const int u = currentUnit();
    const int to = u + delta;
    Job j = doc_->job();
    if (u < 0 || to < 0 || to >= static_cast<int>(j.units.size())) return;
    std::swap(j.units[static_cast<std::size_t>(u)], j.units[static_cast<std::size_t>(to)]);
    doc_->edit(j, tr("Move unit %1").arg(u + 1), {}, to);
}

void UnitListPanel::remove()
{
    const int u = currentUnit();
    if (u < 0) return;
    Job j = doc_->job();
    j.units.erase(j.units.begin() + u);
    doc_->edit(j, tr("Delete unit %1").arg(u + 1), {}, std::max(0, u - 1));
}

}  // namespace taiwa::ui
