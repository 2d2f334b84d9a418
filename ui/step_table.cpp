// The step list table.
#include "ui/step_table.h"

#include "ui/number_text.h"

#include <QHeaderView>

#include <cmath>

namespace taiwa::ui {

StepTable::StepTable(QWidget* parent) : QTableWidget(0, 7, parent)
{
    setObjectName("steps");
    setHorizontalHeaderLabels({tr("No."), tr("Unit"), tr("Step"), tr("Tool"), tr("Start"), tr("Depth"), tr("Time")});
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    verticalHeader()->hide();
    horizontalHeader()->setStretchLastSection(true);
}

void StepTable::setPlan(const std::shared_ptr<const Plan>& plan)
{
    setRowCount(0);
    if (!plan) return;
    const Job& job = plan->job;
    const double toJob = job.lengthUnit == LengthUnit::Inch ? 1.0 / kMillimetresPerInch : 1.0;
    setRowCount(static_cast<int>(plan->steps.size()));
    for (std::size_t i = 0; i < plan->steps.size(); ++i) {
        const Step& s = plan->steps[i];
        const int r = static_cast<int>(i);
        QString unit = QString::number(s.unit + 1);
        if (s.unit >= 0 && static_cast<std::size_t>(s.unit) < job.units.size() && !job.units[s.unit].name.empty())
            unit += " " + QString::fromStdString(job.units[s.unit].name);
        auto round = [toJob](double mm) { return formatNumber(std::round(mm * toJob * 1e4) / 1e4); };
        setItem(r, 0, new QTableWidgetItem(QString::number(r + 1)));
        setItem(r, 1, new QTableWidgetItem(unit));
        setItem(r, 2, new QTableWidgetItem(QString::fromStdString(s.label())));
        QString tool = QStringLiteral("–");
        if (s.tool) {
            tool = QStringLiteral("T%1").arg(s.tool->toolId);
            if (const Tool* t = plan->tool(s.tool->toolId)) tool += " " + QString::fromStdString(t->name);
        }
        setItem(r, 3, new QTableWidgetItem(tool));
        setItem(r, 4, new QTableWidgetItem(round(s.startDepth)));
        setItem(r, 5, new QTableWidgetItem(round(s.cutDepth)));
        auto* time = new QTableWidgetItem(s.minutes ? clockTime(*s.minutes) : QString());
        time->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(r, 6, time);
    }
    resizeColumnsToContents();
}

QStringList StepTable::stepLabels() const
{
    QStringList out;
    for (int r = 0; r < rowCount(); ++r) out << item(r, 2)->text();
    return out;
}

}  // namespace taiwa::ui
