// The module forms' field descriptions, converted once per module kind from
// the kind's own FormFields; the line edit of a contour-name field with its
// completer of the figure's contour names.
#include "ui/field_spec.h"

#include "figure/figure_text.h"

#include <QCompleter>
#include <QLineEdit>
#include <QPointer>
#include <QStringListModel>

#include <map>
#include <string>

namespace taiwa::ui {
namespace {

QString text(const std::string& s) { return QString::fromStdString(s); }

FieldSpec toSpec(const FormField& f)
{
    FieldSpec s;
    s.key = text(f.key);
    s.label = text(f.label);
    s.placeholder = text(f.placeholder);
    s.help = text(f.help);
    s.symbol = text(f.symbol);
    for (const auto& d : f.diagFields) s.diagFields << text(d);
    s.kind = f.kind == FormFieldKind::Code             ? FieldKind::Code
             : f.kind == FormFieldKind::OptionalNumber ? FieldKind::OptionalNumber
             : f.kind == FormFieldKind::ContourName    ? FieldKind::ContourName
             : f.kind == FormFieldKind::ContourNames   ? FieldKind::ContourNames
             : f.kind == FormFieldKind::Points         ? FieldKind::Points
                                                       : FieldKind::Number;
    s.whole = f.whole;
    for (const auto& [value, meaning] : f.codes) s.codes.emplace_back(value, text(meaning));
    s.get = [get = f.get](const MachiningUnit& u) { return get(u.module); };
    s.set = [set = f.set](MachiningUnit& u, std::optional<double> v) { set(u.module, v); };
    if (f.isText()) {
        s.getText = [get = f.getText](const MachiningUnit& u) { return text(get(u.module)); };
        s.setText = [set = f.setText](MachiningUnit& u, const QString& t) { set(u.module, t.toStdString()); };
    }
    return s;
}

// Completes the whole text (one name), or the name after the last comma or
// blank (a list), keeping what comes before it.
class NameCompleter : public QCompleter {
public:
    NameCompleter(QLineEdit* edit, bool list) : QCompleter(edit), edit_(edit), list_(list)
    {
        setModel(new QStringListModel(this));
        setCaseSensitivity(Qt::CaseInsensitive);
        setCompletionMode(QCompleter::PopupCompletion);
    }
    QStringList splitPath(const QString& path) const override { return {list_ ? path.mid(lastStart(path)) : path}; }
    QString pathFromIndex(const QModelIndex& index) const override
    {
        const QString name = QCompleter::pathFromIndex(index);
        if (!list_ || !edit_) return name;
        const QString typed = edit_->text();
        return typed.left(lastStart(typed)) + name;
    }

private:
    static qsizetype lastStart(const QString& s)
    {
        qsizetype i = s.size();
        while (i > 0 && s[i - 1] != ',' && !s[i - 1].isSpace()) --i;
        return i;
    }
    QPointer<QLineEdit> edit_;
    bool list_;
};

}  // namespace

bool FieldSpec::sameText(const MachiningUnit& unit, const QString& typed) const
{
    if (!isText()) return false;
    MachiningUnit copy = unit;
    setText(copy, typed);
    return getText(copy) == getText(unit);
}

QLineEdit* makeNameEdit(const FieldSpec& field, QWidget* parent)
{
    auto* edit = new QLineEdit(parent);
    if (field.kind != FieldKind::Points)
        edit->setCompleter(new NameCompleter(edit, field.kind == FieldKind::ContourNames));
    return edit;
}

void setCompletionNames(QLineEdit* nameEdit, const QStringList& names)
{
    auto* completer = nameEdit ? nameEdit->completer() : nullptr;
    auto* model = completer ? qobject_cast<QStringListModel*>(completer->model()) : nullptr;
    if (model && model->stringList() != names) model->setStringList(names);
}

QStringList figureContourNames(const std::string& figureText)
{
    QStringList names;
    for (const figure::Definition& d : figure::parseFigure(figureText).definitions)
        if (d.kind() == figure::Kind::Contour) names << text(d.name);
    return names;
}

const std::vector<FieldSpec>& fieldsFor(const ModuleKind& kind)
{
    // Built on the GUI thread only; one entry per module kind.
    static std::map<std::string, std::vector<FieldSpec>> cache;
    auto [it, inserted] = cache.try_emplace(kind.name());
    if (inserted)
        for (const auto& f : kind.fields()) it->second.push_back(toSpec(f));
    return it->second;
}

QString modulePrefix(const ModuleKind& kind) { return QString::fromUtf8(kind.name()).toLower(); }

}  // namespace taiwa::ui
