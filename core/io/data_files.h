// The shop's own data files beside the shipped ones (machines, dialects):
// the *.json of a folder in the user's config directory, read in name order,
// and the line a key or a JSON syntax error stands on, for messages that
// name file, line and key.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace taiwa::io {

struct DataFile {
    std::string path;
    std::string text;
    std::string problem;  // cannot be read, too large: then `text` is empty
};

// $XDG_CONFIG_HOME/taiwa/<kind>, else ~/.config/taiwa/<kind>.
std::string userDataFolder(const std::string& kind);
// Every *.json in `folder` (none when it does not exist), at most 1 MB each;
// a directory, device, pipe, socket or dangling link is refused by its kind.
std::vector<DataFile> jsonFilesIn(const std::string& folder);
// The line (from 1) of the first "key" of a dotted path's last part; 0 when absent.
int lineOfKey(const std::string& text, const std::string& dottedPath);
// The line (from 1) of byte `byte` (1-based, as JSON parse errors count).
int lineOfByte(const std::string& text, std::size_t byte);

// The shop's files of a kind joined to the shipped definitions `items`: a
// file whose key (id, name) is known replaces that one, a new key joins; a
// file that cannot be used, or names a key an earlier shop file named, is
// left out with its problem (`read` gives a
// Result<T> naming file, line and key; `what`: "machines", "dialects").
template <class T, class Read, class KeyOf>
void addShopFiles(std::vector<T>& items, std::vector<std::string>& problems, const std::string& folder, Read read,
                  KeyOf key, const std::string& what)
{
    std::vector<std::pair<std::string, std::string>> shopKeys;  // key, file: two shop files of one key are refused
    for (const DataFile& f : jsonFilesIn(folder)) {
        if (!f.problem.empty()) {
            problems.push_back(f.problem);
            continue;
        }
        auto item = read(f.text, f.path);
        if (!item) {
            problems.push_back(item.error() + " (left out; the shipped " + what + " stay)");
            continue;
        }
        const auto earlier = std::find_if(shopKeys.begin(), shopKeys.end(), [&](const auto& k) { return k.first == key(*item); });
        if (earlier != shopKeys.end()) {
            problems.push_back(f.path + ": '" + key(*item) + "' is already defined by " + earlier->second +
                               " (left out: two shop files of one name, and which is meant is not for the program to guess)");
            continue;
        }
        shopKeys.emplace_back(key(*item), f.path);
        const auto same = std::find_if(items.begin(), items.end(), [&](const T& x) { return key(x) == key(*item); });
        if (same != items.end()) *same = std::move(*item);
        else items.push_back(std::move(*item));
    }
}

// A library of data files: the definitions, and the shop files left out
// with their problems.
template <class T>
struct DataLibrary {
    std::vector<T> items;
    std::vector<std::string> problems;
};

// The shipped definitions (`shipped`: pairs of text and source name, from
// builtin_data.h), then the shop's files of `folder` joined to them
// (addShopFiles). A shipped definition that does not read is a bug of the
// build (std::logic_error), never the operator's.
template <class T, class Shipped, class Read, class KeyOf>
DataLibrary<T> loadDataLibrary(const Shipped& shipped, const std::string& folder, Read read, KeyOf key, const std::string& what)
{
    DataLibrary<T> l;
    for (const auto& [text, source] : shipped) {
        auto item = read(text, source);
        if (!item) throw std::logic_error("a shipped file of the " + what + " is broken: " + item.error());
        l.items.push_back(std::move(*item));
    }
    addShopFiles(l.items, l.problems, folder, read, key, what);
    return l;
}

}  // namespace taiwa::io
