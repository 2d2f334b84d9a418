// Fetching a job from the shop server's store for `taiwa export
// --from-store NAME` (store_command.h).
#include "app/store_command.h"

#include "tools/pg_job_store.h"
#include "tools/tool_library.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
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

}  // namespace taiwa::app
