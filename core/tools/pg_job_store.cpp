// The job store on the shop server (pg_job_store.h): versions, history and
// the shop-wide lock, every statement parameterised.
#include "tools/pg_job_store.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cctype>

namespace taiwa {

namespace {


std::string utc(const char* column) { return fmt::format("to_char({} AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS\"Z\"')", column); }

// A lock's columns of table jobs (as j): the job, station, who, since when,
// and whether the station has a session on this database other than the
// asking one (application_name is the station's name, cut to 63 bytes as the
// server cuts it; every role may read it in pg_stat_activity).
std::string lockColumns()
{
    return "j.name, j.locked_station, coalesce(j.locked_by, ''), coalesce(" + utc("j.locked_at") +
           ", ''), EXISTS (SELECT 1 FROM pg_stat_activity a WHERE a.datname = current_database() "
           "AND a.application_name = left(j.locked_station, 63) AND a.pid <> pg_backend_pid())";
}

JobLock lockFrom(const std::vector<std::string>& row) { return {row[0], row[1], row[2], row[3], row[4] == "t"}; }

}  // namespace

std::string jobFileStem(const std::string& name)
{
    std::string stem;
    for (char c : name) stem += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
    return stem;
}

Result<int> PgJobStore::save(const std::string& name, const std::string& content)
{
    const std::string station = server_.stationOnServer();
    if (name.empty() || name.find('\0') != std::string::npos || content.find('\0') != std::string::npos)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: job '{}': a name, and text without NUL characters, are needed"),
                                   server_.name(), name)};
    auto run = [&]() -> Result<int> {
        if (auto r = server_.query("BEGIN", {}); !r) return Failure{r.error()};
        if (auto r = server_.query("INSERT INTO jobs (name) VALUES ($1) ON CONFLICT (name) DO NOTHING", {name}); !r) return Failure{r.error()};
        auto lock = server_.query(("SELECT coalesce(locked_station, ''), coalesce(locked_by, ''), coalesce(" + utc("locked_at") +
                                   ", '') FROM jobs WHERE name = $1 FOR UPDATE")
                                      .c_str(),
                                  {name});
        if (!lock) return Failure{lock.error()};
        const auto& row = lock->front();
        if (!row[0].empty() && row[0] != station)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "job '{}' is open at station {} (by {} since {}); it was not saved"), name,
                                       row[0], row[1], row[2])};
        auto v = server_.query("INSERT INTO job_versions (job, version, content, station) "
                               "SELECT $1, coalesce(max(version), 0) + 1, $2, $3 FROM job_versions WHERE job = $1 RETURNING version",
                               {name, content, station});
        if (!v) return Failure{v.error()};
        if (auto r = server_.query("COMMIT", {}); !r) return Failure{r.error()};
        return std::stoi(v->front()[0]);
    };
    auto saved = run();
    if (!saved) {
        (void)server_.query("ROLLBACK", {});
        if (saved.error().starts_with("job '")) return saved;
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: saving job '{}' failed ({})"), server_.name(), name, saved.error())};
    }
    return saved;
}

Result<std::string> PgJobStore::load(const std::string& name, int version)
{
    auto r = version > 0 ? server_.query("SELECT content FROM job_versions WHERE job = $1 AND version = $2", {name, std::to_string(version)})
                         : server_.query("SELECT content FROM job_versions WHERE job = $1 ORDER BY version DESC LIMIT 1", {name});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: opening job '{}' failed ({})"), server_.name(), name, r.error())};
    if (r->empty())
        return Failure{version > 0 ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no version {} of job '{}'"), server_.name(), version, name)
                                   : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no job '{}'"), server_.name(), name)};
    return r->front()[0];
}

Result<std::vector<JobVersionInfo>> PgJobStore::history(const std::string& name)
{
    auto r = server_.query(("SELECT version, who, station, " + utc("at") + " FROM job_versions WHERE job = $1 ORDER BY version").c_str(), {name});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: reading the history of job '{}' failed ({})"), server_.name(), name, r.error())};
    std::vector<JobVersionInfo> out;
    for (const auto& row : *r) out.push_back({std::stoi(row[0]), row[1], row[2], row[3]});
    return out;
}

Result<std::vector<std::string>> PgJobStore::names()
{
    auto r = server_.query("SELECT name FROM jobs WHERE EXISTS (SELECT 1 FROM job_versions WHERE job = name) ORDER BY name", {});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: listing the jobs failed ({})"), server_.name(), r.error())};
    std::vector<std::string> out;
    for (const auto& row : *r) out.push_back(row[0]);
    return out;
}

Result<std::vector<StoredJob>> PgJobStore::list()
{
    auto r = server_.query(("SELECT j.name, v.version, v.who, v.station, " + utc("v.at") +
                            ", coalesce(j.locked_station, ''), coalesce(j.locked_by, ''), coalesce(" + utc("j.locked_at") +
                            ", '') FROM jobs j JOIN LATERAL (SELECT version, who, station, at FROM job_versions "
                            "WHERE job = j.name ORDER BY version DESC LIMIT 1) v ON true ORDER BY j.name")
                               .c_str(),
                           {});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: listing the jobs failed ({})"), server_.name(), r.error())};
    std::vector<StoredJob> out;
    for (const auto& row : *r) out.push_back({row[0], {std::stoi(row[1]), row[2], row[3], row[4]}, row[5], row[6], row[7]});
    return out;
}

Result<void> PgJobStore::lock(const std::string& name)
{
    const std::string station = server_.stationOnServer();
    auto r = server_.query("UPDATE jobs SET locked_by = session_user, locked_station = $2, locked_at = now() "
                           "WHERE name = $1 AND (locked_station IS NULL OR locked_station = $2) RETURNING 1",
                           {name, station});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: locking job '{}' failed ({})"), server_.name(), name, r.error())};
    if (!r->empty()) return {};
    auto holder = server_.query(("SELECT locked_station, locked_by, " + utc("locked_at") + " FROM jobs WHERE name = $1").c_str(), {name});
    if (!holder || holder->empty()) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no job '{}'"), server_.name(), name)};
    const auto& row = holder->front();
    return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "job '{}' is open at station {} (by {} since {})"), name, row[0], row[1], row[2])};
}

Result<void> PgJobStore::unlock(const std::string& name)
{
    auto r = server_.query("UPDATE jobs SET locked_by = NULL, locked_station = NULL, locked_at = NULL WHERE name = $1 AND locked_station = $2",
                           {name, server_.stationOnServer()});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: unlocking job '{}' failed ({})"), server_.name(), name, r.error())};
    return {};
}

Result<std::vector<JobLock>> PgJobStore::locks()
{
    auto r = server_.query(("SELECT " + lockColumns() + " FROM jobs j WHERE j.locked_station IS NOT NULL ORDER BY j.name").c_str(), {});
    if (!r) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: listing the jobs failed ({})"), server_.name(), r.error())};
    std::vector<JobLock> out;
    for (const auto& row : *r) out.push_back(lockFrom(row));
    return out;
}

Result<std::optional<JobLock>> PgJobStore::release(const std::string& name, bool force)
{
    // The holder read and the lock cleared in one transaction, the row held:
    // a lock taken anew meanwhile is never the one released.
    auto run = [&]() -> Result<std::optional<JobLock>> {
        if (auto r = server_.query("BEGIN", {}); !r) return Failure{r.error()};
        auto held = server_.query(("SELECT " + lockColumns() + " FROM jobs j WHERE j.name = $1 FOR UPDATE").c_str(), {name});
        if (!held) return Failure{held.error()};
        if (held->empty()) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no job '{}'"), server_.name(), name)};
        if (held->front()[1].empty()) return std::optional<JobLock>();
        const JobLock lock = lockFrom(held->front());
        if (lock.stationConnected && !force)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "job '{}' is open at station {} (by {} since {}) and that station "
                                                                           "is connected to the server now; its lock was not released"),
                                       name, lock.station, lock.by, lock.at)};
        if (auto r = server_.query("UPDATE jobs SET locked_by = NULL, locked_station = NULL, locked_at = NULL WHERE name = $1", {name}); !r)
            return Failure{r.error()};
        if (auto r = server_.query("COMMIT", {}); !r) return Failure{r.error()};
        return std::optional<JobLock>(lock);
    };
    auto released = run();
    if (!released || !*released) (void)server_.query("ROLLBACK", {});
    if (!released && !released.error().starts_with("job '") && released.error().find(" has no job '") == std::string::npos)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: unlocking job '{}' failed ({})"), server_.name(), name, released.error())};
    return released;
}

}  // namespace taiwa
