// The shop server's tool rows (pg_store_impl.h): a tool written at the
// version it was read (a conflict reported with both values), the library
// read in one snapshot, usage added, a tool removed, and an SQLite library
// imported whole.
#include "tools/pg_store_impl.h"

#include "tools/tool_check.h"
#include "tools/tool_library.h"
#include "tools/tool_row.h"
#include "tools/turning_text.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace taiwa {

using namespace pq;

namespace {

constexpr long kNewIdLock = 0x7461697762;

// A row of a result, as toolFromRow (tools/tool_row.h) reads it.
struct PgRow {
    const PGresult* r;
    int row;
    long long integer(int c) const { return pq::integer(r, row, c); }
    double real(int c) const { return pq::real(r, row, c); }
    std::string text(int c) const { return pq::text(r, row, c); }
    bool flag(int c) const { return text(c) == "t"; }
};

// A tool's values as a statement's parameters: $1 the id, $2…$17 the
// columns of kToolColumns in their order.
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

}  // namespace

// Writes a tool's rows (inside a transaction). `fresh`: an INSERT that
// fails on an existing id; else an UPDATE at `readVersion`. The new
// version, or 0 when no row was written (the version moved on, or the id
// is taken).
Result<std::int64_t> PgToolStore::Impl::writeTool(const Tool& t, bool fresh, std::int64_t readVersion)
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
Result<std::vector<VersionedTool>> PgToolStore::Impl::readTools(int only)
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
        auto t = toolFromRow(PgRow{r, i}, display);
        if (!t) return Failure{t.error()};
        out.push_back({std::move(*t), integer(r, i, 17)});
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
        return d.failure(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "saving tool T{}"), t.id), why);
    }
    if (*version > 0) return SaveOutcome{t.id, *version, std::nullopt};
    // Refused: what the server holds now, and who changed it last.
    ToolConflict conflict;
    conflict.mine = t;
    auto theirs = d.readTools(t.id);
    if (!theirs) {
        d.checkConnection();
        return d.failure(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "reading tool T{}"), t.id), theirs.error());
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

// One statement on tool `id`'s row ($1 the id): refused while offline, a
// failure named by `what` ("removing tool T27"), and a tool not there.
Result<void> PgToolStore::Impl::changeRow(const char* sql, const std::vector<Param>& params, const std::string& what, int id)
{
    if (offline) return refusedOffline();
    auto r = exec(sql, params);
    if (!r) {
        const std::string why = r.error();
        checkConnection();
        return failure(what, why);
    }
    if (std::string(PQcmdTuples(r->get())) == "0") return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no tool T{}"), display, id)};
    return {};
}

Result<void> PgToolStore::remove(int id)
{
    return d_->changeRow("DELETE FROM tools WHERE id = $1", {std::to_string(id)}, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "removing tool T{}"), id), id);
}

Result<void> PgToolStore::addUsage(int id, double minutes)
{
    return d_->changeRow("UPDATE tools SET used_minutes = used_minutes + $2 WHERE id = $1", {std::to_string(id), number(minutes)},
                         fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "adding usage to tool T{}"), id), id);
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
            if (const auto field = unstorable(t)) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool T{} ({}) holds a NUL character"), t.id, *field)};
            auto w = d.writeTool(t, true);
            if (!w) return Failure{w.error()};
        }
        if (auto r = d.exec("COMMIT"); !r) return Failure{r.error()};
        return {};
    };
    if (auto r = run(); !r) {
        d.rollback();
        d.checkConnection();
        return d.failure(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "importing {}"), path), r.error());
    }
    return static_cast<int>(tools->size());
}

}  // namespace taiwa
