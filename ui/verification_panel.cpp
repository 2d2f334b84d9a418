// The station's verification list.
#include "ui/verification_panel.h"

#include <QBrush>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <exception>

namespace taiwa::ui {

namespace {

// The plan verified; a verification that cannot run says why in `skipped`.
verify::Report reportOf(const Plan& plan)
{
    try {
        return verify::verifyPlan(plan);
    } catch (const std::exception& e) {
        verify::Report r;
        r.skipped = e.what();
        return r;
    }
}

}  // namespace

VerificationPanel::VerificationPanel(QWidget* parent)
    : QWidget(parent), run_(new QPushButton(tr("&Verify"), this)), summary_(new QLabel(this)), list_(new QListWidget(this))
{
    pool_.setMaxThreadCount(1);
    run_->setObjectName("verify.run");
    run_->setToolTip(tr("Cut every step into the stock on a %1 mm grid and list gouges, collisions, rapids into "
                        "stock, travel limits and material left")
                         .arg(QLocale().toString(verify::Options{}.resolution)));
    summary_->setObjectName("verify.summary");
    summary_->setWordWrap(true);
    list_->setObjectName("verify.findings");
    list_->setWordWrap(true);
    auto* top = new QHBoxLayout;
    top->addWidget(run_);
    top->addWidget(summary_, 1);
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    box->addLayout(top);
    box->addWidget(list_, 1);
    connect(run_, &QPushButton::clicked, this, &VerificationPanel::verify);
    connect(list_, &QListWidget::currentRowChanged, this, &VerificationPanel::onRowChanged);
    setPlan(nullptr);
}

VerificationPanel::~VerificationPanel() { pool_.waitForDone(); }

void VerificationPanel::setPlan(std::shared_ptr<const Plan> plan)
{
    if (plan && plan == plan_) return;
    plan_ = std::move(plan);
    ++generation_;
    report_ = {};
    list_->clear();
    run_->setEnabled(plan_ && !busy_);
    summary_->setText(plan_ ? tr("Not verified since the last change.") : tr("No plan to verify."));
    summary_->setStyleSheet(QString());
}

void VerificationPanel::verify()
{
    if (!plan_ || busy_) return;
    busy_ = true;
    run_->setEnabled(false);
    summary_->setText(tr("Verifying…"));
    pool_.start([this, generation = generation_, plan = plan_] {
        const verify::Report r = reportOf(*plan);
        QMetaObject::invokeMethod(this, [this, generation, plan, r] { show(generation, plan, r); }, Qt::QueuedConnection);
    });
}

void VerificationPanel::verifyNow()
{
    if (!plan_) return;
    busy_ = true;
    show(generation_, plan_, reportOf(*plan_));
}

void VerificationPanel::show(std::uint64_t generation, std::shared_ptr<const Plan> plan, const verify::Report& r)
{
    busy_ = false;
    run_->setEnabled(plan_ != nullptr);
    if (generation != generation_) return;  // the plan changed meanwhile: that result is for the old one
    report_ = r;
    list_->clear();
    for (const verify::Finding& f : r.findings) {
        auto* item = new QListWidgetItem(QString::fromStdString(verify::describe(f, *plan)), list_);
        if (f.fatal()) item->setForeground(QBrush(QColor(192, 0, 0)));
    }
    if (!r.skipped.empty()) {
        summary_->setText(tr("Not verified: %1").arg(QString::fromStdString(r.skipped)));
    } else {
        int faults = 0;
        for (const auto& f : r.findings) faults += f.fatal() ? 1 : 0;
        const int left = r.count(verify::FindingKind::RestMaterial);
        summary_->setText(faults == 0 && left == 0
                              ? tr("Verified at %1 mm: clean.").arg(QLocale().toString(r.resolution))
                              : tr("Verified at %1 mm: %2 faults, %3 with material left.")
                                    .arg(QLocale().toString(r.resolution))
                                    .arg(faults)
                                    .arg(left));
        summary_->setStyleSheet(faults > 0 ? "color: #c00000; font-weight: bold;" : "");
    }
    emit verified();
}

void VerificationPanel::onRowChanged(int row)
{
    if (row < 0 || row >= static_cast<int>(report_.findings.size())) return;
    const verify::Finding& f = report_.findings[static_cast<std::size_t>(row)];
    emit findingSelected(f.step, f.move, f.position);
}

}  // namespace taiwa::ui
