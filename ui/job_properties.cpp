// The job properties box.
#include "ui/job_properties.h"
#include "ui/core_messages.h"

#include "machine/machine.h"
#include "model/technology.h"
#include "ui/job_document.h"
#include "ui/length_units.h"
#include "ui/number_text.h"

#include <QEvent>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {
namespace {
// The stock's fields: a block's, or a lathe job's bar.
const char* const kStockKeys[4] = {"stock.width", "stock.length", "stock.height", ""};
const char* const kBarKeys[4] = {"stock.diameter", "stock.length", "stock.face", "stock.bore"};
const char* stockKey(const Job& j, int which) { return j.bar ? kBarKeys[which] : kStockKeys[which]; }
double& stockValue(Job& j, int which)
{
    if (j.bar) return which == 0 ? j.bar->diameter : which == 1 ? j.bar->length : which == 2 ? j.bar->face : j.bar->bore;
    return which == 0 ? j.stock.width : which == 1 ? j.stock.length : j.stock.height;
}
double stockValue(const Job& j, int which)
{
    if (j.bar) return which == 0 ? j.bar->diameter : which == 1 ? j.bar->length : which == 2 ? j.bar->face : j.bar->bore;
    return which == 0 ? j.stock.width : which == 1 ? j.stock.length : j.stock.height;
}
}  // namespace

void JobProperties::nameFields()
{
    const auto label = [this](QWidget* field, const QString& text) {
        if (auto* l = qobject_cast<QLabel*>(form_->labelForField(field))) l->setText(text);
    };
    label(name_, tr("Name"));
    label(material_, tr("Material"));
    label(unit_, tr("Units"));
    label(machine_, tr("Machine"));
    label(vice_, tr("Clamping"));
    label(jaws_, tr("Jaws' height"));
    const auto& materials = TechnologyTable::builtIn().materials();
    for (int i = 0; i < material_->count() && i < static_cast<int>(materials.size()); ++i) {
        const MaterialTechnology& m = materials[static_cast<std::size_t>(i)];
        material_->setItemText(i, m.description.empty() ? QString::fromStdString(m.id) : localName(m.description, m.names));
    }
    unit_->setItemText(0, tr("mm"));
    unit_->setItemText(1, tr("inch (converts every length)"));
    const auto& machines = machineLibrary();
    for (int i = 0; i < machine_->count() && i < static_cast<int>(machines.size()); ++i) {
        const Machine& m = machines[static_cast<std::size_t>(i)];
        machine_->setItemText(i, QString::fromStdString(m.id) + " – " + localName(m.name, m.names));
    }
    vice_->setItemText(0, tr("not given"));
    vice_->setItemText(1, tr("vice on the X faces"));
    vice_->setItemText(2, tr("vice on the Y faces"));
    vice_->setToolTip(tr("How the block is held, for the instruction sheet's setup picture"));
    jaws_->setToolTip(tr("How far up the block's sides the jaws grip, from its bottom"));
}

void JobProperties::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange) return;
    nameFields();
    refresh(true);  // the stock's words, a block's or a bar's, and an unknown material's
}

JobProperties::JobProperties(JobDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), name_(new QLineEdit(this)), material_(new QComboBox(this)), unit_(new QComboBox(this))
{
    auto* form = new QFormLayout(this);
    name_->setObjectName("job.name");
    material_->setObjectName("job.material");
    unit_->setObjectName("job.unit");
    for (const MaterialTechnology& m : TechnologyTable::builtIn().materials())
        material_->addItem(QString(), QString::fromStdString(m.id));  // named by nameFields(), as the other choices
    unit_->addItem(QString(), 0);
    unit_->addItem(QString(), 1);
    form->addRow(new QLabel(this), name_);  // its words set by nameFields()
    form->addRow(new QLabel(this), material_);  // its words set by nameFields()
    form->addRow(new QLabel(this), unit_);  // its words set by nameFields()
    // The machine: a milling machine takes a block, a lathe a bar.
    machine_ = new QComboBox(this);
    // Long choices ("vmc – Vertical machining centre") shrink with the
    // column instead of widening it; the list shows them whole.
    for (QComboBox* c : {material_, unit_, machine_}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(12);
    }
    machine_->setObjectName("job.machine");
    for (const Machine& m : machineLibrary()) machine_->addItem(QString(), QString::fromStdString(m.id));
    form->addRow(new QLabel(this), machine_);  // its words set by nameFields()
    connect(machine_, &QComboBox::activated, this, [this](int i) {
        Job j = doc_->job();
        j.machine = machine_->itemData(i).toString().toStdString();
        const Machine* m = findMachine(j.machine);
        if (m && m->kind == MachineKind::Lathe && !j.bar) j.bar = BarStock{};
        if (m && m->kind == MachineKind::Mill) j.bar.reset();
        doc_->edit(j, tr("Machine %1").arg(QString::fromStdString(j.machine)));
    });
    form_ = form;
    for (int i = 0; i < 4; ++i) {
        stock_[i] = new QLineEdit(this);
        stock_[i]->setObjectName(i < 3 ? kStockKeys[i] : kBarKeys[i]);  // renamed by refresh() for a bar
        form->addRow(new QLabel(this), stock_[i]);  // its words set by refresh(): a block's or a bar's
        connect(stock_[i], &QLineEdit::textEdited, this, [this, i](const QString& t) { editStock(i, t); });
        connect(stock_[i], &QLineEdit::returnPressed, this, [this] { focusNextChild(); });
        connect(stock_[i], &QLineEdit::editingFinished, doc_, &JobDocument::breakMerge);
    }
    // How the block is held: the sheet draws the jaws and says where they grip.
    vice_ = new QComboBox(this);
    vice_->setObjectName("job.clamping");
    for (int i = 0; i < 3; ++i) vice_->addItem(QString());
    vice_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    vice_->setMinimumContentsLength(12);
    jaws_ = new QLineEdit(this);
    jaws_->setObjectName("clamping.height");
    form->addRow(new QLabel(this), vice_);  // its words set by nameFields()
    form->addRow(new QLabel(this), jaws_);  // its words set by nameFields()
    nameFields();
    connect(vice_, &QComboBox::activated, this, [this](int i) {
        Job j = doc_->job();
        if (i == 0) {
            j.clamping.reset();
        } else {
            // A third of the block's height at first, in tenths of the job's unit.
            if (!j.clamping) j.clamping = Clamping{Clamping::Grip::Y, std::max(0.1, std::round(j.stock.height / 3.0 * 10.0) / 10.0)};
            j.clamping->grip = i == 1 ? Clamping::Grip::X : Clamping::Grip::Y;
        }
        doc_->edit(j, tr("Change clamping"));
    });
    connect(jaws_, &QLineEdit::textEdited, this, &JobProperties::editJaws);
    connect(jaws_, &QLineEdit::returnPressed, this, [this] { focusNextChild(); });
    connect(jaws_, &QLineEdit::editingFinished, doc_, &JobDocument::breakMerge);
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
    doc_->edit(j, tr("Edit %1").arg(stockKey(j, which)), stockKey(j, which));
}

void JobProperties::editJaws(const QString& text)
{
    const auto v = parseNumber(text);
    badJaws_ = !v;
    if (!v) {
        jaws_->setStyleSheet("background: #ffd0d0;");
        jaws_->setToolTip(tr("not a number"));
        return;
    }
    Job j = doc_->job();
    if (!j.clamping) return;  // the field is off without a vice
    j.clamping->height = *v;
    doc_->edit(j, tr("Edit %1").arg("clamping.height"), "clamping.height");
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
    int mi = machine_->findData(QString::fromStdString(j.machine));
    if (mi < 0) {
        machine_->addItem(QString::fromStdString(j.machine) + tr(" (unknown)"), QString::fromStdString(j.machine));
        mi = machine_->count() - 1;
    }
    machine_->setCurrentIndex(mi);
    const QString blockLabels[4] = {tr("Stock width (X)"), tr("Stock length (Y)"), tr("Stock height (Z)"), QString()};
    const QString barLabels[4] = {tr("Bar diameter"), tr("Bar length"), tr("Face stock"), tr("Bore (0: solid)")};
    for (int i = 0; i < 4; ++i) {
        const bool shown = j.bar || i < 3;
        stock_[i]->setVisible(shown);
        stock_[i]->setObjectName(j.bar || i == 3 ? kBarKeys[i] : kStockKeys[i]);
        if (auto* label = qobject_cast<QLabel*>(form_->labelForField(stock_[i]))) {
            label->setText(j.bar ? barLabels[i] : blockLabels[i]);
            label->setVisible(shown);
        }
    }
    // A lathe holds its bar in the chuck: no vice.
    vice_->setVisible(!j.bar);
    jaws_->setVisible(!j.bar);
    for (QWidget* w : {static_cast<QWidget*>(vice_), static_cast<QWidget*>(jaws_)})
        if (QWidget* label = form_->labelForField(w)) label->setVisible(!j.bar);
    vice_->setCurrentIndex(!j.clamping ? 0 : j.clamping->grip == Clamping::Grip::X ? 1 : 2);
    jaws_->setEnabled(j.clamping.has_value());
    if (!j.clamping) {
        jaws_->clear();
        badJaws_ = false;
    } else if (const auto typed = parseNumber(jaws_->text());
               !(typed && (*typed == j.clamping->height || jaws_->text() == formatShown(j.clamping->height))) &&
               (force || !badJaws_)) {
        jaws_->setText(formatShown(j.clamping->height));
        badJaws_ = false;
    }
    for (int i = 0; i < 4; ++i) {
        if (!j.bar && i == 3) continue;
        const double v = stockValue(j, i);
        const auto typed = parseNumber(stock_[i]->text());
        if ((typed && (*typed == v || stock_[i]->text() == formatShown(v))) || (!force && bad_[i])) continue;
        stock_[i]->setText(formatShown(v));
        bad_[i] = false;
    }
}

void JobProperties::showDiagnostics(const Diagnostics& jobLevel)
{
    for (int i = 0; i < 4; ++i) {
        QString msg = bad_[i] ? tr("not a number") : QString();
        for (const Diagnostic& d : jobLevel)
            if (d.field == stockKey(doc_->job(), i) || (i == 0 && d.field == "stock.shape") || (i == 0 && d.field == "machine"))
                msg = coreMessage(d.message);
        stock_[i]->setStyleSheet(msg.isEmpty() ? QString() : QStringLiteral("background: #ffd0d0;"));
        stock_[i]->setToolTip(msg);
    }
    QString jaws = badJaws_ ? tr("not a number") : QString();
    for (const Diagnostic& d : jobLevel)
        if (d.field == "clamping.height" || d.field == "clamping")
            jaws = coreMessage(d.message);
    jaws_->setStyleSheet(jaws.isEmpty() ? QString() : QStringLiteral("background: #ffd0d0;"));
    jaws_->setToolTip(jaws.isEmpty() ? tr("How far up the block's sides the jaws grip, from its bottom") : jaws);
    bool badMaterial = false;
    for (const Diagnostic& d : jobLevel) badMaterial |= d.field == "material";
    material_->setStyleSheet(badMaterial ? QStringLiteral("background: #ffd0d0;") : QString());
}

}  // namespace taiwa::ui
