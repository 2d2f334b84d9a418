// The step panel: step list, step numbers, play timer and view buttons.
#include "ui/step_panel.h"
#include "ui/core_messages.h"

#include "ui/number_text.h"
#include "ui/core_texts.h"
#include "ui/step_table.h"

#include "modules/inclined_face.h"

#include <QEvent>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QToolButton>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {
namespace {

QString length(double mm, LengthUnit u)
{
    return formatNumber(std::round(fromMm(mm, u) * 1e4) / 1e4) + " " + unitSymbol(u);
}

}  // namespace

StepPanel::StepPanel(QWidget* parent)
    : QWidget(parent), table_(new StepTable(this)), details_(new QLabel(this)), play_(new QToolButton(this)),
      stock_(new QCheckBox(this)), before_(new QCheckBox(this)), paths_(new QCheckBox(this)),
      timer_(new QTimer(this)), speed_(new QSpinBox(this))
{
    details_->setObjectName("step.details");
    details_->setWordWrap(true);
    details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    details_->setMinimumHeight(details_->fontMetrics().lineSpacing() * 3);
    details_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    play_->setObjectName("step.play");
    play_->setCheckable(true);
    stock_->setObjectName("view.stock");
    stock_->setChecked(true);
    before_->setObjectName("view.before");
    paths_->setObjectName("view.paths");
    paths_->setChecked(true);
    timer_->setInterval(1200);

    auto* buttons = new QHBoxLayout;
    // Tool buttons (as wide as their text) so that the row fits beside the
    // unit form at the window's smallest useful width.
    auto* all = new QToolButton(this);
    all->setObjectName("step.all");
    buttons->addWidget(all);
    buttons->addWidget(play_);
    buttons->addStretch(1);
    const char* const views[] = {"view.iso", "view.top", "view.front"};
    for (int i = 0; i < 3; ++i) {
        auto* b = new QToolButton(this);
        b->setObjectName(views[i]);
        connect(b, &QToolButton::clicked, this, [this, i] { emit viewRequested(static_cast<ViewButton>(i)); });
        buttons->addWidget(b);
    }
    // The stock switches on a row of their own: the panel stays narrow.
    auto* switches = new QHBoxLayout;
    switches->addWidget(stock_);
    switches->addWidget(before_);
    // The view's own switches, placed by the station beside the section bar.
    viewBar_ = new QWidget(this);
    viewBar_->setObjectName("view.bar");
    viewBar_->hide();  // until placed
    auto* bar = new QHBoxLayout(viewBar_);
    bar->setContentsMargins(0, 0, 0, 0);
    zoom_ = new QToolButton(viewBar_);
    zoom_->setObjectName("view.step");
    connect(zoom_, &QToolButton::clicked, this, [this] { emit viewRequested(ViewButton::Step); });
    paths_->setParent(viewBar_);
    bar->addWidget(paths_);
    bar->addWidget(zoom_);
    switches->addStretch(1);
    // Single blocks and the blocks a tick of Play moves on.
    auto* back = new QToolButton(this);
    back->setText(QStringLiteral("◀"));
    back->setObjectName("step.blockBack");
    auto* forward = new QToolButton(this);
    forward->setText(QStringLiteral("▶|"));
    forward->setObjectName("step.blockForward");
    speed_->setObjectName("step.speed");
    speed_->setRange(1, 1000);
    speed_->setValue(1);
    speed_->setPrefix(QStringLiteral("×"));
    nameParts();
    switches->addWidget(back);
    switches->addWidget(forward);
    switches->addWidget(speed_);
    connect(back, &QToolButton::clicked, this, [this] { stepBlock(-1); });
    connect(forward, &QToolButton::clicked, this, [this] { stepBlock(1); });

    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    box->addWidget(table_, 1);
    box->addWidget(details_);
    box->addLayout(buttons);
    box->addLayout(switches);

    connect(table_, &QTableWidget::itemSelectionChanged, this, &StepPanel::onSelectionChanged);
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] { emit stepChosen(selectedStep()); });
    connect(all, &QToolButton::clicked, this, [this] { selectStep(-1); });
    connect(play_, &QToolButton::toggled, this, &StepPanel::setPlaying);
    connect(timer_, &QTimer::timeout, this, &StepPanel::advance);
    connect(stock_, &QCheckBox::toggled, this, &StepPanel::showStockToggled);
    connect(stock_, &QCheckBox::toggled, before_, &QWidget::setEnabled);
    connect(before_, &QCheckBox::toggled, this, &StepPanel::stockBeforeToggled);
    connect(paths_, &QCheckBox::toggled, this, &StepPanel::showPathsToggled);
}

namespace {

// Step k of `before` in `after`: the same unit (equal, else at the same
// index) and the same step of it (its label, the n-th of that label); -1: gone.
int sameStep(const Plan* before, int k, const Plan* after)
{
    if (!before || !after || k < 0 || k >= static_cast<int>(before->steps.size())) return k;
    const Step& s = before->steps[static_cast<std::size_t>(k)];
    const auto unitOf = [](const Plan& p, const Step& t) -> const MachiningUnit* {
        return t.unit >= 0 && t.unit < static_cast<int>(p.job.units.size()) ? &p.job.units[static_cast<std::size_t>(t.unit)] : nullptr;
    };
    const MachiningUnit* unit = unitOf(*before, s);
    const std::string label = s.label();
    int nth = 0;
    for (int i = 0; i < k; ++i)
        nth += before->steps[static_cast<std::size_t>(i)].unit == s.unit && before->steps[static_cast<std::size_t>(i)].label() == label;
    for (const bool byValue : {true, false}) {
        int seen = 0;
        for (std::size_t i = 0; i < after->steps.size(); ++i) {
            const Step& t = after->steps[i];
            const MachiningUnit* u = unitOf(*after, t);
            const bool sameUnit = byValue ? unit && u && *u == *unit : t.unit == s.unit;
            if (sameUnit && t.label() == label && seen++ == nth) return static_cast<int>(i);
        }
    }
    return -1;
}

}  // namespace

void StepPanel::setPlan(const std::shared_ptr<const Plan>& plan)
{
    const int keep = sameStep(plan_.get(), selectedStep(), plan.get());
    plan_ = plan;
    if (table_->editing()) {
        table_->setPlan(plan);  // waits for the cell being typed into; the selection stays
        return;
    }
    {
        const QSignalBlocker block(table_);
        table_->setPlan(plan);
        if (keep >= 0 && keep < table_->rowCount()) table_->selectRow(keep);
        else table_->clearSelection();
    }
    if (!plan || table_->rowCount() == 0) setPlaying(false);
    lastEmitted_ = -2;  // a new plan: tell the preview again
    onSelectionChanged();
}

int StepPanel::selectedStep() const
{
    const auto rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : rows.first().row();
}

void StepPanel::selectStep(int index)
{
    if (index < 0 || index >= table_->rowCount()) table_->clearSelection();
    else table_->selectRow(index);
    onSelectionChanged();
}

bool StepPanel::stockShown() const { return stock_->isChecked(); }

bool StepPanel::stockBefore() const { return before_->isChecked(); }

bool StepPanel::pathsShown() const { return paths_->isChecked(); }

void StepPanel::setStockShown(bool on) { stock_->setChecked(on); }

void StepPanel::setPathsShown(bool on) { paths_->setChecked(on); }

bool StepPanel::isPlaying() const { return timer_->isActive(); }

void StepPanel::setPlaying(bool on)
{
    on = on && table_->rowCount() > 0;
    if (on == isPlaying()) {
        const QSignalBlocker block(play_);
        play_->setChecked(on);
        return;
    }
    if (on) {
        // A step selected (with a path): its blocks from where they stand;
        // none: every step in turn from the first.
        const int k = selectedStep();
        if (k >= 0 && moveCount(k) > 0) {
            if (playStep_ != k || playMove_ >= moveCount(k) - 1) setPlayhead(k, -1);
            timer_->start(kBlockInterval);
        } else {
            selectStep(0);
            timer_->start(stepInterval_);
        }
    } else {
        timer_->stop();
    }
    const QSignalBlocker block(play_);
    play_->setChecked(on);
    play_->setText(on ? tr("■ Stop (&Y)") : tr("▶ Pla&y"));
}

void StepPanel::setPlayInterval(int ms)
{
    stepInterval_ = ms;
    if (playStep_ < 0) timer_->setInterval(ms);
}

void StepPanel::setBlocksPerTick(int n) { speed_->setValue(n); }

int StepPanel::moveCount(int step) const
{
    if (!plan_ || step < 0 || step >= static_cast<int>(plan_->steps.size())) return 0;
    const Step& s = plan_->steps[static_cast<std::size_t>(step)];
    return s.path ? static_cast<int>(s.path->moves.size()) : 0;
}

void StepPanel::setPlayhead(int step, int move)
{
    playStep_ = step;
    playMove_ = move;
    emit playheadMoved(step, move);
}

void StepPanel::stepBlock(int delta)
{
    const int k = playStep_ >= 0 ? playStep_ : selectedStep();
    if (k < 0 || moveCount(k) == 0) return;
    const int from = playStep_ == k ? playMove_ : -1;
    setPlayhead(k, std::clamp(from + delta, -1, moveCount(k) - 1));
}

void StepPanel::advance()
{
    if (playStep_ >= 0) {
        // Blocks: on by the speed; past the step's last, the next step's
        // first (a step without a path passed over); after the last, stop.
        int k = playStep_, move = playMove_ + speed_->value();
        while (k >= 0 && move >= moveCount(k)) {
            if (playMove_ < moveCount(k) - 1) {
                move = moveCount(k) - 1;  // show the step's last block before going on
                break;
            }
            do ++k;
            while (k < table_->rowCount() && moveCount(k) == 0);
            if (k >= table_->rowCount()) {
                setPlaying(false);
                return;
            }
            move = 0;
            advancing_ = true;
            selectStep(k);
            advancing_ = false;
        }
        setPlayhead(k, move);
        return;
    }
    const int next = selectedStep() + 1;
    if (next >= table_->rowCount()) {
        setPlaying(false);
        selectStep(-1);
        return;
    }
    selectStep(next);
}

void StepPanel::nameParts()
{
    play_->setText(play_->isChecked() ? tr("■ Stop (&Y)") : tr("▶ Pla&y"));
    stock_->setText(tr("&Stock"));
    stock_->setToolTip(tr("The stock as the simulation cuts it, instead of a glass block"));
    before_->setText(tr("&Before step"));
    before_->setToolTip(tr("The stock as it is before the selected step, instead of after it"));
    findChild<QToolButton*>("step.all")->setText(tr("&All steps"));
    findChild<QToolButton*>("view.iso")->setText(tr("&Iso"));
    findChild<QToolButton*>("view.top")->setText(tr("&Top"));
    findChild<QToolButton*>("view.front")->setText(tr("F&ront"));
    zoom_->setText(tr("&Zoom to step"));
    zoom_->setToolTip(tr("Zoom to the selected step, the view turned as it is (all steps: the whole job)"));
    paths_->setText(tr("Pat&hs"));
    paths_->setToolTip(tr("The tool paths drawn; off, the stock and the colour map show unhidden"));
    findChild<QToolButton*>("step.blockBack")->setToolTip(tr("One block back in the selected step"));
    findChild<QToolButton*>("step.blockForward")->setToolTip(tr("One block on in the selected step, the material coming off"));
    speed_->setToolTip(tr("How many blocks Play moves on ten times a second with a step selected"));
}

void StepPanel::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange) return;
    nameParts();
    showDetails(selectedStep());
}

void StepPanel::onSelectionChanged()
{
    const int index = selectedStep();
    // Another step chosen (not by the play itself): the blocks played end.
    if (playStep_ >= 0 && !advancing_ && index != playStep_) {
        timer_->stop();
        const QSignalBlocker block(play_);
        play_->setChecked(false);
        play_->setText(tr("▶ Pla&y"));
        setPlayhead(-1, -1);
    }
    showDetails(index);
    if (index == lastEmitted_) return;
    lastEmitted_ = index;
    emit stepSelected(index);
}

void StepPanel::showDetails(int index)
{
    if (!plan_ || index < 0 || index >= static_cast<int>(plan_->steps.size())) {
        if (!plan_) {
            details_->setText(tr("No steps: the job has input errors."));
        } else if (!plan_->steps.empty() && !plan_->steps.front().minutes) {
            // The step list comes before the times: keep the last ones until the new arrive.
            details_->setText(tr("%n step(s), %1 min, %2 tool change(s) (updating…)", "",
                                 static_cast<int>(plan_->steps.size()))
                                  .arg(lastMinutes_ ? QString::number(*lastMinutes_, 'f', 1) : QStringLiteral("…"))
                                  .arg(plan_->toolChanges));
        } else {
            lastMinutes_ = plan_->totalMinutes;
            details_->setText(tr("%n step(s), %1 min, %2 tool change(s)", "", static_cast<int>(plan_->steps.size()))
                                  .arg(QString::number(plan_->totalMinutes, 'f', 1))
                                  .arg(plan_->toolChanges));
        }
        return;
    }
    const Step& s = plan_->steps[static_cast<std::size_t>(index)];
    const MillingGeometry& g = millingOf(s);
    const LengthUnit u = plan_->job.lengthUnit;
    QStringList lines;
    lines << tr("<b>%1</b> of unit %2 (%3), machining type %4")
                 .arg(stepLabel(s))
                 .arg(s.unit + 1)
                 .arg(QString::fromStdString(s.module))
                 .arg(static_cast<int>(s.machiningType));
    lines << tr("Air to %1, cuts to %2; leaves wall %3, floor %4")
                 .arg(length(g.startDepth, u), length(g.cutDepth, u), length(g.wallAllowance, u),
                      length(g.floorAllowance, u));
    if (g.outline) {
        QStringList pts;
        for (const Point2& p : g.outline->corners)
            pts << QStringLiteral("(%1, %2)").arg(formatNumber(std::round(fromMm(p.x, u) * 1e4) / 1e4),
                                                  formatNumber(std::round(fromMm(p.y, u) * 1e4) / 1e4));
        lines << tr("Outline %1, r %2").arg(pts.join(' '), length(g.outline->cornerRadius, u));
    } else if (const InclinedFace* face = s.payload.getIf<InclinedFace>()) {
        lines << tr("Inclined face at %1° from the vertical, scallop %2")
                     .arg(formatNumber(face->angle), length(face->scallop, u));
    } else {
        lines << tr("At (%1, %2), Ø %3")
                     .arg(formatNumber(std::round(fromMm(g.position.x, u) * 1e4) / 1e4),
                          formatNumber(std::round(fromMm(g.position.y, u) * 1e4) / 1e4), length(g.holeDiameter, u));
    }
    if (g.wallTaper > 0) lines << tr("Wall taper %1° per side").arg(formatNumber(g.wallTaper));
    if (s.tool) {
        const Tool* t = plan_->tool(s.tool->toolId);
        knowToolNames(plan_->tools);  // a name the reason quotes, in the station's language
        lines << tr("T%1 %2: %3")
                     .arg(s.tool->toolId)
                     .arg(t ? localToolName(*t) : QString())
                     .arg(coreMessage(s.tool->reason));
    }
    if (s.minutes && s.machineMinutes)
        lines << tr("Estimated %1 min (%2 min as the machine moves)")
                     .arg(QString::number(*s.minutes, 'f', 2), QString::number(*s.machineMinutes, 'f', 2));
    else if (s.minutes)
        lines << tr("Estimated %1 min").arg(QString::number(*s.minutes, 'f', 2));
    details_->setText(lines.join("<br>"));
}

}  // namespace taiwa::ui
