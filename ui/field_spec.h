// What the unit forms show, in Qt's terms: the module's own form description
// (core/modules/form_fields.h, one FormField per input) as FieldSpecs with
// QStrings and getters/setters on a MachiningUnit. The forms and the undo
// commands are generic over these descriptions; no module is named here.
#pragma once

#include "model/job.h"
#include "modules/module_kind.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <utility>
#include <string>
#include <vector>

class QLineEdit;
class QWidget;

namespace taiwa::ui {

// ContourName, ContourNames: text naming contours of the job's figure
// (one name; several, separated by commas or blanks); Points: points typed
// as "x, y; x, y" (AREA's drawn passes).
enum class FieldKind { Number, OptionalNumber, Code, ContourName, ContourNames, Points };

struct FieldSpec {
    QString key;                 // widget objectName suffix: "P1.x", "depth", "U"
    QString label;               // form label (source text): "P1 X", "T (depth)"
    QString placeholder;         // shown in an empty field (OptionalNumber: what empty means)
    QString help;                // one line: what the value is (source text)
    QString symbol;              // its symbol's id in the module drawing ("sym-P1"); empty: none
    QStringList diagFields;      // checkJob field names shown on this widget
    FieldKind kind = FieldKind::Number;
    bool whole = false;          // a count: a fraction is refused, not rounded
    std::vector<std::pair<int, QString>> codes;  // Code: value and its meaning (source text: codeMeaning translates it)
    std::function<std::optional<double>(const MachiningUnit&)> get;
    std::function<void(MachiningUnit&, std::optional<double>)> set;
    // ContourName, ContourNames: the value as text ("K2, K3") and set from text.
    std::function<QString(const MachiningUnit&)> getText;
    std::function<void(MachiningUnit&, const QString&)> setText;
    bool isText() const
    {
        return kind == FieldKind::ContourName || kind == FieldKind::ContourNames || kind == FieldKind::Points;
    }
    // Whether `typed` says the same as the unit's value (the form keeps it then).
    bool sameText(const MachiningUnit& unit, const QString& typed) const;
};

// Fields of a module's form, top to bottom (the tab order).
const std::vector<FieldSpec>& fieldsFor(const ModuleKind& kind);
// The line edit of a contour-name field: it completes the names set with
// setCompletionNames (a list field completes the name being typed after
// the last comma or blank).
QLineEdit* makeNameEdit(const FieldSpec& field, QWidget* parent);
void setCompletionNames(QLineEdit* nameEdit, const QStringList& names);
// The names of the contours the job's figure text defines, in order (the
// text read as far as it can be; its refusals do not matter here).
QStringList figureContourNames(const std::string& figureText);

// Widget objectName prefix of a module: its name in lower case ("m4", "m2d").
QString modulePrefix(const ModuleKind& kind);

}  // namespace taiwa::ui
