// The shop's data files read through one validating reader (data_reader.h).
#include "io/data_reader.h"

#include "io/data_files.h"
#include "io/json_document.h"

#include <fmt/format.h>

#include <algorithm>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace taiwa::io {

using nlohmann::json;

namespace {

// The line of the second "key" in the text: where a repeated key stands.
int lineOfRepeat(const std::string& text, const std::string& key)
{
    const std::string quoted = "\"" + key + "\"";
    const auto first = text.find(quoted);
    if (first == std::string::npos) return 0;
    const auto second = text.find(quoted, first + quoted.size());
    return lineOfByte(text, (second == std::string::npos ? first : second) + 1);
}

// A SAX pass that only remembers where the syntax broke.
struct ErrorPosition : nlohmann::json_sax<json> {
    std::optional<std::size_t> byte;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool key(string_t&) override { return true; }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override
    {
        byte = position;
        return false;
    }
};

}  // namespace

std::string clean(std::string_view s)
{
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        std::size_t n = c < 0x80 ? 1 : c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
        if (n > 1) {
            if (i + n > s.size()) n = 0;
            for (std::size_t k = 1; k < n; ++k)
                if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) n = 0;
            // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8 either.
            const auto c1 = n > 1 ? static_cast<unsigned char>(s[i + 1]) : 0;
            if ((c == 0xe0 && c1 < 0xa0) || (c == 0xed && c1 > 0x9f) || (c == 0xf0 && c1 < 0x90) || (c == 0xf4 && c1 > 0x8f)) n = 0;
        }
        if (n == 0 || (n == 1 && (c < 0x20 || c == 0x7f))) {
            out += fmt::format("\\x{:02x}", c);
            ++i;
        } else {
            out.append(s.substr(i, n));
            i += n;
        }
    }
    return out;
}

bool printable(const std::string& s)
{
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) return false;
    }
    return true;
}

std::string shortNumber(double v)
{
    if (!std::isfinite(v)) return v > 0 ? "infinity" : v < 0 ? "-infinity" : "not a number";
    return fmt::format("{:.6g}", v);
}

DataReader::DataReader(const std::string& text, const std::string& source) : source_(source), text_(text)
{
    ParsedDocument doc = parseDocument(text);
    if (!doc.root) {
        // Where the syntax breaks, by a pass that builds nothing (a tree nested
        // too deep is never built); else the reader's sentence (too deep, a
        // number too large).
        ErrorPosition at;
        json::sax_parse(text.begin(), text.end(), &at);
        if (at.byte) throw Refusal("not valid JSON", Place::inFile(source_, lineOfByte(text, *at.byte)));
        throw Refusal(doc.error, Place::inFile(source_));
    }
    if (!doc.repeatedKeys.empty()) {
        const JsonPath& p = doc.repeatedKeys.front();
        const std::string key = joinPath(p.begin(), p.end());
        const int line = lineOfRepeat(text, p.back());
        throw Refusal("given twice (which one is meant is not for the program to guess)", Place::inFile(source_, line, key));
    }
    root_ = std::move(*doc.root);
    if (!root_.is_object()) fail("(file)", "not a JSON object");
}

void DataReader::fail(const std::string& key, const std::string& what) const
{
    const int line = lineOfKey(text_, key.substr(0, key.find('[')));
    // A key or a value of the file quoted in the message is shown as
    // printable text of one line (control bytes and broken UTF-8 as \xNN).
    throw Refusal(clean(what), Place::inFile(source_, line, clean(key)));
}

const json* DataReader::find(const json& in, const std::string& key) const
{
    const auto it = in.find(key);
    return it == in.end() ? nullptr : &*it;
}

const json& DataReader::at(const json& in, const std::string& key, const std::string& path) const
{
    const json* v = find(in, key);
    if (!v) fail(path, "missing");
    return *v;
}

std::string DataReader::text(const json& v, const std::string& path, std::size_t maxLength, bool allowEmpty) const
{
    if (!v.is_string()) fail(path, "must be a text");
    const std::string& s = v.get_ref<const std::string&>();
    if (!allowEmpty && s.find_first_not_of(' ') == std::string::npos) fail(path, "must be a text that is not empty");
    if (s.size() > maxLength) fail(path, fmt::format("is {} characters long; at most {}", s.size(), maxLength));
    if (!printable(s)) fail(path, "holds a control character (a line break, a tab, an escape); only printable text is read");
    return s;
}

std::string DataReader::text(const std::string& key, const std::string& fallback, std::size_t maxLength) const
{
    const json* v = find(root_, key);
    return v ? text(*v, key, maxLength, true) : fallback;
}

long long DataReader::whole(const json& v, const std::string& path, long long low, long long high) const
{
    const std::string range = fmt::format("must be a whole number from {} to {}", low, high);
    if (v.is_number_unsigned()) {
        const std::uint64_t u = v.get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(high) || static_cast<long long>(u) < low) fail(path, range);
        return static_cast<long long>(u);
    }
    if (!v.is_number_integer() || v.get<long long>() < low || v.get<long long>() > high) fail(path, range);
    return v.get<long long>();
}

int DataReader::whole(const std::string& key, int fallback, int low, int high) const
{
    const json* v = find(root_, key);
    return v ? static_cast<int>(whole(*v, key, low, high)) : fallback;
}

double DataReader::number(const json& v, const std::string& path, double low, double high, bool lowOpen) const
{
    const std::string range = fmt::format("must be a number {} {} up to {}", lowOpen ? "above" : "from", shortNumber(low),
                                          shortNumber(high));
    if (!v.is_number()) fail(path, range);
    const double d = v.get<double>();
    if (!std::isfinite(d) || (lowOpen ? !(d > low) : !(d >= low)) || !(d <= high)) fail(path, range + ", not " + shortNumber(d));
    return d;
}

bool DataReader::flag(const std::string& key, bool fallback) const
{
    const json* v = find(root_, key);
    if (!v) return fallback;
    if (!v->is_boolean()) fail(key, "must be true or false");
    return v->get<bool>();
}

bool DataReader::boolean(const json& v, const std::string& path) const
{
    if (!v.is_boolean()) fail(path, "must be true or false");
    return v.get<bool>();
}

std::vector<std::string> DataReader::texts(const json& v, const std::string& path, std::size_t maxCount,
                                           std::size_t maxLength) const
{
    if (!v.is_array() || v.size() > maxCount) fail(path, fmt::format("must be a list of at most {} texts", maxCount));
    std::vector<std::string> out;
    for (const json& x : v) out.push_back(text(x, path, maxLength, false));
    return out;
}

void DataReader::onlyKeys(const json& v, const std::string& path, const std::vector<std::string>& keys) const
{
    if (!v.is_object()) fail(path, "must be an object");
    for (const auto& [key, value] : v.items())
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) fail(path + "." + key, "not a key of " + path + " (a typo?)");
}

std::string DataReader::identifier(const std::string& key) const
{
    const json& v = at(root_, key, key);
    if (!v.is_string()) fail(key, "must be a text");
    const std::string& s = v.get_ref<const std::string&>();
    if (s.empty() || s.size() > 32 || s.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") != std::string::npos ||
        s.front() == '-' || s.front() == '_')
        fail(key, "must be 1 to 32 lower-case letters, digits, '-' or '_', starting with a letter or digit (it names "
                  "files and is printed on the tape)");
    return s;
}

}  // namespace taiwa::io
