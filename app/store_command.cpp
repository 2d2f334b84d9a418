// The job store's commands (store_command.h): a job fetched for `taiwa
// export --from-store NAME`, `taiwa store list|history`, `taiwa import-tools`.
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
    std::string stem;
    for (char c : name) stem += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
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

int storeCommand(const std::string& action, const std::string& name, const std::string& toolsSetting)
{
    const std::string command = "store " + action;
    auto server = jobServer(toolsSetting, "the job store");
    if (!server) {
        std::cerr << "taiwa: " << command << ": " << server.error() << '\n';
        return 2;
    }
    PgJobStore jobs(**server);
    if (action == "list") {
        auto list = jobs.list();
        if (!list) {
            std::cerr << "taiwa: " << command << ": " << list.error() << '\n';
            return 1;
        }
        for (const StoredJob& j : *list)
            std::cout << field(j.name) << '\t' << j.newest.version << '\t' << field(j.newest.who) << '\t' << field(j.newest.station) << '\t'
                      << j.newest.at << '\t'
                      << (j.lockedStation.empty() ? std::string("-")
                                                  : field(fmt::format("open at station {} by {} since {}", j.lockedStation, j.lockedBy, j.lockedAt)))
                      << '\n';
        if (list->empty()) std::cerr << "taiwa: " << command << ": " << (*server)->name() << " holds no jobs\n";
        return 0;
    }
    auto history = jobs.history(name);
    if (!history) {
        std::cerr << "taiwa: " << command << ": " << history.error() << '\n';
        return 1;
    }
    if (history->empty()) {
        std::cerr << "taiwa: " << command << ": " << fmt::format("{} has no job '{}'", (*server)->name(), name) << '\n';
        return 2;
    }
    for (const JobVersionInfo& v : *history) std::cout << v.version << '\t' << field(v.who) << '\t' << field(v.station) << '\t' << v.at << '\n';
    return 0;
}

}  // namespace taiwa::app
