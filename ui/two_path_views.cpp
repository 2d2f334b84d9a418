// The station's two-path views (two_path_views.h).
#include "ui/two_path_views.h"

#include "ui/core_messages.h"
#include "ui/core_texts.h"
#include "ui/nc_view.h"
#include "ui/number_text.h"
#include "ui/two_path_chart.h"

#include <QComboBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>

#include <algorithm>

namespace taiwa::ui {

TwoPathSteps::TwoPathSteps(QWidget* parent) : QTreeWidget(parent)
{
    setColumnCount(ColumnCount);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setRootIsDecorated(true);
    header()->setStretchLastSection(false);
    header()->setSectionResizeMode(StepName, QHeaderView::Stretch);
    nameColumns();
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (filling_ || !item) return;
        if (const int block = item->data(0, kBlockRole).toInt()) emit blockChosen(block);
        else if (item->data(0, kStepRole).isValid()) emit stepChosen(item->data(0, kStepRole).toInt());
    });
}

void TwoPathSteps::nameColumns() { setHeaderLabels({tr("Path, step"), tr("Tool"), tr("Time")}); }

void TwoPathSteps::changeEvent(QEvent* e)
{
    QTreeWidget::changeEvent(e);
    if (e->type() == QEvent::LanguageChange) nameColumns();
}

void TwoPathSteps::setShown(const Plan& plan, const TwoPathShown& shown)
{
    filling_ = true;
    clear();
    const bool balanced = shown.balanced.cut && *shown.balanced.cut && shown.balanced.timeline;
    // The tool by its number, its name in the tooltip (as the step list has it).
    const auto tool = [&](const Step& s) { return s.tool ? QStringLiteral("T%1").arg(s.tool->toolId) : QStringLiteral("–"); };
    for (std::size_t p = 0; p < shown.pathNames.size(); ++p) {
        QStringList tools;
        for (int t : shown.tools[p]) tools << QStringLiteral("T%1").arg(t);
        auto* path = new QTreeWidgetItem(this, QStringList{tr("Path %1 (%2): turret with %3")
                                                    .arg(p + 1)
                                                    .arg(localPathName(shown.pathNames[p]))
                                                    .arg(tools.isEmpty() ? tr("no tool") : tools.join(", "))});
        path->setFirstColumnSpanned(true);
        QFont bold = path->font(0);
        bold.setBold(true);
        path->setFont(0, bold);
        for (std::size_t k = 0; k < plan.steps.size(); ++k) {
            const bool rough = k == shown.balanced.step;
            if (p > 0 && !(rough && balanced)) continue;  // the other paths run the balanced roughing only
            const Step& s = plan.steps[k];
            QString time = s.minutes ? clockTime(*s.minutes) : QString();
            QString name = stepLabel(s);
            std::vector<const TimelineBlock*> blocks;
            if (rough && balanced) {
                for (const TimelineBlock& b : shown.balanced.timeline->blocks)
                    if (b.path == p && b.number > 0) blocks.push_back(&b);
                QStringList numbers;
                for (const auto* b : blocks) numbers << QStringLiteral("CB%1").arg(b->number);
                name = tr("%1, balanced: %2").arg(name, numbers.join(", "));
                // The path's part of the roughing on the timeline: from its first block to its last.
                time = blocks.empty() ? QString() : clockTime((blocks.back()->end - blocks.front()->start) / 60.0);
            }
            auto* row = new QTreeWidgetItem(path, QStringList{name, tool(s), time});
            if (const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr) row->setToolTip(ToolName, localToolName(*t));
            row->setData(0, kStepRole, static_cast<int>(k));
            row->setTextAlignment(Time, Qt::AlignRight | Qt::AlignVCenter);
            for (const TimelineBlock* b : blocks) {
                QString what = tr("CB%1: cut %2–%3 s").arg(b->number).arg(b->cutStart, 0, 'f', 2).arg(b->cutEnd, 0, 'f', 2);
                if (b->wait) what += ", " + tr("wait M%1").arg(*b->wait);
                if (b->dwell > 0) what += ", " + tr("dwell %1 s").arg(b->dwell, 0, 'f', 3);
                auto* block = new QTreeWidgetItem(row, QStringList{what, QString(), clockTime((b->end - b->start) / 60.0)});
                block->setData(0, kStepRole, static_cast<int>(k));
                block->setData(0, kBlockRole, b->number);
                block->setTextAlignment(Time, Qt::AlignRight | Qt::AlignVCenter);
            }
        }
    }
    expandAll();
    resizeColumnToContents(ToolName);
    resizeColumnToContents(Time);
    filling_ = false;
}

void TwoPathSteps::selectBlock(int block)
{
    filling_ = true;
    QTreeWidgetItem* found = nullptr;
    for (QTreeWidgetItemIterator it(this); *it && !found; ++it)
        if ((*it)->data(0, kBlockRole).toInt() == block && block > 0) found = *it;
    if (found) {
        setCurrentItem(found);
        scrollToItem(found);
    } else {
        clearSelection();
    }
    filling_ = false;
}

TwoPathViews::TwoPathViews(QObject* parent)
    : QObject(parent), steps_(new TwoPathSteps), chart_(new TwoPathChart), tape_(new NcView)
{
    steps_->setObjectName("paths.steps");
    chart_->setObjectName("paths.chart");
    tape_->setObjectName("paths.tape");
    // Path 2's tape is in the dialect chosen above path 1's.
    tape_->findChild<QComboBox*>("nc.dialect")->hide();
    tape_->findChild<QLabel*>("nc.label")->hide();
    // Its parts named as path 2's: "nc", "nc.dialect", ... are path 1's
    // tape (the window's look-ups and the tests find that one).
    for (QObject* part : tape_->findChildren<QObject*>())
        if (part->objectName().startsWith("nc")) part->setObjectName("paths.tape." + part->objectName());
    connect(steps_, &TwoPathSteps::blockChosen, this, &TwoPathViews::chooseBlock);
    connect(chart_, &TwoPathChart::blockClicked, this, &TwoPathViews::chooseBlock);
}

TwoPathViews::~TwoPathViews()
{
    // The widgets are the window's once placed; those never placed are ours.
    for (QWidget* w : std::initializer_list<QWidget*>{steps_, chart_, tape_})
        if (!w->parent()) delete w;
}

const PostedProgram* TwoPathViews::setPlan(const Plan& plan, const QString& dialect, const QString& stem)
{
    shown_ = twoPathShown(plan, dialect.toStdString(), stem.toStdString());
    if (!shown_) return nullptr;
    steps_->setShown(plan, *shown_);
    const auto& cut = shown_->balanced.cut;
    chart_->setTimeline(shown_->balanced.timeline, shown_->pathNames,
                        cut && *cut ? (**cut).paths.front().endWait : std::nullopt);
    tape_->setDialect(dialect);
    if (shown_->programs.size() > 1) {
        tape_->setProgram(QString::fromStdString(shown_->programs[1].nc), shown_->programs[1].lines);
        return &shown_->programs[0];
    }
    tape_->setMessage(!shown_->error.isEmpty() ? shown_->error
                                               : tr("No roughing step to balance between the paths: path 2 has no program."));
    return nullptr;
}

void TwoPathViews::chooseBlock(int block)
{
    if (!shown_) return;
    chart_->selectBlock(block);
    steps_->selectBlock(block);
    const int move = shown_->cutMoveOf(block);
    if (move < 0) return;
    const auto on = shown_->blockOfMove(static_cast<int>(shown_->balanced.step), move);
    if (on && on->first > 0) tape_->selectMove(static_cast<int>(shown_->balanced.step), move);
    emit blockChosen(static_cast<int>(shown_->balanced.step), move, on ? static_cast<int>(on->first) : 0);
}

void TwoPathViews::followMove(int step, int move)
{
    if (!shown_) return;
    const auto on = shown_->blockOfMove(step, move);
    const int block = on ? on->second : 0;
    chart_->selectBlock(block);
    steps_->selectBlock(block);
    if (on && on->first > 0) tape_->selectMove(step, move);
}

}  // namespace taiwa::ui
