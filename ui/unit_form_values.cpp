// The generic module form's values (unit_form.h): the unit's values shown
// in the fields (text being typed kept), typed text parsed into edits or
// refused as "not a number", and the check diagnostics shown under the
// fields they name. The widgets, their names and their arrangement:
// unit_form.cpp.
#include "ui/unit_form.h"

#include "ui/core_messages.h"
#include "ui/number_text.h"
#include "ui/profile_editor.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QStringList>

#include <cmath>

namespace taiwa::ui {

namespace {
const char* const kRed = "background: #ffd0d0;";
}

void UnitForm::setContext(const Job& job, const std::vector<Tool>& library)
{
    if (profile_) profile_->setContext(job.bar, library);
    QStringList contours;
    bool read = false;
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        if (!fields_[i].isText() || fields_[i].kind == FieldKind::Points) continue;
        if (!read) contours = figureContourNames(job.figure), read = true;
        setCompletionNames(rows_[i].edit, contours);
    }
}

void UnitForm::setUnit(const MachiningUnit& unit, bool force)
{
    current_ = unit.module;
    if (profile_)
        if (const turning::TurnedProfile* p = kind_.turnedProfile(unit.module)) {
            profile_->setUnit(kind_, unit.module);  // first: setProfile draws with it
            profile_->setProfile(*p, force);
        }
    updating_ = true;
    if (name_->text() != QString::fromStdString(unit.name)) name_->setText(QString::fromStdString(unit.name));
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        Row& row = rows_[i];
        if (fields_[i].isText()) {  // contour names: kept as typed while they say the same
            if (force ? row.edit->text() != fields_[i].getText(unit) : !fields_[i].sameText(unit, row.edit->text()))
                row.edit->setText(fields_[i].getText(unit));
            continue;
        }
        const std::optional<double> v = fields_[i].get(unit);
        if (row.combo) {
            const int code = v ? static_cast<int>(std::lround(*v)) : 0;
            int item = row.combo->findData(code);
            if (item < 0) {
                row.combo->addItem(QStringLiteral("%1 – not a code of the table").arg(code), code);
                item = row.combo->count() - 1;
            }
            row.combo->setCurrentIndex(item);
            continue;
        }
        const QString text = row.edit->text();
        const bool empty = text.trimmed().isEmpty();
        const std::optional<double> typed = parseNumber(text);
        const bool same = (typed && v && (*typed == *v || text == formatShown(*v))) ||
                          (empty && !v && fields_[i].kind == FieldKind::OptionalNumber);
        if (same || (!force && row.notANumber)) continue;
        row.edit->setText(v ? formatShown(*v) : QString());
        row.notANumber = false;
    }
    updating_ = false;
}

void UnitForm::onTextEdited(int field, const QString& text)
{
    Row& row = rows_[static_cast<std::size_t>(field)];
    const bool optional = fields_[static_cast<std::size_t>(field)].kind == FieldKind::OptionalNumber;
    if (optional && text.trimmed().isEmpty()) {
        row.notANumber = false;
        emit edited(field, std::nullopt);
        return;
    }
    const std::optional<double> v = parseNumber(text);
    const bool fraction = v && fields_[static_cast<std::size_t>(field)].whole && *v != std::round(*v);
    row.notANumber = !v || fraction;
    row.fraction = fraction;
    if (!v || fraction) {
        setMessage(field, fraction ? tr("not a whole number") : tr("not a number"));
        return;
    }
    emit edited(field, v);
}

void UnitForm::setMessage(int field, const QString& message, bool warning)
{
    Row& row = rows_[static_cast<std::size_t>(field)];
    QWidget* editor = row.edit ? static_cast<QWidget*>(row.edit) : row.combo;
    editor->setStyleSheet(message.isNull() || warning ? QString() : QString(kRed));
    editor->setToolTip(message);
    // A warning (the plan goes on: an area left unswept) in amber, an error in red.
    row.message->setStyleSheet(warning ? QStringLiteral("color: #8a5a00;") : QStringLiteral("color: #a00000;"));
    row.message->setText(message);
    row.message->setVisible(!message.isEmpty());
}

Diagnostics UnitForm::showDiagnostics(const Diagnostics& all)
{
    const Diagnostics ofThisUnit = profile_ ? profile_->showDiagnostics(all) : all;
    std::vector<QString> messages(fields_.size());
    std::vector<bool> red(fields_.size(), false), error(fields_.size(), false);
    Diagnostics unmatched;
    for (const Diagnostic& d : ofThisUnit) {
        const QString field = QString::fromStdString(d.field);
        bool shown = false;
        for (std::size_t i = 0; i < fields_.size(); ++i) {
            if (!fields_[i].diagFields.contains(field)) continue;
            red[i] = true;
            if (d.severity == Severity::Error) error[i] = true;
            if (!shown) {  // the message once, under the first widget it names
                const QString m = coreMessage(d.message);
                messages[i] = messages[i].isEmpty() ? m : messages[i] + "\n" + m;
                shown = true;
            }
        }
        if (!shown) unmatched.push_back(d);
    }
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        const int index = static_cast<int>(i);
        if (rows_[i].notANumber) setMessage(index, rows_[i].fraction ? tr("not a whole number") : tr("not a number"));
        else if (red[i]) setMessage(index, messages[i].isEmpty() ? QStringLiteral("") : messages[i], !error[i]);
        else setMessage(index, QString());
    }
    layOutNow();
    return unmatched;
}

bool UnitForm::hasUnparsableText() const
{
    for (const Row& r : rows_)
        if (r.notANumber) return true;
    return false;
}

}  // namespace taiwa::ui
