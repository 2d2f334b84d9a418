// Reading and writing job files (*.taiwa): versioned JSON through
// nlohmann::json, never a hand-written parser; each unit's own fields read and
// written by its module's door. Reading never throws: a file that is not a
// readable job gives diagnostics naming what is wrong. The format is
// described in docs/job-format.md and resources/schema/taiwa-job.schema.json.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace taiwa {

// Files larger than this are refused before parsing.
constexpr std::size_t kMaxJobFileBytes = 64u * 1024u * 1024u;  // a 100,000-unit job is about 25 MB

struct JobReadResult {
    std::optional<Job> job;   // present only when the file was read whole
    Diagnostics diagnostics;  // why it could not be read (field = JSON path such as "units[2].depth")
};

// Parses a job document. Diagnostics for a unit carry its 1-based number and
// module; fields of the job itself have no unit.
JobReadResult readJob(std::string_view text);
// Reads a file (size limit checked before reading it into memory).
JobReadResult readJobFile(const std::string& path);

// The canonical text of a job: two-space indented JSON, keys in a fixed
// order, optional values omitted when absent, numbers in their shortest
// round-trip form, a final newline. readJob(writeJob(j)) == j, and
// writeJob(readJob(writeJob(j))) is the same text.
std::string writeJob(const Job& job);

// The oldest job format version that holds everything of `job`: the
// newest its units' modules came with (ModuleKind::formatVersion), its
// two-path settings (6), its figure (5), clamping (4), a bar (3) or a dialect (2).
int formatVersionFor(const Job& job);

}  // namespace taiwa
