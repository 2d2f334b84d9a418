// A module's form made from its description file (modules/module_text.h):
// each field described there is bound to what it reads and writes, by the
// job-file key it names through the module's job-file table
// (io/unit_keys.h: a number, an optional number, a whole number or code, a
// contour name, one coordinate of a point), or by the door itself, asked
// first, for a field the table holds in a grammar of its own (M4's corners,
// PROBE's touches) or that it shows otherwise (HOLES' pattern and hole as
// codes): ModuleKindOf::ownField, modules/module_kind.h.
#pragma once

#include "io/unit_keys.h"
#include "modules/form_fields.h"
#include "modules/module_text.h"

#include <fmt/format.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace taiwa::form {

// The door's own binding of a field: its reading and writing (and kind), or
// nullopt where the job-file table binds it. The texts are the description's.
using OwnBinding = std::function<std::optional<FormField>(const FieldText&)>;

namespace detail {

// The field of unit U that the table entry for `t.bind` reads and writes.
template <class U>
std::optional<FormField> boundByKey(const io::UnitKeys<U>& keys, const FieldText& t)
{
    const auto dot = t.bind.find('.');
    const std::string key = t.bind.substr(0, dot);
    const std::string axis = dot == std::string::npos ? "" : t.bind.substr(dot + 1);
    const io::UnitKey<U>* entry = keys.find(key);
    if (!entry) return std::nullopt;
    return std::visit(
        [&](auto m) -> std::optional<FormField> {
            using M = decltype(m);
            if constexpr (std::is_same_v<M, std::monostate>) {
                return std::nullopt;
            } else if constexpr (std::is_same_v<M, Point2 U::*>) {
                if (axis != "x" && axis != "y") return std::nullopt;
                const bool x = axis == "x";
                return number<U>(
                    t.key, t.label, t.checks, [m, x](const U& u) { return x ? (u.*m).x : (u.*m).y; },
                    [m, x](U& u, double v) { (x ? (u.*m).x : (u.*m).y) = v; });
            } else if (!axis.empty()) {
                return std::nullopt;  // a coordinate of what is not a point
            } else if constexpr (std::is_same_v<M, double U::*>) {
                return member<U>(t.key, t.label, t.checks, m);
            } else if constexpr (std::is_same_v<M, std::optional<double> U::*>) {
                return optionalMember<U>(t.key, t.label, t.placeholder, t.checks, m);
            } else if constexpr (std::is_same_v<M, int U::*>) {
                return intMember<U>(t.key, t.label, m, t.codes.empty() ? FormFieldKind::Number : FormFieldKind::Code);
            } else if constexpr (std::is_same_v<M, std::string U::*>) {
                return contourName<U>(t.key, t.label, t.checks, m);
            } else {
                static_assert(std::is_same_v<M, std::string U::*>, "a kind of io::UnitKey::Member no form field binds");
            }
        },
        entry->member);
}

// The description's texts on a bound field.
FormField described(FormField f, const FieldText& t, std::string_view module);

}  // namespace detail

// The form of unit U whose fields `texts` describes: each field bound by
// `own` if it binds it, else through `keys` (may be null: a module with a
// grammar of its own). A field neither binds is a bug (std::logic_error
// naming the module and the field).
template <class U>
std::vector<FormField> boundForm(const std::vector<FieldText>& texts, const io::UnitKeys<U>* keys,
                                 const OwnBinding& own = {})
{
    std::vector<FormField> fields;
    for (const FieldText& t : texts) {
        std::optional<FormField> f = own ? own(t) : std::nullopt;
        if (!f && keys) f = detail::boundByKey(*keys, t);
        if (!f)
            throw std::logic_error(fmt::format("the form of module {} has field \"{}\" bound to \"{}\", which neither "
                                               "its job-file table nor its door reads",
                                               U::kName, t.key, t.bind));
        fields.push_back(detail::described(std::move(*f), t, U::kName));
    }
    return fields;
}

}  // namespace taiwa::form
