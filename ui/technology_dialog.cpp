// The technology data dialog.
#include "ui/technology_dialog.h"

#include <iterator>

#include "job/job_check.h"
#include "ui/number_text.h"

#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace taiwa::ui {
namespace {

struct Entry {
    const char* key;
    const char* symbol;
    const char* meaning;
    bool length;  // false: gamma, a coefficient
    std::optional<double> TechnologyOverrides::*override;
    double TechnologyData::*value;
};

const Entry kEntries[] = {
    {"alpha1", "α1", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "pilot hole stops this far above the floor"),
     true, &TechnologyOverrides::alpha1, &TechnologyData::alpha1},
    {"alpha2", "α2", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "wall allowance left by roughing"), true,
     &TechnologyOverrides::alpha2, &TechnologyData::alpha2},
    {"alpha3", "α3", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "wall allowance of the semi-finish pass (F = 3)"),
     true, &TechnologyOverrides::alpha3, &TechnologyData::alpha3},
    {"beta2", "β2", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "floor allowance left by roughing"), true,
     &TechnologyOverrides::beta2, &TechnologyData::beta2},
    {"gamma", "γ", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "roughing layer depth / tool diameter"), false,
     &TechnologyOverrides::gamma, &TechnologyData::gamma},
    {"stepOver", "ae/D", QT_TRANSLATE_NOOP("taiwa::ui::TechnologyDialog", "roughing step-over / tool diameter"), false,
     &TechnologyOverrides::stepOver, &TechnologyData::stepOver},
};
constexpr int kFields = static_cast<int>(std::size(kEntries));
static_assert(kFields == 6, "TechnologyDialog::edits_ holds one editor per entry");


QString shown(double v) { return formatNumber(std::round(v * 1e5) / 1e5); }

}  // namespace

TechnologyDialog::TechnologyDialog(const Job& job, QWidget* parent)
    : QDialog(parent), job_(job), error_(new QLabel(this))
{
    setWindowTitle(tr("Technology data"));
    const MaterialTechnology* material = TechnologyTable::builtIn().find(job.material);
    const QString unit = QString::fromUtf8(unitSymbol(job.lengthUnit));
    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("<b>Value</b>"), this), 0, 0, 1, 2);
    grid->addWidget(new QLabel(tr("<b>Table (%1)</b>").arg(QString::fromStdString(job.material)), this), 0, 2);
    grid->addWidget(new QLabel(tr("<b>This job</b> (empty = table)"), this), 0, 3);
    grid->addWidget(new QLabel(tr("<b>In force</b>"), this), 0, 4);
    for (int i = 0; i < kFields; ++i) {
        const Entry& e = kEntries[i];
        const int row = i + 1;
        auto* symbol = new QLabel(QStringLiteral("<b>%1</b>").arg(e.symbol), this);
        grid->addWidget(symbol, row, 0);
        grid->addWidget(new QLabel(tr(e.meaning), this), row, 1);
        QString table = tr("(unknown material)");
        if (material) {
            const double v = material->data.*(e.value);
            table = shown(e.length ? fromMm(v, job.lengthUnit) : v) + (e.length ? " " + unit : QString());
        }
        grid->addWidget(new QLabel(table, this), row, 2);
        edits_[i] = new QLineEdit(this);
        edits_[i]->setObjectName(QStringLiteral("technology.%1").arg(e.key));
        if (const auto& o = job.technology.*(e.override)) edits_[i]->setText(formatNumber(*o));
        symbol->setBuddy(edits_[i]);
        grid->addWidget(edits_[i], row, 3);
        effective_[i] = new QLabel(this);
        grid->addWidget(effective_[i], row, 4);
        connect(edits_[i], &QLineEdit::textChanged, this, &TechnologyDialog::refresh);
    }
    error_->setStyleSheet("color: #a00000;");
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (overrides()) accept();  // a field that is not a number keeps the dialog open
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* box = new QVBoxLayout(this);
    box->addLayout(grid);
    box->addWidget(error_);
    box->addWidget(buttons);
    refresh();
    buttons->button(QDialogButtonBox::Ok)->setObjectName("technology.ok");
}

std::optional<TechnologyOverrides> TechnologyDialog::overrides() const
{
    TechnologyOverrides o;
    for (int i = 0; i < kFields; ++i) {
        const QString text = edits_[i]->text().trimmed();
        if (text.isEmpty()) continue;
        const auto v = parseNumber(text);
        if (!v) return std::nullopt;
        o.*(kEntries[i].override) = *v;
    }
    return o;
}

void TechnologyDialog::refresh()
{
    const auto o = overrides();
    error_->setText(o ? QString() : tr("not a number"));
    for (int i = 0; i < kFields; ++i) {
        const bool bad = !edits_[i]->text().trimmed().isEmpty() && !parseNumber(edits_[i]->text());
        edits_[i]->setStyleSheet(bad ? "background: #ffd0d0;" : "");
    }
    Job j = job_;
    if (o) j.technology = *o;
    const auto inForce = jobTechnology(toMillimetres(j), TechnologyTable::builtIn());
    for (int i = 0; i < kFields; ++i) {
        const Entry& e = kEntries[i];
        if (!inForce) {
            effective_[i]->setText(QStringLiteral("–"));
            continue;
        }
        const double v = (*inForce).*(e.value);
        effective_[i]->setText(shown(e.length ? fromMm(v, j.lengthUnit) : v) +
                               (e.length ? QStringLiteral(" ") + unitSymbol(j.lengthUnit) : QString()));
    }
}

}  // namespace taiwa::ui
