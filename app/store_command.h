// `taiwa export --from-store NAME`: the job's newest version fetched from
// the shop server's job store (docs/shop-server.md) into a file of its own,
// which the export then reads as any job file.
#pragma once

#include "model/result.h"

#include <string>

namespace taiwa::app {

// The server is the tool setting's (`--tools` or $TAIWA_TOOL_DB, which must
// name a server); the job is written to NAME.taiwa in a new folder under
// the temporary directory. Its path, or why not.
Result<std::string> fetchStoredJob(const std::string& name, const std::string& toolsSetting);

// `taiwa import-tools FILE`: the server's tool library replaced by that of
// the SQLite library FILE (any version; read from a copy, left as it was).
// The server is the tool setting's, which must name one. Exit 0 with a
// line on stdout, 2 when the setting is no server or FILE no library (its
// reason on stderr, the server unchanged), 1 when the server fails.
int importTools(const std::string& file, const std::string& toolsSetting);

}  // namespace taiwa::app
