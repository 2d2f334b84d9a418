// The module forms' field descriptions, converted once per module kind from
// the kind's own FormFields.
#include "ui/field_spec.h"

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
                                                       : FieldKind::Number;
    for (const auto& [value, meaning] : f.codes) s.codes.emplace_back(value, text(meaning));
    s.get = [get = f.get](const MachiningUnit& u) { return get(u.module); };
    s.set = [set = f.set](MachiningUnit& u, std::optional<double> v) { set(u.module, v); };
    return s;
}

}  // namespace

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
