// The job-file reader's messages (see job_messages.h).
#include "io/job_messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include <nlohmann/json.hpp>

namespace taiwa::msg::io {

namespace {
std::string joined(const std::vector<std::string>& items)
{
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
    return out;
}

// What was found: "a string (\"deep\")", "1.5", "true", "an array".
std::string found(const nlohmann::json& v)
{
    if (v.is_string())
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a string ({})"),
                           excerpt(v.get_ref<const std::string&>()));
    if (v.is_number() || v.is_boolean()) return v.dump();
    return kindOf(v);
}

// Length of the well-formed UTF-8 sequence `s` starts with (lead byte >= 0x80),
// or 0 (Unicode table 3-7: no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8Length(std::string_view s)
{
    const auto byte = [&s](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(0);
    const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || s.size() < n) return 0;
    const unsigned char low = c == 0xE0 ? 0xA0 : c == 0xF0 ? 0x90 : 0x80;
    const unsigned char high = c == 0xED ? 0x9F : c == 0xF4 ? 0x8F : 0xBF;
    if (byte(1) < low || byte(1) > high) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if ((byte(k) & 0xC0) != 0x80) return 0;
    return n;
}
}  // namespace

std::string kindOf(const nlohmann::json& v)
{
    switch (v.type()) {
    case nlohmann::json::value_t::null:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "null");
    case nlohmann::json::value_t::object:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object");
    case nlohmann::json::value_t::array:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array");
    case nlohmann::json::value_t::string:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a string");
    case nlohmann::json::value_t::boolean:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a boolean");
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number");
    case nlohmann::json::value_t::binary:
    case nlohmann::json::value_t::discarded: break;
    }
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "an unexpected value");
}

std::string excerpt(std::string_view s)
{
    constexpr std::size_t kMax = 40;
    std::string out = "\"";
    std::size_t i = 0;
    while (i < s.size() && i < kMax) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0x80 ? 1 : utf8Length(s.substr(i));
        if (c >= 0x20 && c != 0x7f && c != '"' && c != '\\' && n > 0) {
            out.append(s.substr(i, n));
            i += n;
        } else {
            // Control bytes, quotes and bytes that are not UTF-8 (a broken file's
            // last token) are shown as \xNN so that a message is always valid text.
            out += fmt::format("\\x{:02x}", c);
            ++i;
        }
    }
    return out + (i < s.size() ? "...\"" : "\"");
}

std::string fieldKey(std::string_view key)
{
    const bool plain = !key.empty() && key.size() <= 40 && std::all_of(key.begin(), key.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    return plain ? std::string(key) : excerpt(key);
}

std::string oneOf(const std::vector<std::string>& allowed)
{
    std::vector<std::string> quoted;
    for (const auto& a : allowed) quoted.push_back("\"" + a + "\"");
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "one of {}"), joined(quoted));
}

std::string fileEmpty()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file is empty");
}

std::string fileTooLarge(std::size_t bytes, std::size_t limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the file is {} bytes ({:.1f} MB); a job file may be at most {} bytes ({} MB)"),
        bytes, static_cast<double>(bytes) / (1024.0 * 1024.0), limit, limit / (1024 * 1024));
}

std::string fileCannotOpen(const std::string& reason)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot open: {}"), reason);
}

std::string fileUnreadable(const std::string& reason)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot read the file: {}"), reason);
}

std::string notAFile()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a regular file; a job file is a JSON document");
}

std::string notJson(std::size_t byte, std::size_t line, std::size_t column, const std::string& what)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a job file: JSON syntax error at byte {} (line {}, column {}): {}"),
        byte, line, column, what);
}

std::string nestedTooDeep(std::size_t byte, std::size_t line, std::size_t column, std::size_t limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "not a job file: arrays and objects nested more than {} deep at byte {} (line {}, column {})"),
        limit, byte, line, column);
}

std::string numberTooLarge(const std::string& token)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the number {} is too large for any dimension"),
                       excerpt(token));
}

std::string notAnObject(const nlohmann::json& root)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a job file: the document is {}, a job is a JSON object"),
                       kindOf(root));
}

std::string formatMissing()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a job file: it has no \"format\": \"taiwa-job\"");
}

std::string formatWrong(const nlohmann::json& value)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a job file: its \"format\" is {}, a job has \"taiwa-job\""),
        found(value));
}

std::string versionNewer(long long version, int supported)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP(
                           "taiwa::msg", "written by a newer Taiwa (format version {}); this program reads version {}"),
                       version, supported);
}

std::string versionUnknown(long long version, int supported)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "format version {} does not exist; this program reads version {}"), version,
        supported);
}

std::string missing(const std::string& expected)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "missing; it must be {}"), expected);
}

std::string wrongType(const std::string& expected, const nlohmann::json& v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be {}, found {}"), expected, found(v));
}

std::string notWhole(const nlohmann::json& v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be a whole number, found {}"), found(v));
}

std::string wholeOutOfRange(const nlohmann::json& v)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be a whole number from -2147483648 to 2147483647, found {}"),
        found(v));
}

std::string unknownField(const std::string& owner, const std::vector<std::string>& known)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "unknown field; {} has {}"), owner, joined(known));
}

std::string notOneOf(const std::vector<std::string>& allowed, const nlohmann::json& v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be {}, found {}"), oneOf(allowed), found(v));
}

std::string unknownModule(const std::string& name, const std::vector<std::string>& known)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "unknown module {}; this program knows {}"), excerpt(name),
                       joined(known));
}

std::string unknownStockShape(const std::string& shape, const std::vector<std::string>& known)
{
    std::vector<std::string> quoted;
    for (const auto& k : known) quoted.push_back("\"" + k + "\"");
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "unknown stock shape {}; this program knows {}"),
                       excerpt(shape), joined(quoted));
}

std::string cornerCount(std::size_t n)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "needs exactly four corner points P1..P4, found {}"), n);
}

std::string notAPoint(const nlohmann::json& v)
{
    if (v.is_array())
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be a point [x, y], found an array of {}"),
                           v.size());
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "must be a point [x, y], found {}"), kindOf(v));
}

std::string duplicateKey()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "given more than once; say it once so that it is clear which value counts");
}

}  // namespace taiwa::msg::io
