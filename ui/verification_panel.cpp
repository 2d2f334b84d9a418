// The station's verification list.
#include "ui/verification_panel.h"
#include "ui/core_messages.h"

#include "export/verification_cache.h"

#include "viz/palette.h"

#include <QBrush>
#include <QCheckBox>
#include <QEvent>
#include <QColor>
#include <QLocale>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <exception>

namespace taiwa::ui {

namespace {

// The plan verified; a verification that cannot run says why in `skipped`.
verify::Report reportOf(const Plan& plan)
{
    try {
        verify::Options o;
        o.resolution = verify::defaultResolution(plan);
        o.maxCellVisits = verify::kDefaultCellVisits;  // minutes of paths verified on a coarser grid, not minutes waited
        // Run here for the colour map (the cache keeps no height field), and
        // stored: the export that follows finds it (export/verification_cache.h).
        verify::Report r = verify::verifyPlan(plan, o);
        (void)storeVerification(verificationKey(plan, o), r);
        return r;
    } catch (const std::exception& e) {
        verify::Report r;
        r.skipped = e.what();
        return r;
    }
}

// The report's colour map, when it has a stock to colour.
std::shared_ptr<const verify::DeviationMap> mapOf(const Plan& plan, const verify::Report& r)
{
    if (!r.skipped.empty()) return nullptr;
    auto map = std::make_shared<const verify::DeviationMap>(verify::deviationMap(plan, r));
    return map->empty() ? nullptr : map;
}

// A swatch of the colour map's legend.
QString swatch(viz::Rgb c, const QString& text)
{
    return QStringLiteral("<span style=\"background-color: %1;\">&nbsp;&nbsp;&nbsp;</span>&nbsp;%2")
        .arg(QColor(c.r, c.g, c.b).name(), text.toHtmlEscaped());
}

}  // namespace

VerificationPanel::VerificationPanel(QWidget* parent)
    : QWidget(parent), run_(new QPushButton(this)), summary_(new QLabel(this)), list_(new QListWidget(this)),
      colourMap_(new QCheckBox(this)), legend_(new QLabel(this))
{
    pool_.setMaxThreadCount(1);
    run_->setObjectName("verify.run");
    summary_->setObjectName("verify.summary");
    summary_->setWordWrap(true);
    list_->setObjectName("verify.findings");
    list_->setWordWrap(true);
    colourMap_->setObjectName("verify.colourMap");
    legend_->setObjectName("verify.legend");
    legend_->setWordWrap(true);
    legend_->setTextFormat(Qt::RichText);
    legend_->hide();
    nameParts();
    // The summary on a line of its own under the buttons: beside them, at
    // 1366 px, a Japanese sentence had a column a few characters wide.
    auto* top = new QHBoxLayout;
    top->addWidget(run_);
    top->addStretch(1);
    top->addWidget(colourMap_);
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    box->addLayout(top);
    box->addWidget(summary_);
    box->addWidget(legend_);
    box->addWidget(list_, 1);
    connect(run_, &QPushButton::clicked, this, &VerificationPanel::verify);
    connect(colourMap_, &QCheckBox::toggled, this, &VerificationPanel::showColourMap);
    connect(list_, &QListWidget::currentRowChanged, this, &VerificationPanel::onRowChanged);
    setPlan(nullptr);
}

VerificationPanel::~VerificationPanel() { pool_.waitForDone(); }

void VerificationPanel::nameParts()
{
    run_->setText(tr("&Verify"));
    run_->setToolTip(tr("Cut every step into the stock on a %1 mm grid and list gouges, collisions, rapids into "
                        "stock, travel limits and material left")
                         .arg(QLocale().toString(verify::Options{}.resolution)));
    colourMap_->setText(tr("Colour &map"));
    colourMap_->setToolTip(tr("Show the finished part in the 3-D view coloured by what the verification found"));
    const QString mm = QLocale().toString(verify::kThinRest), mm2 = QLocale().toString(verify::kMediumRest);
    legend_->setText(QStringList{swatch(viz::palette::kGouge, tr("gouge")), swatch(viz::palette::kAtSize, tr("at size")),
                                 swatch(viz::palette::kRestThin, tr("up to %1 mm left").arg(mm)),
                                 swatch(viz::palette::kRestMedium, tr("up to %1 mm left").arg(mm2)),
                                 swatch(viz::palette::kRestThick, tr("more left"))}
                         .join(QStringLiteral(" &nbsp; ")));
}

void VerificationPanel::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange) return;
    nameParts();
    const int row = list_->currentRow();
    const QSignalBlocker quiet(list_);  // the same finding chosen again: nothing to announce
    showReport();
    list_->setCurrentRow(row);
}

void VerificationPanel::setPlan(std::shared_ptr<const Plan> plan)
{
    if (plan && plan == plan_) return;
    plan_ = std::move(plan);
    ++generation_;
    report_ = {};
    map_ = nullptr;
    colourMap_->setEnabled(false);
    showColourMap();
    reported_ = false;
    verifying_ = false;
    run_->setEnabled(plan_ && !busy_);
    showReport();
}

void VerificationPanel::verify()
{
    if (!plan_ || busy_) return;
    busy_ = true;
    verifying_ = true;
    run_->setEnabled(false);
    showReport();
    pool_.start([this, generation = generation_, plan = plan_] {
        auto r = std::make_shared<verify::Report>(reportOf(*plan));
        auto map = mapOf(*plan, *r);
        r->stock = {};  // the map keeps what is drawn of it
        QMetaObject::invokeMethod(
            this, [this, generation, r, map] { show(generation, *r, map); }, Qt::QueuedConnection);
    });
}

void VerificationPanel::verifyNow()
{
    if (!plan_) return;
    busy_ = true;
    verify::Report r = reportOf(*plan_);
    auto map = mapOf(*plan_, r);
    r.stock = {};
    show(generation_, r, map);
}

void VerificationPanel::show(std::uint64_t generation, const verify::Report& r, std::shared_ptr<const verify::DeviationMap> map)
{
    busy_ = false;
    run_->setEnabled(plan_ != nullptr);
    if (generation != generation_) return;  // the plan changed meanwhile: that result is for the old one
    report_ = r;
    reported_ = true;
    verifying_ = false;
    map_ = std::move(map);
    colourMap_->setEnabled(map_ != nullptr);
    showColourMap();
    showReport();
    emit verified();
}

void VerificationPanel::showReport()
{
    list_->clear();
    summary_->setStyleSheet(QString());
    if (!reported_) {
        summary_->setText(verifying_ ? tr("Verifying…") : plan_ ? tr("Not verified since the last change.") : tr("No plan to verify."));
        return;
    }
    const verify::Report& r = report_;
    for (const verify::Finding& f : r.findings) {
        auto* item = new QListWidgetItem(coreMessage(verify::describe(f, *plan_)), list_);
        if (f.fatal()) item->setForeground(QBrush(QColor(192, 0, 0)));
    }
    if (!r.skipped.empty()) {
        summary_->setText(tr("Not verified: %1").arg(coreMessage(r.skipped)));
        return;
    }
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
    if (!r.coarsened.empty()) summary_->setText(summary_->text() + "\n" + coreMessage(r.coarsened));
}

void VerificationPanel::showColourMap()
{
    const bool on = colourMap_->isChecked() && map_;
    legend_->setVisible(on);
    emit colourMapChanged(on ? map_ : nullptr);
}

void VerificationPanel::onRowChanged(int row)
{
    if (row < 0 || row >= static_cast<int>(report_.findings.size())) return;
    const verify::Finding& f = report_.findings[static_cast<std::size_t>(row)];
    emit findingSelected(f.step, f.move, f.position);
}

}  // namespace taiwa::ui
