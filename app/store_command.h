// The shop server's job store on the command line (docs/shop-server.md):
// `taiwa export --from-store NAME` (the job's newest version fetched into a
// file of its own, which the export then reads as any job file), `taiwa
// store list`, `taiwa store history NAME`; and `taiwa import-tools FILE`.
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

// `taiwa store list` (`action` "list": every job, one line each: name,
// newest version, who saved it, from which station, when, and who holds
// its lock) and `taiwa store history NAME` (every version of job `name`,
// oldest first: version, who, station, when), tab-separated on stdout.
// `taiwa store locks` (every locked job: name, station, who, since when,
// and whether that station is connected now) and `taiwa store unlock NAME
// [--force]` (the lock released whoever holds it, saying who held it and
// since when; refused while the holding station is connected, unless
// `force`). Exit 0; 2 when the setting names no server, the server cannot
// be reached or has no job NAME, or the unlock is refused (the reason on
// stderr); 1 when it fails.
int storeCommand(const std::string& action, const std::string& name, bool force, const std::string& toolsSetting);

}  // namespace taiwa::app
