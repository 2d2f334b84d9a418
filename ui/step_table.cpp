// The step list table.
#include "ui/step_table.h"

#include "ui/core_texts.h"
#include "ui/number_text.h"

#include "tools/cutting.h"

#include <QHeaderView>

#include <cmath>

namespace taiwa::ui {

namespace {

// What the S and F cells show of a step: the values the tape will carry, in
// the job's units (F per minute, or per revolution on a lathe; S in rpm,
// or m/min under constant surface speed).
struct ShownCutting {
    std::optional<double> speed, feed;
};

ShownCutting shownCutting(const Plan& plan, const Step& s)
{
    ShownCutting c;
    const double toJob = plan.job.lengthUnit == LengthUnit::Inch ? 1.0 / kMillimetresPerInch : 1.0;
    if (s.turn) {
        const TurnCutting& tc = s.turn->cutting;
        c.speed = tc.constantSurfaceSpeed ? tc.surfaceSpeed : tc.rpm;
        c.feed = tc.feedPerRev * toJob;
        return c;
    }
    const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
    if (!t) return c;
    if (const auto sf = stepSpeedsFeeds(s, *t, plan.mmJob.material)) {
        c.speed = sf->rpm;
        c.feed = sf->feed * toJob;
    }
    return c;
}

}  // namespace

StepTable::StepTable(QWidget* parent) : QTableWidget(0, ColumnCount, parent)
{
    setObjectName("steps");
    setHorizontalHeaderLabels(
        {tr("No."), tr("Unit"), tr("Step"), tr("Tool"), tr("S"), tr("F"), tr("Start"), tr("Depth"), tr("Time")});
    horizontalHeaderItem(Speed)->setToolTip(tr("Spindle speed (rpm; m/min under constant surface speed): type to set "
                                               "it for this unit's steps of this kind, empty it for the tool's"));
    horizontalHeaderItem(Feed)->setToolTip(tr("Feed (per minute; per revolution on a lathe): type to set it for this "
                                              "unit's steps of this kind, empty it for the tool's"));
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                    QAbstractItemView::AnyKeyPressed);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    verticalHeader()->hide();
    horizontalHeader()->setStretchLastSection(true);
    connect(this, &QTableWidget::itemChanged, this, &StepTable::onItemChanged);
}

void StepTable::closeEditor(QWidget* editor, QAbstractItemDelegate::EndEditHint hint)
{
    QTableWidget::closeEditor(editor, hint);
    if (!waiting_) return;
    // After the editor's own commit (this call comes after it), on the next turn.
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (!waiting_ || state() == QAbstractItemView::EditingState) return;
            auto plan = std::move(*waiting_);
            waiting_.reset();
            const int row = currentRow();
            const QSignalBlocker quiet(this);  // the same step stays selected: nothing to tell
            setPlan(plan);
            if (row >= 0 && row < rowCount()) selectRow(row);
        },
        Qt::QueuedConnection);
}

void StepTable::setPlan(const std::shared_ptr<const Plan>& plan)
{
    if (state() == QAbstractItemView::EditingState) {
        waiting_ = plan;
        return;
    }
    waiting_.reset();
    filling_ = true;
    plan_ = plan;
    setRowCount(0);
    if (!plan) {
        filling_ = false;
        return;
    }
    const Job& job = plan->job;
    const double toJob = job.lengthUnit == LengthUnit::Inch ? 1.0 / kMillimetresPerInch : 1.0;
    setRowCount(static_cast<int>(plan->steps.size()));
    const auto fixed = [](const QString& text) {
        auto* item = new QTableWidgetItem(text);
        item->setFlags(item->flags() & ~Qt::ItemIsEditable);
        return item;
    };
    for (std::size_t i = 0; i < plan->steps.size(); ++i) {
        const Step& s = plan->steps[i];
        const int r = static_cast<int>(i);
        QString unit = QString::number(s.unit + 1);
        if (s.unit >= 0 && static_cast<std::size_t>(s.unit) < job.units.size() && !job.units[s.unit].name.empty())
            unit += " " + QString::fromStdString(job.units[s.unit].name);
        auto round = [toJob](double mm) { return formatNumber(std::round(mm * toJob * 1e4) / 1e4); };
        setItem(r, No, fixed(QString::number(r + 1)));
        setItem(r, Unit, fixed(unit));
        setItem(r, StepName, fixed(stepLabel(s)));
        // The tool by its number (its name in the tooltip and the step's details): the columns fit.
        auto* tool = fixed(s.tool ? QStringLiteral("T%1").arg(s.tool->toolId) : QStringLiteral("–"));
        if (const Tool* t = s.tool ? plan->tool(s.tool->toolId) : nullptr) tool->setToolTip(QString::fromStdString(t->name));
        setItem(r, ToolName, tool);
        const ShownCutting c = shownCutting(*plan, s);
        const std::pair<Column, std::optional<double>> cells[] = {{Speed, c.speed}, {Feed, c.feed}};
        for (const auto& [column, value] : cells) {
            auto* item = new QTableWidgetItem(value ? formatNumber(std::round(*value * 1e4) / 1e4) : QString());
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            const bool set = column == Speed ? s.cutting.speed.has_value() : s.cutting.feed.has_value();
            if (set) {
                QFont bold = item->font();
                bold.setBold(true);
                item->setFont(bold);
                item->setToolTip(tr("Set for this step kind of the unit; empty the cell for the tool's cutting data"));
            }
            setItem(r, column, item);
        }
        setItem(r, Start, fixed(round(s.startDepth)));
        setItem(r, Depth, fixed(round(s.cutDepth)));
        auto* time = fixed(s.minutes ? clockTime(*s.minutes) : QString());
        time->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(r, Time, time);
    }
    resizeColumnsToContents();
    filling_ = false;
}

void StepTable::onItemChanged(QTableWidgetItem* item)
{
    if (filling_ || !plan_ || (item->column() != Speed && item->column() != Feed)) return;
    const auto row = static_cast<std::size_t>(item->row());
    if (row >= plan_->steps.size()) return;
    const Step& s = plan_->steps[row];
    const QString text = item->text().trimmed();
    std::optional<double> value;
    if (!text.isEmpty()) {
        value = parseNumber(text);
        if (!value || *value <= 0) {
            // Not a number: the cell goes back to what the plan says (once its editor has closed).
            QMetaObject::invokeMethod(this, [this] { setPlan(std::shared_ptr<const Plan>(plan_)); }, Qt::QueuedConnection);
            return;
        }
    }
    // Told once the cell's editor has closed: the edit re-plans, and the new
    // plan refills this table.
    QMetaObject::invokeMethod(
        this,
        [this, unit = s.unit, key = QString::fromLatin1(toKey(s.kind)), speed = item->column() == Speed, value] {
            emit cuttingEdited(unit, key, speed, value);
        },
        Qt::QueuedConnection);
}

QStringList StepTable::stepLabels() const
{
    QStringList out;
    for (int r = 0; r < rowCount(); ++r) out << item(r, StepName)->text();
    return out;
}

}  // namespace taiwa::ui
