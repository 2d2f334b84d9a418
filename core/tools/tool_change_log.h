// Who changed which tool, what and when (docs/tools.md, "The change log"):
// the station's SQLite library keeps a row per edit in its `tool_changes`
// table (schema version 8), as the shop server keeps its change log; a tool
// as a JSON object of its fields for the log's old and new values; the
// fields an edit changed, for the station to show before it is applied and
// in the tool's history; and the check that a tool's name still states its
// size (a T26 "Flat end mill 8 mm carbide" edited to 12 mm).
#pragma once

#include "model/result.h"
#include "model/tool.h"

#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace taiwa {

// One edit of a tool: "add", "change" or "remove", who (the user), the
// station (stationName()), when (UTC, ISO 8601), and the tool before and
// after as toolJson (empty for none). The shop server's log has the same
// (tools/pg_tool_store.h).
struct ToolChangeRecord {
    std::string operation, who, station, at;
    std::string oldValues, newValues;
};

// Now, as the change logs write it: UTC, ISO 8601, to the second.
std::string utcNow();

// The tool's fields as one JSON object, keys in a fixed order.
std::string toolJson(const Tool& t);

// One field an edit changes: its key (as in toolJson) and the values before
// and after, as the tool library dialog shows them ("8" → "12").
struct ToolFieldChange {
    std::string field, before, after;
    friend bool operator==(const ToolFieldChange&, const ToolFieldChange&) = default;
};
std::vector<ToolFieldChange> toolChanges(const Tool& before, const Tool& after);

// The name states a size the tool does not have: "the name says 8 mm, the
// diameter is 12 mm". Sizes read from the name: a number followed by "mm"
// ("8 mm", "8mm") or after "Ø"/"D" ("Ø8", "D8"); none stated, or one of them
// the diameter (within 1 µm), is no mismatch.
std::optional<std::string> nameSizeMismatch(const Tool& t);

// The log in a library file (inside the caller's transaction): one row.
Result<void> logToolChange(sqlite3* db, const std::string& operation, int toolId, const std::string& oldValues,
                           const std::string& newValues);
// The rows of one tool, oldest first.
Result<std::vector<ToolChangeRecord>> readToolChanges(sqlite3* db, int toolId);

}  // namespace taiwa
