// The tool library interface's SQLite store (the ToolLibrary file, as
// always) and the choice between it and the shop server by the setting
// (docs/shop-server.md, "Connecting a station").
#include "tools/tool_store.h"

#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cstdlib>
#include <unistd.h>

namespace taiwa {

Result<std::vector<Tool>> ToolStore::tools()
{
    auto versioned = versionedTools();
    if (!versioned) return versioned.failure();
    std::vector<Tool> out;
    out.reserve(versioned->size());
    for (auto& v : *versioned) out.push_back(std::move(v.tool));
    return out;
}

namespace {

// The station's own file: no versions, a save replaces (as ToolLibrary::save).
class SqliteToolStore : public ToolStore {
public:
    explicit SqliteToolStore(ToolLibrary lib) : lib_(std::move(lib)) {}
    std::string name() const override { return lib_.path(); }
    Result<std::vector<VersionedTool>> versionedTools() override
    {
        auto tools = lib_.tools();
        if (!tools) return tools.failure();
        std::vector<VersionedTool> out;
        for (auto& t : *tools) out.push_back({std::move(t), 0});
        return out;
    }
    Result<SaveOutcome> save(const Tool& tool, std::int64_t) override
    {
        auto id = lib_.save(tool);
        if (!id) return id.failure();
        return SaveOutcome{*id, 0, std::nullopt};
    }
    Result<void> remove(int id) override { return lib_.remove(id); }
    Result<void> addUsage(int id, double minutes) override { return lib_.addUsage(id, minutes); }
    std::string status() const override { return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tools: {}"), lib_.path()); }

private:
    ToolLibrary lib_;
};

}  // namespace

bool isServerSetting(const std::string& setting)
{
    return setting.starts_with("postgresql://") || setting.starts_with("postgres://") || setting.starts_with("service=");
}

std::string stationName()
{
    if (const char* s = std::getenv("TAIWA_STATION"); s && *s) return s;
    char host[256] = {};
    if (gethostname(host, sizeof host - 1) == 0 && *host) return host;
    return "station";
}

std::string defaultServerCopyPath()
{
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return std::string(xdg) + "/taiwa/tools-server-copy.sqlite";
    const char* home = std::getenv("HOME");
    return std::string(home ? home : ".") + "/.local/share/taiwa/tools-server-copy.sqlite";
}

Result<std::unique_ptr<ToolStore>> openToolStore(const std::string& setting, const std::string& copyPath)
{
    const std::string s = setting.empty() ? defaultToolLibraryPath() : setting;
    if (isServerSetting(s)) {
        auto pg = PgToolStore::open(s, {copyPath.empty() ? defaultServerCopyPath() : copyPath, {}, 3});
        if (!pg) return pg.failure();
        return std::unique_ptr<ToolStore>(std::move(*pg));
    }
    auto lib = ToolLibrary::open(s);
    if (!lib) return lib.failure();
    return std::unique_ptr<ToolStore>(std::make_unique<SqliteToolStore>(std::move(*lib)));
}

}  // namespace taiwa
