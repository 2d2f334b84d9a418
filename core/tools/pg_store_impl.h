// Inside the shop server's tool store (pg_tool_store.h), for its own files
// alone (it brings libpq): the connection's state and what its files share.
// pg_tool_store.cpp connects, migrates and opens; pg_tool_rows.cpp reads
// and writes tool rows; pg_local_copy.cpp keeps the station's copy for when
// the server is away; pg_change_log.cpp reads the change log and LISTENs.
#pragma once

#include "tools/pg_tool_store.h"

#include <libpq-fe.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

namespace pq {

using Param = std::optional<std::string>;  // a statement's parameter; none: NULL

struct ResultDeleter {
    void operator()(PGresult* r) const { PQclear(r); }
};
using PgResult = std::unique_ptr<PGresult, ResultDeleter>;

// Without the line break and spaces libpq's messages end in.
std::string trimmed(std::string s);
// A number as a statement's parameter.
std::string number(double v);
std::string number(long long v);
// A field of a result as a number or as text.
double real(const PGresult* r, int row, int col);
long long integer(const PGresult* r, int row, int col);
std::string text(const PGresult* r, int row, int col);

}  // namespace pq

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

    // The connection and the schema (pg_tool_store.cpp).
    void disconnect();
    std::string error() const;
    Result<void> connect();
    Result<pq::PgResult> exec(const char* sql, const std::vector<pq::Param>& params = {});
    void rollback();
    Failure failure(const std::string& what, const std::string& why);
    Result<int> version();
    Result<void> migrate();
    void checkConnection();
    // Tool rows (pg_tool_rows.cpp).
    Result<std::int64_t> writeTool(const Tool& t, bool fresh, std::int64_t readVersion = 0);
    Result<std::vector<VersionedTool>> readTools(int only = 0);
    Result<void> changeRow(const char* sql, const std::vector<pq::Param>& params, const std::string& what, int id);
    // The station's copy (pg_local_copy.cpp).
    Result<void> writeCopy(const std::vector<VersionedTool>& tools);
    Result<void> goOffline(const std::string& why);
    Result<void> comeOnline(bool listen);
    Failure refusedOffline();
};

}  // namespace taiwa
