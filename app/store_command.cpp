// Fetching a job from the shop server's store for `taiwa export
// --from-store NAME` (store_command.h).
#include "app/store_command.h"

#include "tools/pg_job_store.h"
#include "tools/tool_library.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace taiwa::app {

Result<std::string> fetchStoredJob(const std::string& name, const std::string& toolsSetting)
{
    const std::string setting = toolsSetting.empty() ? defaultToolLibraryPath() : toolsSetting;
    if (!isServerSetting(setting))
        return Failure{fmt::format("--from-store needs the shop server: TAIWA_TOOL_DB or --tools names the file {}, not a server "
                                   "(postgresql://…, docs/shop-server.md)",
                                   setting)};
    auto server = PgToolStore::open(setting, {defaultServerCopyPath(), {}, 3});
    if (!server) return Failure{server.error()};
    if ((*server)->readOnly()) return Failure{fmt::format("{} cannot be reached: the job store has no copy on this station", (*server)->name())};
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

}  // namespace taiwa::app
