// The shop server's change log and notifications (pg_store_impl.h): a
// tool's history of changes, LISTEN, and the changes other stations
// announced, waited for on the connection's socket.
#include "tools/pg_store_impl.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <poll.h>

namespace taiwa {

using namespace pq;

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
        return d.failure(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "reading the history of tool T{}"), id), why);
    }
    std::vector<ToolChangeRecord> out;
    for (int i = 0; i < PQntuples(r->get()); ++i)
        out.push_back({text(r->get(), i, 0), text(r->get(), i, 1), text(r->get(), i, 2), text(r->get(), i, 3), text(r->get(), i, 4),
                       text(r->get(), i, 5)});
    return out;
}

int PgToolStore::socket() const { return d_->conn ? PQsocket(d_->conn) : -1; }

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
