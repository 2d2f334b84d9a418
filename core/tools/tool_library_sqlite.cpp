// The SQLite tool library's common parts (tool_library_sqlite.h): a failure
// described naming the file, and a tool written as its rows in `tools`,
// `tool_names` and `cutting_data`.
#include "tools/tool_library_sqlite.h"

#include "model/translate_noop.h"
#include "tools/tool_row.h"
#include "tools/turning_text.h"

#include <fmt/format.h>

namespace taiwa::tooldb {

std::string describe(sqlite3* db, const std::string& path)
{
    const int code = sqlite3_extended_errcode(db) & 0xff;
    if (code == SQLITE_NOTADB)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a tool library (the file is not an SQLite database)"), path);
    if (code == SQLITE_BUSY || code == SQLITE_LOCKED)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is locked by another program; close it and try again"), path);
    if (code == SQLITE_READONLY || code == SQLITE_CANTOPEN || code == SQLITE_PERM)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot be opened for writing ({})"), path, sqlite3_errmsg(db));
    if (code == SQLITE_CORRUPT)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is damaged ({}); restore it from a backup"), path, sqlite3_errmsg(db));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), path, sqlite3_errmsg(db));
}

bool exec(sqlite3* db, const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK; }


bool insert(sqlite3* db, const Tool& t)
{
    const std::string sql = fmt::format("INSERT OR REPLACE INTO tools (id, {}) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)", kToolColumns);
    Statement s(db, sql.c_str());
    if (!s.ok()) return false;
    s.bind(1, t.id);
    s.bind(2, t.name);
    s.bind(3, std::string(toKey(t.type)));
    s.bind(4, t.diameter);
    s.bind(5, t.cornerRadius);
    s.bind(6, t.taperAngle);
    s.bind(7, t.pointAngle);
    s.bind(8, t.fluteLength);
    s.bind(9, t.stickout);
    s.bind(10, t.holder);
    s.bind(11, t.flutes);
    s.bind(12, t.lifeMinutes);
    s.bind(13, t.usedMinutes);
    s.bind(14, t.centreCutting ? 1 : 0);
    s.bind(15, turningText(t.turning));
    s.bind(16, t.holderDiameter);
    s.bind(17, t.holderLength);
    if (s.step() != SQLITE_DONE) return false;
    for (const char* table : {"DELETE FROM cutting_data WHERE tool_id = ?", "DELETE FROM tool_names WHERE tool_id = ?"}) {
        Statement del(db, table);
        del.bind(1, t.id);
        if (!del.ok() || del.step() != SQLITE_DONE) return false;
    }
    for (const auto& [language, name] : t.names) {
        Statement n(db, "INSERT INTO tool_names VALUES (?,?,?)");
        n.bind(1, t.id);
        n.bind(2, language);
        n.bind(3, name);
        if (!n.ok() || n.step() != SQLITE_DONE) return false;
    }
    for (const auto& c : t.cutting) {
        Statement cd(db, "INSERT INTO cutting_data VALUES (?,?,?,?,?)");
        cd.bind(1, t.id);
        cd.bind(2, c.material);
        cd.bind(3, c.surfaceSpeed);
        cd.bind(4, c.feedPerTooth);
        cd.bind(5, c.plungeFactor);
        if (!cd.ok() || cd.step() != SQLITE_DONE) return false;
    }
    return true;
}

}  // namespace taiwa::tooldb
