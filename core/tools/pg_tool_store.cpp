// The tool crib on a PostgreSQL server through libpq (docs/shop-server.md):
// connecting, the migrations of resources/db/, opening the store and the
// statements of the job store. Its other concerns have files of their own
// (pg_store_impl.h): tool rows, the station's copy, the change log and
// LISTEN/NOTIFY. Every statement is parameterised (PQexecParams); the only
// SQL sent as text is these files' own and the migration files.
#include "tools/pg_store_impl.h"

#include "tools/tool_library.h"
#include "model/translate_noop.h"

#include "db_migrations.h"

#include <fmt/format.h>

#include <charconv>
#include <cstring>
#include <map>

namespace taiwa {

using namespace pq;

int latestShopSchemaVersion() { return std::size(db::kMigrations) == 0 ? 0 : std::end(db::kMigrations)[-1].version; }

namespace pq {

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

}  // namespace pq

namespace {

constexpr long kMigrationLock = 0x7461697761;  // "taiwa": one station migrates at a time

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

void PgToolStore::Impl::disconnect()
{
    if (conn) PQfinish(conn);
    conn = nullptr;
}

std::string PgToolStore::Impl::error() const { return conn ? trimmed(PQerrorMessage(conn)) : std::string("not connected"); }

Result<void> PgToolStore::Impl::connect()
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
Result<PgResult> PgToolStore::Impl::exec(const char* sql, const std::vector<Param>& params)
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

void PgToolStore::Impl::rollback()
{
    if (conn && PQstatus(conn) == CONNECTION_OK && PQtransactionStatus(conn) != PQTRANS_IDLE) PgResult(PQexec(conn, "ROLLBACK"));
}

Failure PgToolStore::Impl::failure(const std::string& what, const std::string& why)
{
    return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {} failed ({})"), display, what, why)};
}

Result<int> PgToolStore::Impl::version()
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
Result<void> PgToolStore::Impl::migrate()
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

// A statement failed: was it the connection? Then the station works on
// from the copy.
void PgToolStore::Impl::checkConnection()
{
    if (conn && PQstatus(conn) == CONNECTION_BAD) (void)goOffline(error());
}

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

}  // namespace taiwa
