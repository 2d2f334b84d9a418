// One tool library interface, two stores: the station's SQLite file
// (ToolLibrary, the default) and the shop's PostgreSQL server
// (pg_tool_store.h), chosen by the setting $TAIWA_TOOL_DB (docs/shop-server.md).
// A save names the row version it was read at; a save over a row changed
// since is refused with both values (ToolConflict), never a silent overwrite.
#pragma once

#include "model/result.h"
#include "model/tool.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// A tool with the version of its row when it was read (SQLite: always 0).
struct VersionedTool {
    Tool tool;
    std::int64_t version = 0;
};

// A save refused because the row changed (or went) since it was read: what
// the station meant to save, what the store holds now, and who changed it.
// The choice is the operator's: keep mine (save `mine` again at
// `theirVersion`) or take theirs (`theirs`).
struct ToolConflict {
    Tool mine;
    std::optional<Tool> theirs;  // none: the tool was removed meanwhile
    std::int64_t theirVersion = 0;
    std::string changedBy, station, changedAt;  // from the change log, where the store has one
};

// What a save did: the tool's id and its new version, or the conflict.
struct SaveOutcome {
    int id = 0;
    std::int64_t version = 0;
    std::optional<ToolConflict> conflict;
    bool saved() const { return !conflict; }
};

class ToolStore {
public:
    virtual ~ToolStore() = default;
    // The library as it is named in messages: the file, or the server
    // (postgresql://user@host:port/db, never a password).
    virtual std::string name() const = 0;
    // All tools ordered by id, with their versions.
    virtual Result<std::vector<VersionedTool>> versionedTools() = 0;
    Result<std::vector<Tool>> tools();
    // Saves `tool` if its row is still at `readVersion` (0 with id 0: a new
    // tool, given the next free id; 0 with an id: that id must be free).
    // SQLite ignores the version and replaces, as it always has.
    virtual Result<SaveOutcome> save(const Tool& tool, std::int64_t readVersion) = 0;
    virtual Result<void> remove(int id) = 0;
    virtual Result<void> addUsage(int id, double minutes) = 0;
    // Reading from a copy because the server cannot be reached: edits are
    // refused, and `asOf()` says when the copy was taken (UTC, ISO 8601).
    virtual bool readOnly() const { return false; }
    virtual std::string asOf() const { return {}; }
    // The status bar's line: "tools: FILE", "tools: server S", "tools as of
    // T (server S cannot be reached: …)".
    virtual std::string status() const = 0;
    // Where the tools last read came from, in a sentence for the instruction
    // sheet: "Tools from the library of S as of T" (T the server's time of
    // the read), "Tools as of T (server S away, read-only copy)"; empty for
    // the station's own file (the sheet says nothing, as it always has).
    virtual std::string origin() const { return {}; }
};

// Whether a setting names a PostgreSQL server (postgresql://…, postgres://…,
// or libpq's "service=NAME") rather than an SQLite file.
bool isServerSetting(const std::string& setting);

// The station's name on the server (its change log, its notifications):
// $TAIWA_STATION, else the host name.
std::string stationName();

// Where a station keeps its copy of the server's library:
// $XDG_DATA_HOME/taiwa/tools-server-copy.sqlite (else ~/.local/share/…).
std::string defaultServerCopyPath();

// Opens the store a setting names (defaultToolLibraryPath() when empty): an
// SQLite file, or the server with its local copy at `copyPath` (empty:
// defaultServerCopyPath()).
Result<std::unique_ptr<ToolStore>> openToolStore(const std::string& setting = {}, const std::string& copyPath = {});

}  // namespace taiwa
