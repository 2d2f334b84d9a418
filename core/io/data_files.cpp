// The shop's own data files (data_files.h).
#include "io/data_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace taiwa::io {

std::string userDataFolder(const std::string& kind)
{
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::string(xdg) + "/taiwa/" + kind;
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.config/taiwa/" + kind;
}

std::vector<DataFile> jsonFilesIn(const std::string& folder)
{
    std::error_code ec;
    std::vector<std::filesystem::path> paths;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        if (e.path().extension() == ".json") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    std::vector<DataFile> files;
    for (const auto& p : paths) {
        DataFile f{p.string(), {}, {}};
        if (std::filesystem::file_size(p, ec) > (1u << 20)) {
            f.problem = f.path + ": larger than 1 MB, not a definition";
        } else {
            std::ifstream in(p, std::ios::binary);
            f.text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            if (!in.good() && !in.eof()) f.problem = f.path + ": cannot read it";
        }
        files.push_back(std::move(f));
    }
    return files;
}

int lineOfKey(const std::string& text, const std::string& dottedPath)
{
    const std::string key = "\"" + dottedPath.substr(dottedPath.rfind('.') + 1) + "\"";
    const auto at = text.find(key);
    if (at == std::string::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

int lineOfByte(const std::string& text, std::size_t byte)
{
    const auto upTo = std::min<std::size_t>(byte > 0 ? byte - 1 : 0, text.size());
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(upTo), '\n'));
}

}  // namespace taiwa::io
