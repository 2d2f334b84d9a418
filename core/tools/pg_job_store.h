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

private:
    PgToolStore& server_;
};

}  // namespace taiwa
