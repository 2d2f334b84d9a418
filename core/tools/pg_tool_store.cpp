// The tool crib on a PostgreSQL server through libpq (docs/shop-server.md):
// connecting, the migrations of resources/db/, reading and saving tools by
// row version, LISTEN/NOTIFY, and the local SQLite copy for when the server
// is away. Every statement is parameterised (PQexecParams); the only SQL sent
// as text is this file's own and the migration files.
#include "tools/pg_tool_store.h"

#include "tools/tool_check.h"
#include "tools/tool_library.h"
#include "tools/turning_text.h"
#include "model/translate_noop.h"

#include "db_migrations.h"

#include <fmt/format.h>
#include <libpq-fe.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <map>
#include <unistd.h>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <poll.h>

namespace taiwa {

int latestShopSchemaVersion() { return std::size(db::kMigrations) == 0 ? 0 : std::end(db::kMigrations)[-1].version; }

namespace {

constexpr long kMigrationLock = 0x7461697761;  // "taiwa": one station migrates at a time
constexpr long kNewIdLock = 0x7461697762;

using Param = std::optional<std::string>;

struct ResultDeleter {
    void operator()(PGresult* r) const { PQclear(r); }
};
using PgResult = std::unique_ptr<PGresult, ResultDeleter>;

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

std::string number(double v) { return fmt::format("{}", v); }
std::string number(long long v) { return std::to_string(v); }

double real(const PGresult* r, int row, int col)
{
    const char* t = PQgetvalue(r, row, col);
    double v = 0;
    std::from_chars(t, t + std::strlen(t), v);
    return v;
}
long long integer(const PGresult* r, int row, int col) { return std::atoll(PQgetvalue(r, row, col)); }
std::string text(const PGresult* r, int row, int col) { return std::string(PQgetvalue(r, row, col), PQgetlength(r, row, col)); }

// The tools' columns, in the order of the parameters $2…$17 ($1 is the id).
constexpr const char* kToolColumns = "name, type, diameter, corner_radius, taper_angle, point_angle, flute_length, stickout, "
                                     "holder, flutes, life_minutes, used_minutes, centre_cutting, turning, holder_diameter, holder_length";

std::vector<Param> toolParams(const Tool& t)
{
    return {std::to_string(t.id), t.name, std::string(toKey(t.type)), number(t.diameter), number(t.cornerRadius),
            number(t.taperAngle), number(t.pointAngle), number(t.fluteLength), number(t.stickout), t.holder,
            std::to_string(t.flutes), number(t.lifeMinutes), number(t.usedMinutes), std::string(t.centreCutting ? "true" : "false"),
            turningText(t.turning), number(t.holderDiameter), number(t.holderLength)};
}

// A text field holding a character the server cannot store (NUL), named.
std::optional<std::string> unstorable(const Tool& t)
{
    const auto has = [](const std::string& s) { return s.find('\0') != std::string::npos; };
    if (has(t.name)) return "name";
    if (has(t.holder)) return "holder";
    for (const auto& [language, n] : t.names)
        if (has(language) || has(n)) return "names";
    for (const auto& c : t.cutting)
        if (has(c.material)) return "cutting";
    return std::nullopt;
}

// The server as messages name it: postgresql://user@host:port/db or
// "service NAME", never a password.
std::string displayName(const std::string& conninfo)
{
    char* err = nullptr;
    PQconninfoOption* opts = PQconninfoParse(conninfo.c_str(), &err);
    if (!opts) {
        PQfreemem(err);
        return "the tool server";
    }
    std::map<std::string, std::string> v;
    for (PQconninfoOption* o = opts; o->keyword; ++o)
        if (o->val) v[o->keyword] = o->val;
    PQconninfoFree(opts);
    if (v.count("service") && !v.count("host")) return fmt::format("postgresql service {}", v["service"]);
    std::string out = "postgresql://";
    if (v.count("user")) out += v["user"] + "@";
    out += v.count("host") ? v["host"] : "localhost";
    if (v.count("port")) out += ":" + v["port"];
    if (v.count("dbname")) out += "/" + v["dbname"];
    return out;
}

}  // namespace

struct PgToolStore::Impl {
    std::string conninfo, display;
    PgStoreOptions options;
    PGconn* conn = nullptr;
    bool listening = false, wantListen = false;
    // Offline: the copy's tools and when they were taken.
    bool offline = false;
    std::string offlineWhy, copyAsOf;
    // Online: the server's time of the last whole read (UTC, ISO 8601).
    std::string readAsOf;
    std::vector<Tool> copyTools;
    std::string copyFingerprint;

    ~Impl() { disconnect(); }
    void disconnect()
    {
        if (conn) PQfinish(conn);
        conn = nullptr;
    }

    std::string error() const { return conn ? trimmed(PQerrorMessage(conn)) : std::string("not connected"); }

    Result<void> connect()
    {
        disconnect();
        const std::string timeout = std::to_string(options.connectTimeoutSeconds);
        const char* keys[] = {"dbname", "application_name", "connect_timeout", nullptr};
        const char* values[] = {conninfo.c_str(), options.station.c_str(), timeout.c_str(), nullptr};
        conn = PQconnectdbParams(keys, values, 1);
        if (!conn || PQstatus(conn) != CONNECTION_OK) {
            std::string why = error();
            // pg_hba.conf lets this station in over TLS only (hostssl), and the connection had none.
            if (why.find("no encryption") != std::string::npos)
                why += fmt::format("; {} lets this station in over TLS only and the connection was made without: the address must "
                                   "not say sslmode=disable (sslmode=require asks for TLS) and the server must have ssl = on "
                                   "(docs/shop-server.md, \"TLS\")",
                                   display);
            disconnect();
            return Failure{why};
        }
        PQsetNoticeProcessor(conn, [](void*, const char*) {}, nullptr);
        return {};
    }

    // One statement with its parameters; a failure is the server's message.
    Result<PgResult> exec(const char* sql, const std::vector<Param>& params = {})
    {
        if (!conn) return Failure{"not connected"};
        std::vector<const char*> values;
        std::vector<int> lengths;
        for (const auto& p : params) {
            values.push_back(p ? p->c_str() : nullptr);
            lengths.push_back(p ? static_cast<int>(p->size()) : 0);
        }
        PgResult r(params.empty() ? PQexec(conn, sql)
                                  : PQexecParams(conn, sql, static_cast<int>(params.size()), nullptr, values.data(), lengths.data(), nullptr, 0));
        const auto status = r ? PQresultStatus(r.get()) : PGRES_FATAL_ERROR;
        if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
            std::string why = r ? trimmed(PQresultErrorMessage(r.get())) : error();
            if (why.empty()) why = error();
            return Failure{why};
        }
        return r;
    }
    void rollback()
    {
        if (conn && PQstatus(conn) == CONNECTION_OK && PQtransactionStatus(conn) != PQTRANS_IDLE) PgResult(PQexec(conn, "ROLLBACK"));
    }
    Failure failure(const std::string& what, const std::string& why)
    {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {} failed ({})"), display, what, why)};
    }

    Result<int> version()
    {
        auto exists = exec("SELECT to_regclass('taiwa_schema') IS NOT NULL");
        if (!exists) return Failure{exists.error()};
        if (text(exists->get(), 0, 0) != "t") return 0;
        auto v = exec("SELECT coalesce(max(version), 0) FROM taiwa_schema");
        if (!v) return Failure{v.error()};
        return static_cast<int>(integer(v->get(), 0, 0));
    }

    // Brings the schema to the newest version, in one transaction, one
    // station at a time; an empty database gets the default library.
    Result<void> migrate()
    {
        auto v = version();
        if (!v) return failure("reading the schema version", v.error());
        const int latest = latestShopSchemaVersion();
        if (*v > latest)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} was set up by a newer Taiwa (schema version {}); this program knows version {}"),
                                       display, *v, latest)};
        if (*v == latest) return {};
        auto step = [&]() -> Result<void> {
            for (const char* sql : {"BEGIN", "SET LOCAL client_min_messages = warning"})
                if (auto r = exec(sql); !r) return Failure{r.error()};
            if (auto r = exec("SELECT pg_advisory_xact_lock($1)", {number(static_cast<long long>(kMigrationLock))}); !r) return Failure{r.error()};
            if (auto r = exec("CREATE TABLE IF NOT EXISTS taiwa_schema (version integer PRIMARY KEY, file text NOT NULL, "
                              "applied_at timestamptz NOT NULL DEFAULT now(), applied_by text NOT NULL DEFAULT session_user)");
                !r)
                return Failure{r.error()};
            auto now = version();  // another station may have done it meanwhile
            if (!now) return Failure{now.error()};
            for (const auto& m : db::kMigrations) {
                if (m.version <= *now) continue;
                if (auto r = exec(m.sql); !r) return Failure{fmt::format("{}: {}", m.file, r.error())};
                if (auto r = exec("INSERT INTO taiwa_schema (version, file) VALUES ($1, $2)", {std::to_string(m.version), std::string(m.file)}); !r)
                    return Failure{r.error()};
            }
            if (*now == 0)
                for (const Tool& t : defaultToolLibrary())
                    if (auto r = writeTool(t, true); !r) return Failure{r.error()};
            if (auto r = exec("COMMIT"); !r) return Failure{r.error()};
            return {};
        };
        if (auto r = step(); !r) {
            rollback();
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                            "{}: the schema could not be brought from version {} to {} ({}); a station's "
                                                            "role may only read and write, the owner upgrades it (docs/shop-server.md)"),
                                       display, *v, latest, r.error())};
        }
        return {};
    }

    // Writes a tool's rows (inside a transaction). `fresh`: an INSERT that
    // fails on an existing id; else an UPDATE at `readVersion`. The new
    // version, or 0 when no row was written (the version moved on, or the id
    // is taken).
    Result<std::int64_t> writeTool(const Tool& t, bool fresh, std::int64_t readVersion = 0)
    {
        std::vector<Param> p = toolParams(t);
        Result<PgResult> r = Failure{""};
        if (fresh) {
            r = exec(fmt::format("INSERT INTO tools (id, {}) VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9,$10,$11,$12,$13,$14,$15,$16,$17) "
                                 "ON CONFLICT (id) DO NOTHING RETURNING row_version",
                                 kToolColumns)
                         .c_str(),
                     p);
        } else {
            p.push_back(number(static_cast<long long>(readVersion)));
            r = exec("UPDATE tools SET name=$2, type=$3, diameter=$4, corner_radius=$5, taper_angle=$6, point_angle=$7, "
                     "flute_length=$8, stickout=$9, holder=$10, flutes=$11, life_minutes=$12, used_minutes=$13, "
                     "centre_cutting=$14, turning=$15, holder_diameter=$16, holder_length=$17 "
                     "WHERE id=$1 AND row_version=$18 RETURNING row_version",
                     p);
        }
        if (!r) return Failure{r.error()};
        if (PQntuples(r->get()) == 0) return std::int64_t{0};
        const std::int64_t version = integer(r->get(), 0, 0);
        const std::string id = std::to_string(t.id);
        for (const char* del : {"DELETE FROM cutting_data WHERE tool_id = $1", "DELETE FROM tool_names WHERE tool_id = $1"})
            if (auto d = exec(del, {id}); !d) return Failure{d.error()};
        for (const auto& [language, name] : t.names)
            if (auto n = exec("INSERT INTO tool_names (tool_id, language, name) VALUES ($1,$2,$3)", {id, language, name}); !n)
                return Failure{n.error()};
        int position = 0;
        for (const auto& c : t.cutting)
            if (auto cd = exec("INSERT INTO cutting_data (tool_id, material, position, surface_speed, feed_per_tooth, plunge_factor) "
                               "VALUES ($1,$2,$3,$4,$5,$6)",
                               {id, c.material, std::to_string(position++), number(c.surfaceSpeed), number(c.feedPerTooth), number(c.plungeFactor)});
                !cd)
                return Failure{cd.error()};
        return version;
    }

    // Every tool (one consistent snapshot), or one tool when `only` > 0.
    Result<std::vector<VersionedTool>> readTools(int only = 0)
    {
        const std::string where = only > 0 ? " WHERE id = $1" : "";
        const std::string whereTool = only > 0 ? " WHERE tool_id = $1" : "";
        const std::vector<Param> params = only > 0 ? std::vector<Param>{std::to_string(only)} : std::vector<Param>{};
        // The snapshot's time comes with BEGIN, in the same round trip.
        auto begin = exec("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY; "
                          "SELECT to_char(now() AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS\"Z\"')");
        if (!begin) return Failure{begin.error()};
        const std::string asOf = text(begin->get(), 0, 0);
        auto q = [&](const std::string& sql) { return params.empty() ? exec(sql.c_str()) : exec(sql.c_str(), params); };
        auto rows = q(fmt::format("SELECT id, {}, row_version FROM tools{} ORDER BY id", kToolColumns, where));
        auto cuts = rows ? q("SELECT tool_id, material, surface_speed, feed_per_tooth, plunge_factor FROM cutting_data" + whereTool +
                             " ORDER BY tool_id, position")
                         : Result<PgResult>(Failure{rows.error()});
        auto names = cuts ? q("SELECT tool_id, language, name FROM tool_names" + whereTool) : Result<PgResult>(Failure{cuts.error()});
        if (!names) {
            rollback();
            return Failure{names.error()};
        }
        (void)exec("COMMIT");
        std::vector<VersionedTool> out;
        const PGresult* r = rows->get();
        for (int i = 0; i < PQntuples(r); ++i) {
            VersionedTool v;
            Tool& t = v.tool;
            t.id = static_cast<int>(integer(r, i, 0));
            t.name = text(r, i, 1);
            const auto type = toolTypeFromKey(text(r, i, 2));
            if (!type)
                return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool {} has an unknown type '{}'"), display, t.id, text(r, i, 2))};
            t.type = *type;
            t.diameter = real(r, i, 3);
            t.cornerRadius = real(r, i, 4);
            t.taperAngle = real(r, i, 5);
            t.pointAngle = real(r, i, 6);
            t.fluteLength = real(r, i, 7);
            t.stickout = real(r, i, 8);
            t.holder = text(r, i, 9);
            t.flutes = static_cast<int>(integer(r, i, 10));
            t.lifeMinutes = real(r, i, 11);
            t.usedMinutes = real(r, i, 12);
            t.centreCutting = text(r, i, 13) == "t";
            const auto turning = turningFrom(text(r, i, 14));
            if (!turning)
                return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool {} has unreadable lathe data '{}'"), display, t.id, text(r, i, 14))};
            t.turning = *turning;
            t.holderDiameter = real(r, i, 15);
            t.holderLength = real(r, i, 16);
            v.version = integer(r, i, 17);
            out.push_back(std::move(v));
        }
        const auto find = [&](int id) -> Tool* {
            const auto it = std::lower_bound(out.begin(), out.end(), id, [](const VersionedTool& v, int x) { return v.tool.id < x; });
            return it != out.end() && it->tool.id == id ? &it->tool : nullptr;
        };
        for (int i = 0; i < PQntuples(cuts->get()); ++i)
            if (Tool* t = find(static_cast<int>(integer(cuts->get(), i, 0))))
                t->cutting.push_back({text(cuts->get(), i, 1), real(cuts->get(), i, 2), real(cuts->get(), i, 3), real(cuts->get(), i, 4)});
        for (int i = 0; i < PQntuples(names->get()); ++i)
            if (Tool* t = find(static_cast<int>(integer(names->get(), i, 0)))) t->names[text(names->get(), i, 1)] = text(names->get(), i, 2);
        for (const auto& v : out)
            if (const auto problems = toolProblems(v.tool); !problems.empty())
                return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool T{} ({}): {}"), display, v.tool.id, v.tool.name,
                                           problems.front().message)};
        if (only == 0) readAsOf = asOf;
        return out;
    }

    // The local copy: the server's library as an SQLite tool library with
    // the time it was taken, replaced whole (written beside, then renamed).
    Result<void> writeCopy(const std::vector<VersionedTool>& tools)
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
    Result<void> goOffline(const std::string& why)
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
    Result<void> comeOnline(bool listen)
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

    Failure refusedOffline()
    {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                        "{} cannot be reached ({}): the tools are as of {} and cannot be edited until it is back"),
                                   display, offlineWhy, copyAsOf.empty() ? std::string("an unknown time") : copyAsOf)};
    }

    // A statement failed: was it the connection? Then the station works on
    // from the copy.
    void checkConnection()
    {
        if (conn && PQstatus(conn) == CONNECTION_BAD) (void)goOffline(error());
    }
};

PgToolStore::PgToolStore() : d_(std::make_unique<Impl>()) {}
PgToolStore::~PgToolStore() = default;

Result<std::unique_ptr<PgToolStore>> PgToolStore::open(const std::string& conninfo, PgStoreOptions options)
{
    std::unique_ptr<PgToolStore> store(new PgToolStore());
    Impl& d = *store->d_;
    d.conninfo = conninfo;
    d.display = displayName(conninfo);
    if (options.station.empty()) options.station = stationName();
    d.options = options;
    char* err = nullptr;
    PQconninfoOption* opts = PQconninfoParse(conninfo.c_str(), &err);
    if (!opts) {
        const std::string why = err ? trimmed(err) : "unreadable";
        PQfreemem(err);
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "TAIWA_TOOL_DB: '{}' is not a server address ({})"), d.display, why)};
    }
    bool password = false;
    for (PQconninfoOption* o = opts; o->keyword; ++o)
        if (std::string(o->keyword) == "password" && o->val && *o->val) password = true;
    PQconninfoFree(opts);
    if (password)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "TAIWA_TOOL_DB: the address of {} holds a password; put it in ~/.pgpass or "
                                                                      "the service file instead (docs/shop-server.md)"),
                                   d.display)};
    if (auto c = d.connect(); !c) {
        if (auto off = d.goOffline(c.error()); !off) return Failure{off.error()};
        return store;
    }
    if (auto r = d.comeOnline(false); !r) return Failure{r.error()};
    return store;
}

std::string PgToolStore::name() const { return d_->display; }
std::string PgToolStore::whyOffline() const { return d_->offline ? d_->offlineWhy : std::string(); }
bool PgToolStore::readOnly() const { return d_->offline; }
std::string PgToolStore::asOf() const { return d_->offline ? d_->copyAsOf : std::string(); }
int PgToolStore::socket() const { return d_->conn ? PQsocket(d_->conn) : -1; }

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

Result<void> PgToolStore::reconnect()
{
    if (auto c = d_->connect(); !c) {
        if (auto off = d_->goOffline(c.error()); !off) return off;
        return Failure{d_->refusedOffline().message};
    }
    return d_->comeOnline(d_->wantListen);
}

Result<int> PgToolStore::schemaVersion()
{
    if (d_->offline) return d_->refusedOffline();
    auto v = d_->version();
    if (!v) return d_->failure("reading the schema version", v.error());
    return v;
}

Result<std::vector<VersionedTool>> PgToolStore::versionedTools()
{
    if (!d_->offline) {
        auto tools = d_->readTools();
        if (tools) {
            (void)d_->writeCopy(*tools);
            return tools;
        }
        d_->checkConnection();
        if (!d_->offline) return d_->failure("reading the tools", tools.error());
    }
    std::vector<VersionedTool> out;
    for (const Tool& t : d_->copyTools) out.push_back({t, 0});
    return out;
}

Result<SaveOutcome> PgToolStore::save(const Tool& tool, std::int64_t readVersion)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    if (const auto field = unstorable(tool))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool T{} ({}) holds a NUL character, which the server cannot store"),
                                   d.display, tool.id, *field)};
    Tool t = tool;
    auto attempt = [&]() -> Result<std::int64_t> {
        if (auto r = d.exec("BEGIN"); !r) return Failure{r.error()};
        if (t.id == 0) {
            if (auto r = d.exec("SELECT pg_advisory_xact_lock($1)", {number(static_cast<long long>(kNewIdLock))}); !r) return Failure{r.error()};
            auto next = d.exec("SELECT coalesce(max(id), 0) + 1 FROM tools");
            if (!next) return Failure{next.error()};
            t.id = static_cast<int>(integer(next->get(), 0, 0));
        }
        auto written = d.writeTool(t, readVersion == 0, readVersion);
        if (!written) return written;
        if (*written == 0) {
            d.rollback();
            return std::int64_t{0};
        }
        if (beforeCommit) beforeCommit();
        if (auto r = d.exec("COMMIT"); !r) return Failure{r.error()};
        return written;
    };
    auto version = attempt();
    if (!version) {
        d.rollback();
        const std::string why = version.error();
        d.checkConnection();
        return d.failure(fmt::format("saving tool T{}", t.id), why);
    }
    if (*version > 0) return SaveOutcome{t.id, *version, std::nullopt};
    // Refused: what the server holds now, and who changed it last.
    ToolConflict conflict;
    conflict.mine = t;
    auto theirs = d.readTools(t.id);
    if (!theirs) {
        d.checkConnection();
        return d.failure(fmt::format("reading tool T{}", t.id), theirs.error());
    }
    if (!theirs->empty()) {
        conflict.theirs = theirs->front().tool;
        conflict.theirVersion = theirs->front().version;
    }
    auto last = d.exec("SELECT who, station, to_char(at AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS\"Z\"') FROM tool_changes "
                       "WHERE tool_id = $1 ORDER BY id DESC LIMIT 1",
                       {std::to_string(t.id)});
    if (last && PQntuples(last->get()) == 1) {
        conflict.changedBy = text(last->get(), 0, 0);
        conflict.station = text(last->get(), 0, 1);
        conflict.changedAt = text(last->get(), 0, 2);
    }
    return SaveOutcome{t.id, conflict.theirVersion, std::move(conflict)};
}

Result<void> PgToolStore::remove(int id)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    auto r = d.exec("DELETE FROM tools WHERE id = $1", {std::to_string(id)});
    if (!r) {
        const std::string why = r.error();
        d.checkConnection();
        return d.failure(fmt::format("removing tool T{}", id), why);
    }
    if (std::string(PQcmdTuples(r->get())) == "0") return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no tool T{}"), d.display, id)};
    return {};
}

Result<void> PgToolStore::addUsage(int id, double minutes)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    auto r = d.exec("UPDATE tools SET used_minutes = used_minutes + $2 WHERE id = $1", {std::to_string(id), number(minutes)});
    if (!r) {
        const std::string why = r.error();
        d.checkConnection();
        return d.failure(fmt::format("adding usage to tool T{}", id), why);
    }
    if (std::string(PQcmdTuples(r->get())) == "0") return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no tool T{}"), d.display, id)};
    return {};
}

Result<int> PgToolStore::importSqliteLibrary(const std::string& path)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    // The shop's file is read from a copy: opening upgrades an older file in place.
    const std::string copy = (std::filesystem::temp_directory_path() / fmt::format("taiwa-import-{}.sqlite", ::getpid())).string();
    std::error_code ec;
    std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing, ec);
    if (ec) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot be read ({})"), path, ec.message())};
    auto tools = readToolLibrary(copy);
    std::filesystem::remove(copy, ec);
    if (!tools) return Failure{tools.error()};
    auto run = [&]() -> Result<void> {
        if (auto r = d.exec("BEGIN"); !r) return Failure{r.error()};
        if (auto r = d.exec("DELETE FROM tools"); !r) return Failure{r.error()};
        for (const Tool& t : *tools) {
            if (const auto field = unstorable(t)) return Failure{fmt::format("tool T{} ({}) holds a NUL character", t.id, *field)};
            auto w = d.writeTool(t, true);
            if (!w) return Failure{w.error()};
        }
        if (auto r = d.exec("COMMIT"); !r) return Failure{r.error()};
        return {};
    };
    if (auto r = run(); !r) {
        d.rollback();
        d.checkConnection();
        return d.failure(fmt::format("importing {}", path), r.error());
    }
    return static_cast<int>(tools->size());
}

Result<std::vector<ToolChangeRecord>> PgToolStore::history(int id)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    auto r = d.exec("SELECT operation, who, station, to_char(at AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS\"Z\"'), "
                    "coalesce(old_values::text, ''), coalesce(new_values::text, '') FROM tool_changes WHERE tool_id = $1 ORDER BY id",
                    {std::to_string(id)});
    if (!r) {
        const std::string why = r.error();
        d.checkConnection();
        return d.failure(fmt::format("reading the history of tool T{}", id), why);
    }
    std::vector<ToolChangeRecord> out;
    for (int i = 0; i < PQntuples(r->get()); ++i)
        out.push_back({text(r->get(), i, 0), text(r->get(), i, 1), text(r->get(), i, 2), text(r->get(), i, 3), text(r->get(), i, 4),
                       text(r->get(), i, 5)});
    return out;
}

Result<std::vector<std::vector<std::string>>> PgToolStore::query(const char* sql, const std::vector<std::optional<std::string>>& params)
{
    Impl& d = *d_;
    if (d.offline) return d.refusedOffline();
    auto r = d.exec(sql, params);
    if (!r) {
        const std::string why = r.error();
        d.checkConnection();
        return Failure{why};
    }
    std::vector<std::vector<std::string>> rows;
    for (int i = 0; i < PQntuples(r->get()); ++i) {
        rows.emplace_back();
        for (int c = 0; c < PQnfields(r->get()); ++c) rows.back().push_back(text(r->get(), i, c));
    }
    return rows;
}

const std::string& PgToolStore::stationOnServer() const { return d_->options.station; }

Result<void> PgToolStore::listen()
{
    if (d_->offline) return d_->refusedOffline();
    if (auto r = d_->exec("LISTEN taiwa_tools"); !r) return d_->failure("LISTEN", r.error());
    d_->listening = d_->wantListen = true;
    return {};
}

std::vector<ToolChange> PgToolStore::changes(int timeoutMs)
{
    std::vector<ToolChange> out;
    PGconn* conn = d_->conn;
    if (!conn) return out;
    const int self = PQbackendPID(conn);
    const auto drain = [&] {
        PQconsumeInput(conn);
        while (PGnotify* n = PQnotifies(conn)) {
            if (n->be_pid != self) {
                const auto j = nlohmann::json::parse(n->extra, nullptr, false);
                if (j.is_object())
                    out.push_back({j.value("id", 0), j.value("version", std::int64_t{0}), j.value("operation", std::string()),
                                   j.value("who", std::string()), j.value("station", std::string())});
            }
            PQfreemem(n);
        }
    };
    drain();
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    while (out.empty() && timeoutMs > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now()).count();
        if (left <= 0) break;
        pollfd p{PQsocket(conn), POLLIN, 0};
        if (::poll(&p, 1, static_cast<int>(left)) <= 0) break;
        drain();
        if (PQstatus(conn) == CONNECTION_BAD) break;
    }
    // The connection went (the server stopped): the copy, read-only.
    if (PQstatus(conn) == CONNECTION_BAD) (void)d_->goOffline(d_->error());
    return out;
}

}  // namespace taiwa
