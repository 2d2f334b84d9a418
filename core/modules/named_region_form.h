// The form fields of a named region (modules/named_region.h): "outline",
// the contour's name, and "islands", the names typed separated by commas
// or blanks,
// bound by the door of a contour unit (CP, AREA; ModuleKindOf::ownField).
#pragma once

#include "modules/form_binding.h"
#include "modules/named_region.h"

#include <optional>

namespace taiwa::form {

// The field `t` bound to "outline" or "islands" of the named region at
// member `m` of unit U; nullopt for any other field.
template <class U>
std::optional<FormField> namedRegionField(NamedRegion U::*m, const FieldText& t)
{
    if (t.bind == "outline")
        return contourName<U>(t.key, t.label, t.checks, [m](auto& u) -> auto& { return (u.*m).outline; });
    if (t.bind == "islands")
        return contourNames<U>(t.key, t.label, t.checks, [m](auto& u) -> auto& { return (u.*m).islands; });
    return std::nullopt;
}

}  // namespace taiwa::form
