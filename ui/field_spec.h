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
#include <vector>

namespace taiwa::ui {

enum class FieldKind { Number, OptionalNumber, Code };

struct FieldSpec {
    QString key;                 // widget objectName suffix: "P1.x", "depth", "U"
    QString label;               // form label (source text): "P1 X", "T (depth)"
    QString placeholder;         // shown in an empty field (OptionalNumber: what empty means)
    QString help;                // one line: what the value is (source text)
    QString symbol;              // its symbol's id in the module drawing ("sym-P1"); empty: none
    QStringList diagFields;      // checkJob field names shown on this widget
    FieldKind kind = FieldKind::Number;
    std::vector<std::pair<int, QString>> codes;  // Code: value and its meaning (source text: codeMeaning translates it)
    std::function<std::optional<double>(const MachiningUnit&)> get;
    std::function<void(MachiningUnit&, std::optional<double>)> set;
};

// Fields of a module's form, top to bottom (the tab order).
const std::vector<FieldSpec>& fieldsFor(const ModuleKind& kind);
// Widget objectName prefix of a module: its name in lower case ("m4", "m2d").
QString modulePrefix(const ModuleKind& kind);

}  // namespace taiwa::ui
