// The tool library in SQLite: schema, first-use creation with the default
// library, reading and editing. Every failure is a message naming the file.
#include "tools/tool_library.h"
#include "tools/turning_text.h"

#include "tools/tool_change_log.h"
#include "tools/tool_check.h"
#include "tools/tool_row.h"
#include "tools/tool_store.h"
#include "model/translate_noop.h"

#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <iterator>
#include <optional>
#include <system_error>

namespace taiwa {

namespace {

constexpr int kSchemaVersion = 8;

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

// A prepared statement that finalizes itself.
class Statement {
public:
    Statement(sqlite3* db, const char* sql) { ok_ = sqlite3_prepare_v2(db, sql, -1, &s_, nullptr) == SQLITE_OK; }
    ~Statement() { sqlite3_finalize(s_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    bool ok() const { return ok_; }
    sqlite3_stmt* get() const { return s_; }
    void bind(int i, double v) { sqlite3_bind_double(s_, i, v); }
    void bind(int i, int v) { sqlite3_bind_int(s_, i, v); }
    void bind(int i, const std::string& v) { sqlite3_bind_text(s_, i, v.c_str(), -1, SQLITE_TRANSIENT); }
    int step() { return sqlite3_step(s_); }
    double real(int c) const { return sqlite3_column_double(s_, c); }
    int integer(int c) const { return sqlite3_column_int(s_, c); }
    bool flag(int c) const { return integer(c) != 0; }
    std::string text(int c) const
    {
        const auto* t = sqlite3_column_text(s_, c);
        return t ? reinterpret_cast<const char*>(t) : "";
    }

private:
    sqlite3_stmt* s_ = nullptr;
    bool ok_ = false;
};

std::string describe(sqlite3* db, const std::string& path)
{
    const int code = sqlite3_extended_errcode(db) & 0xff;
    if (code == SQLITE_NOTADB)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a tool library (the file is not an SQLite database)"), path);
    if (code == SQLITE_BUSY || code == SQLITE_LOCKED)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is locked by another program; close it and try again"), path);
    if (code == SQLITE_READONLY || code == SQLITE_CANTOPEN || code == SQLITE_PERM)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot be opened for writing ({})"), path, sqlite3_errmsg(db));
    if (code == SQLITE_CORRUPT)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is damaged ({}); restore it from a backup"), path, sqlite3_errmsg(db));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), path, sqlite3_errmsg(db));
}

bool exec(sqlite3* db, const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK; }

bool insert(sqlite3* db, const Tool& t);

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

bool insert(sqlite3* db, const Tool& t)
{
    const std::string sql = fmt::format("INSERT OR REPLACE INTO tools (id, {}) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)", kToolColumns);
    Statement s(db, sql.c_str());
    if (!s.ok()) return false;
    s.bind(1, t.id);
    s.bind(2, t.name);
    s.bind(3, std::string(toKey(t.type)));
    s.bind(4, t.diameter);
    s.bind(5, t.cornerRadius);
    s.bind(6, t.taperAngle);
    s.bind(7, t.pointAngle);
    s.bind(8, t.fluteLength);
    s.bind(9, t.stickout);
    s.bind(10, t.holder);
    s.bind(11, t.flutes);
    s.bind(12, t.lifeMinutes);
    s.bind(13, t.usedMinutes);
    s.bind(14, t.centreCutting ? 1 : 0);
    s.bind(15, turningText(t.turning));
    s.bind(16, t.holderDiameter);
    s.bind(17, t.holderLength);
    if (s.step() != SQLITE_DONE) return false;
    for (const char* table : {"DELETE FROM cutting_data WHERE tool_id = ?", "DELETE FROM tool_names WHERE tool_id = ?"}) {
        Statement del(db, table);
        del.bind(1, t.id);
        if (!del.ok() || del.step() != SQLITE_DONE) return false;
    }
    for (const auto& [language, name] : t.names) {
        Statement n(db, "INSERT INTO tool_names VALUES (?,?,?)");
        n.bind(1, t.id);
        n.bind(2, language);
        n.bind(3, name);
        if (!n.ok() || n.step() != SQLITE_DONE) return false;
    }
    for (const auto& c : t.cutting) {
        Statement cd(db, "INSERT INTO cutting_data VALUES (?,?,?,?,?)");
        cd.bind(1, t.id);
        cd.bind(2, c.material);
        cd.bind(3, c.surfaceSpeed);
        cd.bind(4, c.feedPerTooth);
        cd.bind(5, c.plungeFactor);
        if (!cd.ok() || cd.step() != SQLITE_DONE) return false;
    }
    return true;
}

}  // namespace

struct ToolLibrary::Db {
    sqlite3* handle = nullptr;
    ~Db() { sqlite3_close(handle); }
};

ToolLibrary::ToolLibrary(std::string path) : db_(std::make_unique<Db>()), path_(std::move(path)) {}
ToolLibrary::~ToolLibrary() = default;
ToolLibrary::ToolLibrary(ToolLibrary&&) noexcept = default;

Result<ToolLibrary> ToolLibrary::open(const std::string& path)
{
    ToolLibrary lib(path);
    std::error_code ec;
    const bool fresh = !std::filesystem::exists(path, ec);
    // SQLite would take an empty file for a new database and fill it: the
    // operator's file is never rewritten, so an empty one is refused.
    // A directory, device or pipe is named by its kind, never handed to SQLite.
    if (!fresh && std::filesystem::is_directory(path, ec))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is a folder, not a tool library (give the library's file)"), path)};
    if (!fresh && !std::filesystem::is_regular_file(path, ec))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a regular file, not a tool library"), path)};
    if (!fresh && std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) == 0)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is empty, not a tool library (delete it to have the default library created)"), path)};
    if (fresh && std::filesystem::path(path).has_parent_path()) {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
        if (ec) {
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot create the folder of the tool library {}: {}"), path, ec.message())};
        }
    }
    if (sqlite3_open_v2(path.c_str(), &lib.db_->handle, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
        return Failure{describe(lib.db_->handle, path)};
    }
    sqlite3* db = lib.db_->handle;
    sqlite3_busy_timeout(db, 1500);
    exec(db, "PRAGMA foreign_keys = ON");
    Statement version(db, "PRAGMA user_version");
    if (!version.ok() || version.step() != SQLITE_ROW) {
        return Failure{describe(db, path)};
    }
    const int v = version.integer(0);
    if (v > kSchemaVersion) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} was written by a newer Taiwa (tool library version {}); this program reads version {}"),
                                   path, v, kSchemaVersion)};
    }
    if (v == 0) {
        // A new file: create the schema and the default library in one transaction.
        Statement tables(db, "SELECT count(*) FROM sqlite_master");
        if (!tables.ok() || tables.step() != SQLITE_ROW || tables.integer(0) != 0) {
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is an SQLite database but not a tool library"), path)};
        }
        bool ok = exec(db, "BEGIN IMMEDIATE") && exec(db, kSchema);
        for (const auto& t : defaultToolLibrary()) ok = ok && insert(db, t);
        if (!ok || !exec(db, "COMMIT")) {
            const std::string why = describe(db, path);
            exec(db, "ROLLBACK");
            return Failure{why};
        }
    } else if (v < kSchemaVersion) {
        // An older library: every migration from its version on, in one transaction.
        bool ok = exec(db, "BEGIN IMMEDIATE");
        for (int from = v; ok && from < kSchemaVersion; ++from) ok = exec(db, kMigrations[from - 1]);
        if (v < 4) ok = ok && addFreeTools(db, defaultLatheTools());
        if (v < 6) ok = ok && addFreeTools(db, defaultHoleTools());
        if (v < 7) ok = ok && addBuiltInNames(db);
        if (!ok || !exec(db, "COMMIT")) {
            const std::string why = describe(db, path);
            exec(db, "ROLLBACK");
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} (while upgrading it from tool library version {})"), why, v)};
        }
    }
    return lib;
}

Result<std::vector<Tool>> ToolLibrary::tools() const
{
    sqlite3* db = db_->handle;
    const std::string sql = fmt::format("SELECT id, {} FROM tools ORDER BY id", kToolColumns);
    Statement s(db, sql.c_str());
    if (!s.ok()) {
        return Failure{describe(db, path_)};
    }
    std::vector<Tool> out;
    int rc;
    while ((rc = s.step()) == SQLITE_ROW) {
        // A number column holding text ('abc') would read as 0: named instead.
        static constexpr std::pair<int, const char*> kNumbers[] = {
            {3, "diameter"}, {4, "corner_radius"}, {5, "taper_angle"}, {6, "point_angle"}, {7, "flute_length"},
            {8, "stickout"}, {10, "flutes"}, {11, "life_minutes"}, {12, "used_minutes"}, {13, "centre_cutting"},
            {15, "holder_diameter"}, {16, "holder_length"}};
        for (const auto& [column, name] : kNumbers) {
            const int kind = sqlite3_column_type(s.get(), column);
            if (kind != SQLITE_INTEGER && kind != SQLITE_FLOAT)
                return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool {}: {} is '{}', not a number"), path_, s.integer(0), name,
                                           s.text(column).substr(0, 40))};
        }
        auto t = toolFromRow(s, path_);
        if (!t) return Failure{t.error()};
        out.push_back(std::move(*t));
    }
    if (rc != SQLITE_DONE) {
        return Failure{describe(db, path_)};
    }
    Statement c(db, "SELECT tool_id, material, surface_speed, feed_per_tooth, plunge_factor FROM cutting_data ORDER BY tool_id, rowid");
    while (c.ok() && (rc = c.step()) == SQLITE_ROW) {
        const int id = c.integer(0);
        for (auto& t : out)
            if (t.id == id) t.cutting.push_back({c.text(1), c.real(2), c.real(3), c.real(4)});
    }
    if (!c.ok() || rc != SQLITE_DONE) {
        return Failure{describe(db, path_)};
    }
    Statement n(db, "SELECT tool_id, language, name FROM tool_names");
    while (n.ok() && (rc = n.step()) == SQLITE_ROW)
        for (auto& t : out)
            if (t.id == n.integer(0)) t.names[n.text(1)] = n.text(2);
    if (!n.ok() || rc != SQLITE_DONE) {
        return Failure{describe(db, path_)};
    }
    // Values no tool can have would fail deep in planning: named here.
    for (const Tool& t : out)
        if (const auto problems = toolProblems(t); !problems.empty())
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool T{} ({}): {}"), path_, t.id, t.name, problems.front().message)};
    return out;
}

Result<int> ToolLibrary::save(const Tool& tool)
{
    sqlite3* db = db_->handle;
    Tool t = tool;
    bool ok = exec(db, "BEGIN IMMEDIATE");
    if (ok && t.id == 0) {
        Statement s(db, "SELECT coalesce(max(id), 0) + 1 FROM tools");
        ok = s.ok() && s.step() == SQLITE_ROW;
        t.id = ok ? s.integer(0) : 0;
    }
    // The change log's row, in the same transaction: the tool as it was, if it was.
    const std::optional<Tool> before = ok ? stored(t.id) : std::nullopt;
    if (ok && before != t) {
        Statement e(db, "SELECT 1 FROM tools WHERE id = ?");
        e.bind(1, t.id);
        const bool existed = e.ok() && e.step() == SQLITE_ROW;
        ok = logToolChange(db, existed ? "change" : "add", t.id, before ? toolJson(*before) : "", toolJson(t)).ok();
    }
    if (!ok || !insert(db, t) || !exec(db, "COMMIT")) {
        const std::string why = describe(db, path_);
        exec(db, "ROLLBACK");
        return Failure{why};
    }
    return t.id;
}

namespace {

// Runs a one-tool statement; a failure when it fails or the tool does not exist.
Result<void> changeOne(sqlite3* db, Statement& s, int id, const std::string& path)
{
    if (!s.ok() || s.step() != SQLITE_DONE) return Failure{describe(db, path)};
    if (sqlite3_changes(db) == 0) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no tool T{}"), path, id)};
    return {};
}

}  // namespace

Result<void> ToolLibrary::remove(int id)
{
    sqlite3* db = db_->handle;
    if (!exec(db, "BEGIN IMMEDIATE")) return Failure{describe(db, path_)};
    const std::optional<Tool> old = stored(id);
    Result<void> done = old ? logToolChange(db, "remove", id, toolJson(*old), "") : Result<void>{};
    if (done) {
        Statement s(db, "DELETE FROM tools WHERE id = ?");
        s.bind(1, id);
        done = changeOne(db, s, id, path_);
    }
    if (!done || !exec(db, "COMMIT")) {
        const std::string why = done ? describe(db, path_) : done.error();
        exec(db, "ROLLBACK");
        return Failure{why};
    }
    return {};
}

Result<std::vector<ToolChangeRecord>> ToolLibrary::history(int id) const { return readToolChanges(db_->handle, id); }

std::optional<Tool> ToolLibrary::stored(int id) const
{
    auto all = tools();  // a damaged library: the log has no old values (the edit itself is not refused)
    if (all)
        for (Tool& t : *all)
            if (t.id == id) return std::move(t);
    return std::nullopt;
}

Result<void> ToolLibrary::addUsage(int id, double minutes)
{
    Statement s(db_->handle, "UPDATE tools SET used_minutes = used_minutes + ? WHERE id = ?");
    s.bind(1, minutes);
    s.bind(2, id);
    return changeOne(db_->handle, s, id, path_);
}

Result<void> ToolLibrary::replaceAll(const std::vector<Tool>& tools)
{
    sqlite3* db = db_->handle;
    bool ok = exec(db, "BEGIN IMMEDIATE") && exec(db, "DELETE FROM cutting_data; DELETE FROM tool_names; DELETE FROM tools");
    for (const Tool& t : tools) ok = ok && insert(db, t);
    if (!ok || !exec(db, "COMMIT")) {
        const std::string why = describe(db, path_);
        exec(db, "ROLLBACK");
        return Failure{why};
    }
    return {};
}

Result<std::vector<Tool>> readToolLibrary(const std::string& path)
{
    if (isServerSetting(path)) {
        auto store = openToolStore(path);
        if (!store) return Failure{store.error()};
        return (*store)->tools();
    }
    auto lib = ToolLibrary::open(path);
    if (!lib) return Failure{lib.error()};
    return lib->tools();
}

}  // namespace taiwa
