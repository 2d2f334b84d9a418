// The description's texts put on a bound form field (form_binding.h).
#include "modules/form_binding.h"

namespace taiwa::form::detail {

FormField described(FormField f, const FieldText& t, std::string_view module)
{
    f.key = t.key;
    f.label = t.label;
    f.diagFields = t.checks;
    if (!t.placeholder.empty()) f.placeholder = t.placeholder;
    if (!t.codes.empty()) f.codes = t.codes;
    if (f.kind == FormFieldKind::Code && f.codes.empty())
        throw std::logic_error(fmt::format("the form of module {} has code field \"{}\" with no codes", module, t.key));
    if (f.kind != FormFieldKind::Code && !f.codes.empty())
        throw std::logic_error(fmt::format("the form of module {} gives field \"{}\" codes, but it is not a code",
                                           module, t.key));
    if (!t.placeholder.empty() && f.kind != FormFieldKind::OptionalNumber && !f.isText())
        throw std::logic_error(fmt::format("the form of module {} gives field \"{}\" a placeholder, but it cannot "
                                           "be empty",
                                           module, t.key));
    f.symbol = t.symbol;
    f.help = t.help;
    return f;
}

}  // namespace taiwa::form::detail
