// The one validating reader of the shop's data files (dialects, machines):
// the text parsed once with the job reader's guards (nesting, numbers too
// large, keys given twice), then typed access with ranges, kinds and
// printable texts; every refusal a Refusal (model/result.h) at FILE:LINE and key, "FILE:LINE: key: why".
// The readers of post/dialect_data.cpp and machine/machine.cpp are built on it.
#pragma once

#include "model/result.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::io {

class DataReader {
public:
    // Parses `text`; refuses (throws Refusal) text that is not JSON, is
    // nested too deep, holds a number too large, is not an object, or gives
    // a key twice in one object.
    DataReader(const std::string& text, const std::string& source);

    const nlohmann::json& root() const { return root_; }
    const std::string& source() const { return source_; }

    // "FILE:LINE: key: what" (no line when the key is not in the text).
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;

    // The member `key` (a dotted path "rapid.x" is only for messages: the
    // value is looked up in `in`, default the root).
    const nlohmann::json* find(const nlohmann::json& in, const std::string& key) const;
    const nlohmann::json& at(const nlohmann::json& in, const std::string& key, const std::string& path) const;

    // A text of printable characters (no control characters, no escape
    // sequences) of at most `maxLength` bytes; `allowEmpty` false refuses "".
    std::string text(const nlohmann::json& v, const std::string& path, std::size_t maxLength, bool allowEmpty) const;
    std::string text(const std::string& key, const std::string& fallback, std::size_t maxLength = 200) const;
    // A whole number in [low, high], compared before it is stored (no wrap).
    long long whole(const nlohmann::json& v, const std::string& path, long long low, long long high) const;
    int whole(const std::string& key, int fallback, int low, int high) const;
    // A finite number in [low, high] (low excluded when `lowOpen`).
    double number(const nlohmann::json& v, const std::string& path, double low, double high, bool lowOpen) const;
    bool flag(const std::string& key, bool fallback) const;
    bool boolean(const nlohmann::json& v, const std::string& path) const;
    // A list of at most `maxCount` texts, each as text() reads it (not empty).
    std::vector<std::string> texts(const nlohmann::json& v, const std::string& path, std::size_t maxCount,
                                   std::size_t maxLength) const;
    // An object whose keys are all among `keys` (a typo is refused, not ignored).
    void onlyKeys(const nlohmann::json& v, const std::string& path, const std::vector<std::string>& keys) const;
    // An identifier: 1 to 32 of a-z, 0-9, '-', '_', starting with a letter or digit.
    std::string identifier(const std::string& key) const;

private:
    nlohmann::json root_;
    std::string source_;
    const std::string& text_;
};

// What a reader built on DataReader makes of `text` (Reader(text, source).read()),
// or its refusal as a Failure at the file's line and key: the door of each.
template <class Reader>
auto readData(const std::string& text, const std::string& source) -> Result<decltype(Reader(text, source).read())>
{
    try {
        return Reader(text, source).read();
    } catch (const Refusal& r) {
        return r.failure();
    }
}

// True when `s` holds no control character (below 0x20, DEL) and is valid
// enough to print: the texts of data files reach terminals and tapes.
bool printable(const std::string& s);

// `s` as one line of valid UTF-8 for a message: control bytes and bytes
// that are not UTF-8 shown as \xNN.
std::string clean(std::string_view s);

// How a number is shown in a message: at most 6 significant digits, an
// exponent for large and small ones (1e+308, not 309 digits).
std::string shortNumber(double v);

}  // namespace taiwa::io
