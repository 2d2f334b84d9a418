// What the unit forms show: one FieldSpec per input of a module (key for the
// widget's objectName, label, the job-file field the checks name, how to read
// and write the value on a MachiningUnit). The forms and the undo commands are
// generic over these descriptions.
#pragma once

#include "model/job.h"

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
    QString label;               // form label: "P1 X", "T (depth)"
    QString placeholder;         // shown in an empty field (OptionalNumber: what empty means)
    QStringList diagFields;      // checkJob field names shown on this widget
    FieldKind kind = FieldKind::Number;
    std::vector<std::pair<int, QString>> codes;  // Code: value and "1 – roughing, ..."
    std::function<std::optional<double>(const MachiningUnit&)> get;
    std::function<void(MachiningUnit&, std::optional<double>)> set;
};

// Fields of the module forms, top to bottom (the tab order).
const std::vector<FieldSpec>& m4Fields();
const std::vector<FieldSpec>& m2dFields();
const std::vector<FieldSpec>& fieldsFor(const ModuleInput& m);
// Widget objectName prefix of a module: "m4", "m2d".
QString modulePrefix(const ModuleInput& m);

}  // namespace taiwa::ui
