// The SQLite tool library's common parts (tool_library_sqlite.cpp), for its
// reading and editing (tool_library.cpp) and its schema
// (tool_library_schema.cpp): a statement that finalizes itself, a failure
// described naming the file, and a tool written as its rows. Internal to
// core/tools.
#pragma once

#include "model/tool.h"

#include <sqlite3.h>

#include <string>

namespace taiwa::tooldb {

// A prepared statement that finalizes itself.
class Statement {
public:
    Statement(sqlite3* db, const char* sql) { ok_ = sqlite3_prepare_v2(db, sql, -1, &s_, nullptr) == SQLITE_OK; }
    ~Statement() { sqlite3_finalize(s_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    bool ok() const { return ok_; }
    sqlite3_stmt* get() const { return s_; }
    void bind(int i, double v) { sqlite3_bind_double(s_, i, v); }
    void bind(int i, int v) { sqlite3_bind_int(s_, i, v); }
    void bind(int i, const std::string& v) { sqlite3_bind_text(s_, i, v.c_str(), -1, SQLITE_TRANSIENT); }
    int step() { return sqlite3_step(s_); }
    double real(int c) const { return sqlite3_column_double(s_, c); }
    int integer(int c) const { return sqlite3_column_int(s_, c); }
    bool flag(int c) const { return integer(c) != 0; }
    std::string text(int c) const
    {
        const auto* t = sqlite3_column_text(s_, c);
        return t ? reinterpret_cast<const char*>(t) : "";
    }

private:
    sqlite3_stmt* s_ = nullptr;
    bool ok_ = false;
};

// What went wrong with the library `path`, in the operator's words (not a
// library, locked, read-only, damaged, or SQLite's own message).
std::string describe(sqlite3* db, const std::string& path);

// Runs `sql`; whether it succeeded.
bool exec(sqlite3* db, const char* sql);

// The tool written (replaced) with its cutting data and names; whether it was.
bool insert(sqlite3* db, const Tool& t);

}  // namespace taiwa::tooldb
