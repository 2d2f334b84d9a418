// The step list table.
#include "ui/step_table.h"

#include "ui/core_messages.h"
#include "ui/core_texts.h"
#include "ui/number_text.h"
#include "model/turn_path.h"


#include <QEvent>
#include <QHeaderView>
#include <QScrollBar>
#include <QStyle>

#include <algorithm>
#include <array>
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
    if (turnOf(s)) {
        const TurnCutting& tc = turnOf(s)->cutting;
        c.speed = tc.constantSurfaceSpeed ? tc.surfaceSpeed : tc.rpm;
        c.feed = tc.feedPerRev * toJob;
        return c;
    }
    if (const auto& sf = s.speeds) {
        c.speed = sf->rpm;
        c.feed = sf->feed * toJob;
    }
    return c;
}

}  // namespace

StepTable::StepTable(QWidget* parent) : QTableWidget(0, ColumnCount, parent)
{
    setObjectName("steps");
    nameColumns();
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                    QAbstractItemView::AnyKeyPressed);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    verticalHeader()->hide();
    horizontalHeader()->setStretchLastSection(true);
    connect(this, &QTableWidget::itemChanged, this, &StepTable::onItemChanged);
}

void StepTable::nameColumns()
{
    setHorizontalHeaderLabels(
        {tr("No."), tr("Unit"), tr("Step"), tr("Tool"), tr("S"), tr("F"), tr("Start"), tr("Depth"), tr("Time")});
    horizontalHeaderItem(Speed)->setToolTip(tr("Spindle speed (rpm; m/min under constant surface speed): type to set "
                                               "it for this unit's steps of this kind, empty it for the tool's"));
    horizontalHeaderItem(Feed)->setToolTip(tr("Feed (per minute; per revolution on a lathe): type to set it for this "
                                              "unit's steps of this kind, empty it for the tool's"));
}

void StepTable::changeEvent(QEvent* e)
{
    QTableWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange) return;
    nameColumns();
    if (plan_ && !editing()) setPlan(std::shared_ptr<const Plan>(plan_));  // the steps' names and tips in the new language
    resizeColumnsToContents();
    fitColumns();
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
    if (!plan) {
        setRowCount(0);
        filling_ = false;
        return;
    }
    // The rows stay and only cells whose text, bold or tooltip changed are
    // set (an edit changes a few: 600 rows made anew took tens of ms); only
    // the columns that changed are fitted to their contents again.
    const Job& job = plan->job;
    const double toJob = job.lengthUnit == LengthUnit::Inch ? 1.0 / kMillimetresPerInch : 1.0;
    const int rows = static_cast<int>(plan->steps.size());
    const bool newRows = rows != rowCount();
    setRowCount(rows);
    std::array<bool, ColumnCount> changed{};
    const auto cell = [&](int r, Column c, const QString& text, const QString& tip = {}, bool bold = false) {
        QTableWidgetItem* it = item(r, c);
        if (!it) {
            it = new QTableWidgetItem(text);
            if (c != Speed && c != Feed) it->setFlags(it->flags() & ~Qt::ItemIsEditable);
            if (c == Speed || c == Feed || c == Time) it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(r, c, it);
            changed[c] = true;
        } else if (it->text() != text) {
            it->setText(text);
            changed[c] = true;
        }
        if (it->toolTip() != tip) it->setToolTip(tip);
        if (it->font().bold() != bold) {
            QFont f = it->font();
            f.setBold(bold);
            it->setFont(f);
            changed[c] = true;
        }
    };
    const QString cuttingTip = tr("Set for this step kind of the unit; empty the cell for the tool's cutting data");
    for (int r = 0; r < rows; ++r) {
        const Step& s = plan->steps[static_cast<std::size_t>(r)];
        QString unit = QString::number(s.unit + 1);
        if (s.unit >= 0 && static_cast<std::size_t>(s.unit) < job.units.size() && !job.units[s.unit].name.empty())
            unit += " " + QString::fromStdString(job.units[s.unit].name);
        auto round = [toJob](double mm) { return formatNumber(std::round(mm * toJob * 1e4) / 1e4); };
        cell(r, No, QString::number(r + 1));
        cell(r, Unit, unit);
        cell(r, StepName, stepLabel(s));
        // The tool by its number (its name in the tooltip and the step's details): the columns fit.
        const Tool* t = s.tool ? plan->tool(s.tool->toolId) : nullptr;
        cell(r, ToolName, s.tool ? QStringLiteral("T%1").arg(s.tool->toolId) : QStringLiteral("–"),
             t ? localToolName(*t) : QString());
        const ShownCutting c = shownCutting(*plan, s);
        const std::pair<Column, std::optional<double>> cuttings[] = {{Speed, c.speed}, {Feed, c.feed}};
        for (const auto& [column, value] : cuttings) {
            const bool set = column == Speed ? s.cutting.speed.has_value() : s.cutting.feed.has_value();
            cell(r, column, value ? formatNumber(std::round(*value * 1e4) / 1e4) : QString(), set ? cuttingTip : QString(), set);
        }
        if (turnOf(s)) {
            // A turned step has no start depth below a top face; its depth is
            // the depth of cut of a pass (a thread's: the thread's), on the radius.
            const double cut = turnOf(s)->thread ? turnOf(s)->thread->depth : turnOf(s)->depthOfCut;
            cell(r, Start, QStringLiteral("–"));
            cell(r, Depth, cut > 0 ? round(cut) : QStringLiteral("–"), cut > 0 ? tr("Depth of cut on the radius: of a pass; of a thread, the whole thread") : QString());
        } else {
            cell(r, Start, round(millingOf(s).startDepth));
            cell(r, Depth, round(millingOf(s).cutDepth));
        }
        cell(r, Time, s.minutes ? clockTime(*s.minutes) : QString());
    }
    if (newRows) resizeColumnsToContents();
    else
        for (int c = 0; c < ColumnCount; ++c)
            if (changed[static_cast<std::size_t>(c)]) resizeColumnToContents(c);
    fitColumns();
    updateGeometries();  // the scroll bars for the new widths now (a table made anew got them from its reset)
    filling_ = false;
}

void StepTable::resizeEvent(QResizeEvent* event)
{
    QTableWidget::resizeEvent(event);
    fitColumns();
}

void StepTable::fitColumns()
{
    // A shown column is fitted to its contents already; a hidden one and the
    // last (stretched) are measured.
    const auto wanted = [this](int c) {
        return isColumnHidden(c) || c == Time ? std::max(sizeHintForColumn(c), horizontalHeader()->sectionSizeHint(c)) : columnWidth(c);
    };
    int total = 0;
    for (int c = 0; c < ColumnCount; ++c) total += wanted(c);
    // The vertical scroll bar that more rows bring takes its width too.
    const int room = viewport()->width() - (verticalScrollBar()->isVisible() ? 0 : style()->pixelMetric(QStyle::PM_ScrollBarExtent));
    for (const Column c : {Start, Depth, Unit}) {
        const bool hide = total > room;
        const int width = wanted(c);
        if (hide) total -= width;
        if (isColumnHidden(c) == hide) continue;
        setColumnHidden(c, hide);
        if (!hide) setColumnWidth(c, width);
    }
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
