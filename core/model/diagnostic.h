// Diagnostics: what the operator must fix (errors) or should know (warnings,
// such as a tool reaching its life), as values that name the job, the unit,
// its module and the field, with a sentence a machinist understands. Every
// stage reports this way; a failure of the program itself (a file that
// cannot be written) is a Failure (model/result.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

enum class Severity { Error, Warning };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::optional<int> unit;  // 1-based unit number; absent for the job itself
    std::string module;       // "M4", "M2D"; empty for job-level fields
    std::string field;        // "corners", "cornerRadius", "stock.height", "technology.alpha1", ...
    std::string message;
    friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

using Diagnostics = std::vector<Diagnostic>;

// Control characters typed into a job (a newline in a material name, an ESC)
// must not forge lines or send terminal escapes: shown as \n, \t, \r, \x1b…
// (format() quotes every part with it; so does the station's translation).
std::string withControlsShown(const std::string& s);

// "JOB: unit N (MODULE) field: message", or "JOB: job field: message" for a
// job-level field, or "JOB: message" for the file as a whole (no unit, no
// field: unreadable, not JSON), as `taiwa check` prints it. A warning's
// message starts with "warning: ".
std::string format(const std::string& job, const Diagnostic& d);

bool hasErrors(const Diagnostics& ds);

// Every list of diagnostics shown to the operator holds at most this many;
// the last line then counts the rest.
constexpr std::size_t kMaxDiagnostics = 100;

// Collects diagnostics up to the cap; the rest are counted and summarised by
// one last line.
// Errors are kept before warnings: once the list is full, an error takes the
// place of the last warning kept, so that no refusal is hidden behind notes.
class DiagnosticSink {
public:
    void add(Diagnostic d);
    bool empty() const { return kept_.empty(); }
    // The kept diagnostics, with a final "N more errors not listed" line (an
    // error) when errors were dropped, and a "N more warnings not listed"
    // line (a warning) when warnings were: a list of warnings alone stays a
    // list without an error.
    Diagnostics finish() &&;

private:
    Diagnostics kept_;
    std::size_t droppedErrors_ = 0, droppedWarnings_ = 0;
};

// The same list, capped as DiagnosticSink caps it.
Diagnostics capped(Diagnostics ds);

}  // namespace taiwa
