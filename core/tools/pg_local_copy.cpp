// The station's copy of the shop server's library (pg_store_impl.h): an
// SQLite tool library with the time it was taken, refreshed on every read
// of a changed library, and read (read-only) while the server is away.
#include "tools/pg_store_impl.h"

#include "tools/tool_library.h"
#include "model/translate_noop.h"

#include <fmt/format.h>
#include <sqlite3.h>

#include <filesystem>

namespace taiwa {

using namespace pq;

// The local copy: the server's library as an SQLite tool library with
// the time it was taken, replaced whole (written beside, then renamed).
Result<void> PgToolStore::Impl::writeCopy(const std::vector<VersionedTool>& tools)
{
    if (options.copyPath.empty()) return {};
    std::string fingerprint = std::to_string(tools.size());
    for (const auto& v : tools) fingerprint += fmt::format(",{}:{}", v.tool.id, v.version);
    if (fingerprint == copyFingerprint) return {};
    const std::string tmp = options.copyPath + ".new";
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    {
        auto lib = ToolLibrary::open(tmp);
        if (!lib) return Failure{lib.error()};
        std::vector<Tool> plain;
        for (const auto& v : tools) plain.push_back(v.tool);
        if (auto r = lib->replaceAll(plain); !r) return r;
    }
    sqlite3* db = nullptr;
    bool ok = sqlite3_open(tmp.c_str(), &db) == SQLITE_OK;
    sqlite3_stmt* s = nullptr;
    ok = ok && sqlite3_exec(db, "CREATE TABLE server_copy (server TEXT NOT NULL, synced_at TEXT NOT NULL)", nullptr, nullptr, nullptr) == SQLITE_OK;
    ok = ok && sqlite3_prepare_v2(db, "INSERT INTO server_copy VALUES (?, ?)", -1, &s, nullptr) == SQLITE_OK;
    if (ok) {
        sqlite3_bind_text(s, 1, display.c_str(), -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 2, utcNow().c_str(), -1, SQLITE_TRANSIENT);
        ok = sqlite3_step(s) == SQLITE_DONE;
    }
    sqlite3_finalize(s);
    sqlite3_close(db);
    if (!ok) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the local copy {} could not be written"), display, options.copyPath)};
    std::filesystem::rename(tmp, options.copyPath, ec);
    if (ec) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the local copy {} could not be written ({})"), display, options.copyPath, ec.message())};
    copyFingerprint = fingerprint;
    return {};
}

// Switches to the copy; a failure when there is none.
Result<void> PgToolStore::Impl::goOffline(const std::string& why)
{
    disconnect();
    listening = false;
    offline = true;
    offlineWhy = why;
    std::error_code ec;
    if (options.copyPath.empty() || !std::filesystem::exists(options.copyPath, ec))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot be reached ({}) and this station has no copy of its tools yet"),
                                   display, why)};
    auto read = readToolLibrary(options.copyPath);
    if (!read) return Failure{read.error()};
    copyTools = std::move(*read);
    copyAsOf.clear();
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(options.copyPath.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db, "SELECT synced_at FROM server_copy", -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW)
            copyAsOf = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
        sqlite3_finalize(s);
    }
    sqlite3_close(db);
    return {};
}

// Online again: schema, a fresh read for the copy, LISTEN renewed.
Result<void> PgToolStore::Impl::comeOnline(bool listen)
{
    if (auto r = migrate(); !r) return r;
    auto tools = readTools();
    if (!tools) return failure("reading the tools", tools.error());
    // A copy that cannot be written (a read-only home) leaves the station
    // working online, without a copy for when the server is away.
    (void)writeCopy(*tools);
    offline = false;
    offlineWhy.clear();
    if (listen) {
        if (auto r = exec("LISTEN taiwa_tools"); !r) return failure("LISTEN", r.error());
        listening = true;
    }
    return {};
}

Failure PgToolStore::Impl::refusedOffline()
{
    return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "{} cannot be reached ({}): the tools are as of {} and cannot be edited until it is back"),
                               display, offlineWhy, copyAsOf.empty() ? std::string("an unknown time") : copyAsOf)};
}

std::string PgToolStore::asOf() const { return d_->offline ? d_->copyAsOf : std::string(); }

std::string PgToolStore::status() const
{
    if (d_->offline)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tools as of {} (read only: {} cannot be reached)"),
                           d_->copyAsOf.empty() ? std::string("?") : d_->copyAsOf, d_->display);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tools: {}"), d_->display);
}

// In English, as the whole sheet is.
std::string PgToolStore::origin() const
{
    if (d_->offline)
        return fmt::format("Tools as of {} (server {} away, read-only copy)",
                           d_->copyAsOf.empty() ? std::string("an unknown time") : d_->copyAsOf, d_->display);
    return fmt::format("Tools from the library of {} as of {}", d_->display, d_->readAsOf);
}

}  // namespace taiwa
