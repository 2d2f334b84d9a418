// Diagnostics of input processing: errors as values that name the job, the
// unit, its module and the field, with a sentence a machinist understands.
#pragma once

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

// "JOB: unit N (MODULE) field: message", or "JOB: job field: message" for a
// job-level field, or "JOB: message" for the file as a whole (no unit, no
// field: unreadable, not JSON), as `taiwa check` prints it.
std::string format(const std::string& job, const Diagnostic& d);

bool hasErrors(const Diagnostics& ds);

}  // namespace taiwa
