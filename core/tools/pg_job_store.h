// The shop's job store on the same PostgreSQL server as the tool crib
// (docs/shop-server.md, "The job store"): a job's file text saved and opened
// by name, every version kept with who saved it from which station and
// when, and a shop-wide lock while a station edits the job. Files stay the
// default; the store is an option (`taiwa export --from-store NAME`).
#pragma once

#include "tools/pg_tool_store.h"

namespace taiwa {

struct JobVersionInfo {
    int version = 0;
    std::string who, station, at;  // at: UTC, ISO 8601
};

// A job of the store: its newest version, and who holds its lock (empty: no one).
struct StoredJob {
    std::string name;
    JobVersionInfo newest;
    std::string lockedStation, lockedBy, lockedAt;
};

// Who holds a job's lock, and whether that station is connected to the
// server now (a session of the database under the station's name, other
// than the asking one's: its window is running, the lock is not stale).
struct JobLock {
    std::string job, station, by, at;  // at: UTC, ISO 8601
    bool stationConnected = false;
};

// A stored job's name made safe for a file name (its exported files' stem):
// letters, digits, '-', '_' and '.' kept, anything else '_'.
std::string jobFileStem(const std::string& name);

class PgJobStore {
public:
    // On a connected tool store (the same server and connection).
    explicit PgJobStore(PgToolStore& server) : server_(server) {}
    // Saves a new version of job `name`; refused while another station
    // holds its lock. The version number saved.
    Result<int> save(const std::string& name, const std::string& content);
    // The text of a version (0: the newest).
    Result<std::string> load(const std::string& name, int version = 0);
    Result<std::vector<JobVersionInfo>> history(const std::string& name);
    Result<std::vector<std::string>> names();
    // Every job with a version, by name.
    Result<std::vector<StoredJob>> list();
    // Takes the job's lock for this station (taken again: fine); refused,
    // naming the station, who and since when, while another holds it.
    Result<void> lock(const std::string& name);
    // Gives this station's lock back (no lock: nothing to do).
    Result<void> unlock(const std::string& name);
    // Every job whose lock is held, by name.
    Result<std::vector<JobLock>> locks();
    // Releases job `name`'s lock whoever holds it (the administrator's
    // `taiwa store unlock`, a lock left by a station that crashed): refused,
    // naming the holder, while the holding station is connected, unless
    // `force`. The lock released; nullopt when no one held it; refused when
    // the store has no job `name`.
    Result<std::optional<JobLock>> release(const std::string& name, bool force);

private:
    PgToolStore& server_;
};

}  // namespace taiwa
