// Formatting diagnostics the way `taiwa check` prints them.
#include "model/diagnostic.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <string>

#include <algorithm>

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
    if (kept_.size() < kMaxDiagnostics) kept_.push_back(std::move(d));
    else ++dropped_;
}

Diagnostics DiagnosticSink::finish() &&
{
    if (dropped_ > 0) {
        // The last kept one makes room for the line that counts the rest.
        kept_.pop_back();
        kept_.push_back({Severity::Error, std::nullopt, "", "",
                         fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} more errors not listed; correct the ones above first"),
                                     dropped_ + 1)});
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
