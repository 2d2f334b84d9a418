// Formatting diagnostics the way `taiwa check` prints them.
#include "model/diagnostic.h"

#include <algorithm>

namespace taiwa {

std::string format(const std::string& job, const Diagnostic& d)
{
    if (!d.unit && d.field.empty()) return job + ": " + d.message;  // the file itself (unreadable, not JSON)
    const std::string where = d.unit ? "unit " + std::to_string(*d.unit) + " (" + d.module + ")" : std::string("job");
    return job + ": " + where + " " + (d.field.empty() ? std::string("unit") : d.field) + ": " + d.message;
}

bool hasErrors(const Diagnostics& ds)
{
    return std::any_of(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

}  // namespace taiwa
