// The shop's tool crib on a PostgreSQL server, through libpq
// (docs/shop-server.md): the schema of resources/db/ applied on connect,
// optimistic locking by row version, changes announced by LISTEN/NOTIFY,
// and a local SQLite copy read (read-only) while the server is away.
#pragma once

#include "tools/tool_change_log.h"
#include "tools/tool_store.h"

#include <functional>

namespace taiwa {

// A change of a tool announced by the server (another station's save).
struct ToolChange {
    int id = 0;
    std::int64_t version = 0;
    std::string operation;  // INSERT, UPDATE, DELETE
    std::string who, station;
};

// One row of the server's change log of a tool.
// ToolChangeRecord: tools/tool_change_log.h (the SQLite library keeps the same log).

struct PgStoreOptions {
    std::string copyPath;  // the local copy (SQLite); empty: none kept
    std::string station;   // the station's name on the server; empty: stationName()
    int connectTimeoutSeconds = 3;
};

class PgToolStore : public ToolStore {
public:
    // Connects (the password from ~/.pgpass or the service file only: an
    // address holding one is refused), brings the schema up to date, gives
    // an empty database the default library and refreshes the local copy.
    // A server that cannot be reached gives a read-only store on the copy;
    // a failure only when there is no copy either.
    static Result<std::unique_ptr<PgToolStore>> open(const std::string& conninfo, PgStoreOptions options = {});
    ~PgToolStore() override;

    std::string name() const override;
    Result<std::vector<VersionedTool>> versionedTools() override;
    Result<SaveOutcome> save(const Tool& tool, std::int64_t readVersion) override;
    Result<void> remove(int id) override;
    Result<void> addUsage(int id, double minutes) override;
    bool readOnly() const override;
    // Why the server could not be reached, while readOnly(); else empty.
    std::string whyOffline() const;
    std::string asOf() const override;
    std::string status() const override;
    std::string origin() const override;

    // Tries the server again (after it was away or a statement failed);
    // back online, the copy is refreshed and LISTEN renewed.
    Result<void> reconnect();
    // The schema version the server is at.
    Result<int> schemaVersion();
    // Replaces the server's whole library by that of an SQLite library file
    // of any version (read from a copy of it: the file is left as it is);
    // the number of tools.
    Result<int> importSqliteLibrary(const std::string& path);
    // The change log of one tool, oldest first.
    Result<std::vector<ToolChangeRecord>> history(int id);

    // LISTEN for other stations' changes; `changes` returns those announced
    // since, waiting up to `timeoutMs` for the first (0: only what is there).
    Result<void> listen();
    std::vector<ToolChange> changes(int timeoutMs);
    // The connection's socket, for a QSocketNotifier (-1 when offline).
    int socket() const;

    // Tests only: called inside a save's transaction once its rows are
    // written, before COMMIT.
    std::function<void()> beforeCommit;

private:
    friend class PgJobStore;
    // A statement for the job store: its rows as text (NULL as ""), or
    // the server's message; nullopt parameters are NULL.
    Result<std::vector<std::vector<std::string>>> query(const char* sql, const std::vector<std::optional<std::string>>& params);
    const std::string& stationOnServer() const;
    PgToolStore();
    struct Impl;
    std::unique_ptr<Impl> d_;
};

// The number of the newest migration of resources/db/ this program knows.
int latestShopSchemaVersion();

}  // namespace taiwa
