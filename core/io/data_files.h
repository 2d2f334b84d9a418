// The shop's own data files beside the shipped ones (machines, dialects):
// the *.json of a folder in the user's config directory, read in name order,
// and the line a key or a JSON syntax error stands on, for messages that
// name file, line and key.
#pragma once

#include <string>
#include <vector>

namespace taiwa::io {

struct DataFile {
    std::string path;
    std::string text;
    std::string problem;  // cannot be read, too large: then `text` is empty
};

// $XDG_CONFIG_HOME/taiwa/<kind>, else ~/.config/taiwa/<kind>.
std::string userDataFolder(const std::string& kind);
// Every *.json in `folder` (none when it does not exist), at most 1 MB each.
std::vector<DataFile> jsonFilesIn(const std::string& folder);
// The line (from 1) of the first "key" of a dotted path's last part; 0 when absent.
int lineOfKey(const std::string& text, const std::string& dottedPath);
// The line (from 1) of byte `byte` (1-based, as JSON parse errors count).
int lineOfByte(const std::string& text, std::size_t byte);

}  // namespace taiwa::io
