// The job store's commands (store_command.h): a job fetched for `taiwa
// export --from-store NAME`, `taiwa store list|history|locks|unlock`, `taiwa import-tools`.
#include "app/store_command.h"

#include "tools/pg_job_store.h"
#include "tools/tool_library.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace taiwa::app {

namespace {

// The server the tool setting names, connected; `what` (what needs it) in
// the refusal when the setting names a file.
Result<std::unique_ptr<PgToolStore>> jobServer(const std::string& toolsSetting, const std::string& what)
{
    const std::string setting = toolsSetting.empty() ? defaultToolLibraryPath() : toolsSetting;
    if (!isServerSetting(setting))
        return Failure{fmt::format("{} needs the shop server: TAIWA_TOOL_DB or --tools names the file {}, not a server "
                                   "(postgresql://…, docs/shop-server.md)",
                                   what, setting)};
    auto server = PgToolStore::open(setting, {defaultServerCopyPath(), {}, 3});
    if (!server) return Failure{server.error()};
    if ((*server)->readOnly())
        return Failure{fmt::format("{} cannot be reached ({}): the job store has no copy on this station", (*server)->name(), (*server)->whyOffline())};
    return server;
}

// A value on a tab-separated line: a tab, a line break or another control
// character (a hostile job name) shown as U+FFFD.
std::string field(const std::string& s)
{
    std::string out;
    for (const char c : s) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? std::string("\uFFFD") : std::string(1, c);
    return out;
}

}  // namespace

Result<std::string> fetchStoredJob(const std::string& name, const std::string& toolsSetting)
{
    auto server = jobServer(toolsSetting, "--from-store");
    if (!server) return Failure{server.error()};
    PgJobStore jobs(**server);
    auto text = jobs.load(name);
    if (!text) return Failure{text.error()};
    // The file's name is the job's, made safe for a file name (the tape's stem).
    const std::string stem = jobFileStem(name);
    std::error_code ec;
    const auto dir = std::filesystem::temp_directory_path(ec) / fmt::format("taiwa-store-{}", ::getpid());
    std::filesystem::create_directories(dir, ec);
    const auto path = dir / (stem + ".taiwa");
    std::ofstream out(path, std::ios::binary);
    out << *text;
    out.close();
    if (!out) return Failure{fmt::format("cannot write the stored job to {}", path.string())};
    return path.string();
}

int importTools(const std::string& file, const std::string& toolsSetting)
{
    const std::string setting = toolsSetting.empty() ? defaultToolLibraryPath() : toolsSetting;
    if (!isServerSetting(setting)) {
        std::cerr << "taiwa: import-tools: the library goes to the shop server: TAIWA_TOOL_DB or --tools names the file "
                  << setting << ", not a server (postgresql://…, docs/shop-server.md); nothing was changed\n";
        return 2;
    }
    // The file first: a library that cannot be read leaves the server as it was, exit 2.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        std::cerr << "taiwa: import-tools: " << file << " is not a file; nothing was changed\n";
        return 2;
    }
    // Not opened here (opening upgrades an older library in place): its header only.
    char header[16] = {};
    std::ifstream in(file, std::ios::binary);
    if (!in.read(header, sizeof header) || std::string(header, sizeof header) != std::string("SQLite format 3\0", 16)) {
        std::cerr << "taiwa: import-tools: " << file << " is not a tool library (the file is not an SQLite database); "
                  << "nothing was changed\n";
        return 2;
    }
    auto server = PgToolStore::open(setting, {defaultServerCopyPath(), {}, 3});
    if (!server) {
        std::cerr << "taiwa: import-tools: " << server.error() << '\n';
        return 1;
    }
    if ((*server)->readOnly()) {
        std::cerr << "taiwa: import-tools: " << (*server)->name() << " cannot be reached; nothing was changed\n";
        return 1;
    }
    auto count = (*server)->importSqliteLibrary(file);
    if (!count) {
        std::cerr << "taiwa: import-tools: " << count.error() << '\n';
        return 1;
    }
    std::cout << "taiwa: " << *count << " tools of " << file << " are now the library of " << (*server)->name() << '\n';
    return 0;
}

namespace {

// `taiwa store unlock NAME [--force]`: who held the lock and since when on
// stdout; a live holder refused (exit 2) with what --force would mean.
int unlockJob(PgJobStore& jobs, const std::string& name, bool force, const std::string& server)
{
    auto released = jobs.release(name, force);
    if (!released) {
        const std::string& why = released.error();
        const bool refused = why.starts_with("job '") || why.find(" has no job '") != std::string::npos;
        std::cerr << "taiwa: store unlock: " << why;
        if (why.starts_with("job '"))
            std::cerr << ". --force releases it all the same: that station keeps the job open without the lock, so another station "
                         "may open and save it meanwhile; every save stays a version of its own in the history (nothing is "
                         "overwritten), and that station's next save takes no lock";
        std::cerr << '\n';
        return refused ? 2 : 1;
    }
    if (!*released) {
        std::cout << "taiwa: job '" << field(name) << "' of " << server << " was not locked; nothing was changed\n";
        return 0;
    }
    const JobLock& l = **released;
    std::cout << "taiwa: released the lock of job '" << field(name) << "' held by station " << field(l.station) << " (" << field(l.by)
              << ") since " << l.at << (l.stationConnected ? "; the station is connected and now edits the job without the lock" : "")
              << '\n';
    return 0;
}

}  // namespace

int storeCommand(const std::string& action, const std::string& name, bool force, const std::string& toolsSetting)
{
    const std::string command = "store " + action;
    // The reason on stderr, and the exit code.
    const auto refused = [&](const std::string& why, int exit) {
        std::cerr << "taiwa: " << command << ": " << why << '\n';
        return exit;
    };
    auto server = jobServer(toolsSetting, "the job store");
    if (!server) return refused(server.error(), 2);
    PgJobStore jobs(**server);
    if (action == "list") {
        auto list = jobs.list();
        if (!list) return refused(list.error(), 1);
        for (const StoredJob& j : *list)
            std::cout << field(j.name) << '\t' << j.newest.version << '\t' << field(j.newest.who) << '\t' << field(j.newest.station) << '\t'
                      << j.newest.at << '\t'
                      << (j.lockedStation.empty() ? std::string("-")
                                                  : field(fmt::format("open at station {} by {} since {}", j.lockedStation, j.lockedBy, j.lockedAt)))
                      << '\n';
        if (list->empty()) std::cerr << "taiwa: " << command << ": " << (*server)->name() << " holds no jobs\n";
        return 0;
    }
    if (action == "locks") {
        auto locks = jobs.locks();
        if (!locks) return refused(locks.error(), 1);
        for (const JobLock& l : *locks)
            std::cout << field(l.job) << '\t' << field(l.station) << '\t' << field(l.by) << '\t' << l.at << '\t'
                      << (l.stationConnected ? "station connected" : "station not connected") << '\n';
        if (locks->empty()) std::cerr << "taiwa: " << command << ": no job of " << (*server)->name() << " is locked\n";
        return 0;
    }
    if (action == "unlock") return unlockJob(jobs, name, force, (*server)->name());
    auto history = jobs.history(name);
    if (!history) return refused(history.error(), 1);
    if (history->empty()) return refused(fmt::format("{} has no job '{}'", (*server)->name(), name), 2);
    for (const JobVersionInfo& v : *history) std::cout << v.version << '\t' << field(v.who) << '\t' << field(v.station) << '\t' << v.at << '\n';
    return 0;
}

}  // namespace taiwa::app
