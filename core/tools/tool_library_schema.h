// The SQLite tool library's schema (tool_library_schema.cpp): its version,
// a new file's tables with the default library, and an older file's
// migrations. Internal to core/tools.
#pragma once

struct sqlite3;

namespace taiwa::tooldb {

constexpr int kSchemaVersion = 8;

// A new file's tables, filled with the default library; whether it worked.
bool createSchema(sqlite3* db);

// A file of version `from` (1 to kSchemaVersion - 1) brought to the current
// version: every migration from it on, the default lathe and hole tools whose
// ids the library does not use yet, the default tools' names in other
// languages; whether it worked.
bool upgradeSchema(sqlite3* db, int from);

}  // namespace taiwa::tooldb
