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

namespace {

// What a path is when it is not a regular file, for the message.
const char* kindOf(std::filesystem::file_type t)
{
    switch (t) {
    case std::filesystem::file_type::directory: return "a directory";
    case std::filesystem::file_type::character: return "a character device";
    case std::filesystem::file_type::block: return "a block device";
    case std::filesystem::file_type::fifo: return "a named pipe (FIFO)";
    case std::filesystem::file_type::socket: return "a socket";
    case std::filesystem::file_type::not_found: return "a link to nothing";
    default: return "not a regular file";
    }
}

}  // namespace

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
        // The kind first (a link followed): a device or a pipe is never
        // opened, it could be endless or block the program.
        const auto status = std::filesystem::status(p, ec);
        if (ec && status.type() != std::filesystem::file_type::not_found) {
            f.problem = f.path + ": cannot read it: " + ec.message();
        } else if (status.type() != std::filesystem::file_type::regular) {
            f.problem = f.path + ": " + kindOf(status.type()) + ", not a definition";
        } else if (const auto size = std::filesystem::file_size(p, ec); ec) {
            f.problem = f.path + ": cannot read it: " + ec.message();
        } else if (size > (1u << 20)) {
            f.problem = f.path + ": larger than 1 MB, not a definition";
        } else {
            std::ifstream in(p, std::ios::binary);
            f.text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            if (!in.good() && !in.eof()) f.problem = f.path + ": cannot read it";
            else if (f.text.size() > (1u << 20)) f.problem = f.path + ": larger than 1 MB, not a definition", f.text.clear();
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
