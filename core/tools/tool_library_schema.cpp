// The SQLite tool library's schema (tool_library_schema.h): the tables of
// version 8 for a new file, the migrations from every older version, and
// the default tools and names those versions brought.
#include "tools/tool_library_schema.h"

#include "tools/tool_library.h"
#include "tools/tool_library_sqlite.h"

#include <iterator>

namespace taiwa::tooldb {

namespace {

// The current schema, for a new file.
constexpr const char* kSchema = R"sql(
CREATE TABLE tools (
  id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, diameter REAL NOT NULL,
  corner_radius REAL NOT NULL DEFAULT 0, taper_angle REAL NOT NULL DEFAULT 0, point_angle REAL NOT NULL DEFAULT 118,
  flute_length REAL NOT NULL DEFAULT 0, stickout REAL NOT NULL DEFAULT 0, holder TEXT NOT NULL DEFAULT '',
  flutes INTEGER NOT NULL DEFAULT 2, life_minutes REAL NOT NULL DEFAULT 0, used_minutes REAL NOT NULL DEFAULT 0,
  centre_cutting INTEGER NOT NULL DEFAULT 1, turning TEXT NOT NULL DEFAULT '',
  holder_diameter REAL NOT NULL DEFAULT 0, holder_length REAL NOT NULL DEFAULT 0);
CREATE TABLE cutting_data (
  tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, material TEXT NOT NULL,
  surface_speed REAL NOT NULL, feed_per_tooth REAL NOT NULL, plunge_factor REAL NOT NULL,
  PRIMARY KEY (tool_id, material));
CREATE TABLE tool_names (
  tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, language TEXT NOT NULL, name TEXT NOT NULL,
  PRIMARY KEY (tool_id, language));
CREATE TABLE tool_changes (tool_id INTEGER NOT NULL, operation TEXT NOT NULL, who TEXT NOT NULL,
  station TEXT NOT NULL, at TEXT NOT NULL, old_values TEXT NOT NULL, new_values TEXT NOT NULL);
PRAGMA user_version = 8;
)sql";

// Migrations: kMigrations[v - 1] brings a version v file to version v + 1.
constexpr const char* kMigrations[] = {
    // 1 -> 2: whether an end mill cuts at its centre (ramping in without a pilot hole).
    "ALTER TABLE tools ADD COLUMN centre_cutting INTEGER NOT NULL DEFAULT 1; PRAGMA user_version = 2;",
    // 2 -> 3: the default library's touch probe T90 (work-centre probing),
    // unless the library has a probe already or uses T90 for another tool.
    "INSERT INTO tools (id, name, type, diameter, flute_length, stickout, holder, flutes, life_minutes, centre_cutting) "
    "SELECT 90, 'Touch probe, 4 mm ruby ball', 'probe', 4, 0, 50, 'HSK63 probe body', 0, 0, 0 "
    "WHERE NOT EXISTS (SELECT 1 FROM tools WHERE type = 'probe' OR id = 90); PRAGMA user_version = 3;",
    // 3 -> 4: lathe tools (the insert code, holder and blade data as JSON in
    // `turning`); the default lathe tools are added after it where their ids
    // are free (addLatheTools).
    "ALTER TABLE tools ADD COLUMN turning TEXT NOT NULL DEFAULT ''; PRAGMA user_version = 4;",
    // 4 -> 5: the holder's nose, for the verification's collision check (0:
    // read from the holder's name, as before).
    "ALTER TABLE tools ADD COLUMN holder_diameter REAL NOT NULL DEFAULT 0; "
    "ALTER TABLE tools ADD COLUMN holder_length REAL NOT NULL DEFAULT 0; PRAGMA user_version = 5;",
    // 5 -> 6: hole patterns' tools (taps, reamers, boring heads, tap drills
    // and reaming pre-drills), added after it where their ids are free
    // (addFreeTools).
    "PRAGMA user_version = 6;",
    // 6 -> 7: tools' names in other languages, for the station (Tool::names);
    // the default library's tools that kept their id and name get theirs
    // (addBuiltInNames).
    "CREATE TABLE tool_names (tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, language TEXT NOT NULL, "
    "name TEXT NOT NULL, PRIMARY KEY (tool_id, language)); PRAGMA user_version = 7;",
    // 7 -> 8: who changed which tool, what and when (tool_change_log.h).
    // (IF NOT EXISTS: a file whose version was set back by hand keeps its log.)
    "CREATE TABLE IF NOT EXISTS tool_changes (tool_id INTEGER NOT NULL, operation TEXT NOT NULL, who TEXT NOT NULL, "
    "station TEXT NOT NULL, at TEXT NOT NULL, old_values TEXT NOT NULL, new_values TEXT NOT NULL); "
    "PRAGMA user_version = 8;",
};
static_assert(std::size(kMigrations) == kSchemaVersion - 1);

// Upgrading to version 4 (6): the default lathe (hole) tools whose ids the
// library does not use yet.
bool addFreeTools(sqlite3* db, const std::vector<Tool>& tools)
{
    for (const Tool& t : tools) {
        Statement used(db, "SELECT count(*) FROM tools WHERE id = ?");
        used.bind(1, t.id);
        if (!used.ok() || used.step() != SQLITE_ROW) return false;
        if (used.integer(0) == 0 && !insert(db, t)) return false;
    }
    return true;
}

// Upgrading to version 7: the names in other languages of the default
// library's tools that still have their id and name (a tool the shop
// renamed keeps its own name in every language).
bool addBuiltInNames(sqlite3* db)
{
    for (const Tool& t : defaultToolLibrary())
        for (const auto& [language, name] : t.names) {
            Statement s(db, "INSERT OR IGNORE INTO tool_names SELECT id, ?, ? FROM tools WHERE id = ? AND name = ?");
            s.bind(1, language);
            s.bind(2, name);
            s.bind(3, t.id);
            s.bind(4, t.name);
            if (!s.ok() || s.step() != SQLITE_DONE) return false;
        }
    return true;
}

}  // namespace

bool createSchema(sqlite3* db)
{
    bool ok = exec(db, kSchema);
    for (const auto& t : defaultToolLibrary()) ok = ok && insert(db, t);
    return ok;
}

bool upgradeSchema(sqlite3* db, int from)
{
    bool ok = true;
    for (int v = from; ok && v < kSchemaVersion; ++v) ok = exec(db, kMigrations[v - 1]);
    if (from < 4) ok = ok && addFreeTools(db, defaultLatheTools());
    if (from < 6) ok = ok && addFreeTools(db, defaultHoleTools());
    if (from < 7) ok = ok && addBuiltInNames(db);
    return ok;
}

}  // namespace taiwa::tooldb
