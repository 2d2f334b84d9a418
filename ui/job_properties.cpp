// The job properties box.
#include "ui/job_properties.h"

#include "model/technology.h"
#include "ui/job_document.h"
#include "ui/length_units.h"
#include "ui/number_text.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>

namespace taiwa::ui {
namespace {
const char* const kStockKeys[3] = {"stock.width", "stock.length", "stock.height"};
double& stockValue(Job& j, int which)
{
    return which == 0 ? j.stock.width : which == 1 ? j.stock.length : j.stock.height;
}
double stockValue(const Job& j, int which)
{
    return which == 0 ? j.stock.width : which == 1 ? j.stock.length : j.stock.height;
}
}  // namespace

JobProperties::JobProperties(JobDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), name_(new QLineEdit(this)), material_(new QComboBox(this)), unit_(new QComboBox(this))
{
    auto* form = new QFormLayout(this);
    name_->setObjectName("job.name");
    material_->setObjectName("job.material");
    unit_->setObjectName("job.unit");
    for (const MaterialTechnology& m : TechnologyTable::builtIn().materials())
        material_->addItem(QString::fromStdString(m.description.empty() ? m.id : m.description),
                           QString::fromStdString(m.id));
    unit_->addItem(tr("mm"), 0);
    unit_->addItem(tr("inch (converts every length)"), 1);
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Material"), material_);
    form->addRow(tr("Units"), unit_);
    const QString labels[3] = {tr("Stock width (X)"), tr("Stock length (Y)"), tr("Stock height (Z)")};
    for (int i = 0; i < 3; ++i) {
        stock_[i] = new QLineEdit(this);
        stock_[i]->setObjectName(kStockKeys[i]);
        form->addRow(labels[i], stock_[i]);
        connect(stock_[i], &QLineEdit::textEdited, this, [this, i](const QString& t) { editStock(i, t); });
        connect(stock_[i], &QLineEdit::returnPressed, this, [this] { focusNextChild(); });
        connect(stock_[i], &QLineEdit::editingFinished, doc_, &JobDocument::breakMerge);
    }
    connect(name_, &QLineEdit::editingFinished, doc_, &JobDocument::breakMerge);
    connect(name_, &QLineEdit::textEdited, this, [this](const QString& t) {
        Job j = doc_->job();
        j.name = t.toStdString();
        doc_->edit(j, tr("Edit job name"), "job.name");
    });
    connect(material_, &QComboBox::activated, this, [this](int i) {
        Job j = doc_->job();
        j.material = material_->itemData(i).toString().toStdString();
        doc_->edit(j, tr("Change material"));
    });
    connect(unit_, &QComboBox::activated, this, [this](int i) {
        const LengthUnit to = i == 1 ? LengthUnit::Inch : LengthUnit::Millimetre;
        doc_->edit(convertLengthUnit(doc_->job(), to), tr("Change length unit"));
    });
}

void JobProperties::editStock(int which, const QString& text)
{
    const auto v = parseNumber(text);
    bad_[which] = !v;
    if (!v) {
        stock_[which]->setStyleSheet("background: #ffd0d0;");
        stock_[which]->setToolTip(tr("not a number"));
        return;
    }
    Job j = doc_->job();
    stockValue(j, which) = *v;
    doc_->edit(j, tr("Edit %1").arg(kStockKeys[which]), kStockKeys[which]);
}

void JobProperties::refresh(bool force)
{
    const Job& j = doc_->job();
    if (force || name_->text().toStdString() != j.name) name_->setText(QString::fromStdString(j.name));
    int m = material_->findData(QString::fromStdString(j.material));
    if (m < 0) {
        material_->addItem(QString::fromStdString(j.material) + tr(" (unknown)"), QString::fromStdString(j.material));
        m = material_->count() - 1;
    }
    material_->setCurrentIndex(m);
    unit_->setCurrentIndex(j.lengthUnit == LengthUnit::Inch ? 1 : 0);
    for (int i = 0; i < 3; ++i) {
        const double v = stockValue(j, i);
        const auto typed = parseNumber(stock_[i]->text());
        if ((typed && (*typed == v || stock_[i]->text() == formatShown(v))) || (!force && bad_[i])) continue;
        stock_[i]->setText(formatShown(v));
        bad_[i] = false;
    }
}

void JobProperties::showDiagnostics(const Diagnostics& jobLevel)
{
    for (int i = 0; i < 3; ++i) {
        QString msg = bad_[i] ? tr("not a number") : QString();
        for (const Diagnostic& d : jobLevel)
            if (d.field == kStockKeys[i]) msg = QString::fromStdString(d.message);
        stock_[i]->setStyleSheet(msg.isEmpty() ? QString() : QStringLiteral("background: #ffd0d0;"));
        stock_[i]->setToolTip(msg);
    }
    bool badMaterial = false;
    for (const Diagnostic& d : jobLevel) badMaterial |= d.field == "material";
    material_->setStyleSheet(badMaterial ? QStringLiteral("background: #ffd0d0;") : QString());
}

}  // namespace taiwa::ui
