// Formatting diagnostics the way `taiwa check` prints them.
#include "model/diagnostic.h"

#include <string>

#include <algorithm>

namespace taiwa {

std::string format(const std::string& job, const Diagnostic& d)
{
    if (!d.unit && d.field.empty()) return job + ": " + d.message;  // the file itself (unreadable, not JSON)
    const std::string where = d.unit ? "unit " + std::to_string(*d.unit) + " (" + d.module + ")" : std::string("job");
    const std::string kind = d.severity == Severity::Warning ? "warning: " : "";
    return job + ": " + where + " " + (d.field.empty() ? std::string("unit") : d.field) + ": " + kind + d.message;
}

bool hasErrors(const Diagnostics& ds)
{
    return std::any_of(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

void DiagnosticSink::add(Diagnostic d)
{
    if (kept_.size() < kMaxDiagnostics) kept_.push_back(std::move(d));
    else ++dropped_;
}

Diagnostics DiagnosticSink::finish() &&
{
    if (dropped_ > 0) {
        // The last kept one makes room for the line that counts the rest.
        kept_.pop_back();
        kept_.push_back({Severity::Error, std::nullopt, "", "",
                         std::to_string(dropped_ + 1) + " more errors not listed; correct the ones above first"});
    }
    return std::move(kept_);
}

Diagnostics capped(Diagnostics ds)
{
    DiagnosticSink sink;
    for (auto& d : ds) sink.add(std::move(d));
    return std::move(sink).finish();
}

}  // namespace taiwa
