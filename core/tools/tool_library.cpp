// The tool library in SQLite: opening it (first-use creation with the
// default library, an older file upgraded), reading and editing, each edit
// with its row in the change log. Every failure is a message naming the
// file. The schema and its migrations: tool_library_schema.cpp; statements,
// failures and a tool's rows: tool_library_sqlite.cpp.
#include "tools/tool_library.h"
#include "tools/turning_text.h"

#include "tools/tool_change_log.h"
#include "tools/tool_library_schema.h"
#include "tools/tool_library_sqlite.h"
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

using tooldb::describe;
using tooldb::exec;
using tooldb::insert;
using tooldb::kSchemaVersion;
using tooldb::Statement;

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
        const bool ok = exec(db, "BEGIN IMMEDIATE") && tooldb::createSchema(db);
        if (!ok || !exec(db, "COMMIT")) {
            const std::string why = describe(db, path);
            exec(db, "ROLLBACK");
            return Failure{why};
        }
    } else if (v < kSchemaVersion) {
        // An older library: every migration from its version on, in one transaction.
        const bool ok = exec(db, "BEGIN IMMEDIATE") && tooldb::upgradeSchema(db, v);
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
        if (!t) return t.failure();
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
        if (!store) return store.failure();
        return (*store)->tools();
    }
    auto lib = ToolLibrary::open(path);
    if (!lib) return lib.failure();
    return lib->tools();
}

}  // namespace taiwa
