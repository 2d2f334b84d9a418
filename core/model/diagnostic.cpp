// Formatting diagnostics the way `taiwa check` prints them, and the capped
// list of them (DiagnosticSink: errors kept before warnings).
#include "model/diagnostic.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <string>

namespace taiwa {

std::string withControlsShown(const std::string& s)
{
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (c == '\r') out += "\\r";
        else if (u < 0x20 || u == 0x7f) {
            static const char* hex = "0123456789abcdef";
            out += "\\x";
            out += hex[u >> 4];
            out += hex[u & 15];
        } else out += c;
    }
    return out;
}

std::string format(const std::string& jobName, const Diagnostic& diagnostic)
{
    Diagnostic d = diagnostic;
    d.module = withControlsShown(d.module);
    d.field = withControlsShown(d.field);
    d.message = withControlsShown(d.message);
    const std::string job = withControlsShown(jobName);
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
    const bool error = d.severity == Severity::Error;
    if (kept_.size() < kMaxDiagnostics) {
        kept_.push_back(std::move(d));
        return;
    }
    // Full: an error takes the place of the last warning kept.
    if (error) {
        const auto warning = std::find_if(kept_.rbegin(), kept_.rend(), [](const Diagnostic& k) { return k.severity != Severity::Error; });
        if (warning != kept_.rend()) {
            kept_.erase(std::next(warning).base());
            ++droppedWarnings_;
            kept_.push_back(std::move(d));
            return;
        }
    }
    ++(error ? droppedErrors_ : droppedWarnings_);
}

Diagnostics DiagnosticSink::finish() &&
{
    // Each count's line takes the place of the last kept one, a warning
    // before an error (counted with its kind), so that the list stays
    // within kMaxDiagnostics.
    const auto lines = [&] { return std::size_t{droppedErrors_ > 0} + std::size_t{droppedWarnings_ > 0}; };
    const auto dropLast = [&](bool error) {
        const auto it = std::find_if(kept_.rbegin(), kept_.rend(), [&](const Diagnostic& k) { return (k.severity == Severity::Error) == error; });
        if (it == kept_.rend()) return false;
        kept_.erase(std::next(it).base());
        ++(error ? droppedErrors_ : droppedWarnings_);
        return true;
    };
    while (lines() > 0 && kept_.size() + lines() > kMaxDiagnostics)
        if (!dropLast(false)) dropLast(true);
    if (droppedWarnings_ > 0)
        kept_.push_back({Severity::Warning, std::nullopt, "", "",
                         fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} more warnings not listed"), droppedWarnings_)});
    if (droppedErrors_ > 0)
        kept_.push_back({Severity::Error, std::nullopt, "", "",
                         fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} more errors not listed; correct the ones above first"),
                                     droppedErrors_)});
    return std::move(kept_);
}

Diagnostics capped(Diagnostics ds)
{
    DiagnosticSink sink;
    for (auto& d : ds) sink.add(std::move(d));
    return std::move(sink).finish();
}

}  // namespace taiwa
