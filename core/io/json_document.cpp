// Parsing a job file's text to JSON, finding repeated keys, and wording
// nlohmann's parse errors for a machinist (json_document.h).
#include "io/json_document.h"

#include "io/job_messages.h"

#include <set>
#include <utility>

namespace taiwa::io {

using nlohmann::json;

std::string joinPath(JsonPath::const_iterator begin, JsonPath::const_iterator end)
{
    std::string out;
    for (auto it = begin; it != end; ++it) {
        if (!out.empty() && !it->starts_with("[")) out += '.';
        out += *it;
    }
    return out;
}

namespace {

// The part of an exception text after `marker`, up to `stop` (or the end).
std::string between(const std::string& text, const std::string& marker, const std::string& stop)
{
    const auto from = text.find(marker);
    if (from == std::string::npos) return {};
    const auto start = from + marker.size();
    return text.substr(start, text.find(stop, start) - start);
}

// 1-based line and column of a 0-based byte offset.
std::pair<std::size_t, std::size_t> lineAndColumn(std::string_view text, std::size_t offset)
{
    std::size_t line = 1, lineStart = 0;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i)
        if (text[i] == '\n') ++line, lineStart = i + 1;
    return {line, offset - lineStart + 1};
}

std::string describe(const json::parse_error& e, std::string_view text)
{
    const std::string what = e.what();
    std::string description = between(what, " - ", "; last read: '");
    if (description.empty()) description = between(what, ": ", "; last read: '");
    const auto lastRead = what.find("; last read: '");
    if (lastRead != std::string::npos) {
        std::string token = what.substr(lastRead + 14);
        if (!token.empty() && token.back() == '\'') token.pop_back();
        description += "; last read " + msg::io::excerpt(token);
    }
    // nlohmann's byte is 1-based and counts the character it failed on.
    const std::size_t offset = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    const auto [line, column] = lineAndColumn(text, offset);
    return msg::io::notJson(offset + 1, line, column, description);
}

// The offset at which the text opens an array or object nested deeper than
// kMaxNesting, if it does. Checked before parsing, so that no deep tree is
// ever built: copying, comparing or printing one recurses once per level.
std::optional<std::size_t> tooDeepAt(std::string_view text)
{
    std::size_t depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting) return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

// A second, DOM-free pass over a document (SAX) that knows where it is: it
// names every key given a second time in its object by its path, and where
// the parser stopped (a number too large for a double). It also remembers the
// last "module" string of each open object (the unit's). nlohmann's parse with
// a callback did the first job 20 times slower than a plain parse.
class DocumentWalker : public nlohmann::json_sax<json> {
public:
    std::vector<JsonPath> repeated;
    JsonPath errorPath;
    std::string errorModule;

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t& s) override
    {
        if (!frames_.empty() && frames_.back().object && frames_.back().key == "module") frames_.back().module = s;
        return value();
    }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_array() override { return close(); }
    bool key(string_t& k) override
    {
        Frame& top = frames_.back();
        if (!top.keys.insert(k).second && repeated.size() < 100) {
            JsonPath path = here(frames_.size() - 1);
            path.push_back(msg::io::fieldKey(k));
            repeated.push_back(std::move(path));
        }
        top.key = k;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override
    {
        errorPath = here(frames_.size());
        for (const Frame& f : frames_)
            if (f.object && !f.module.empty()) errorModule = f.module;
        return false;
    }

private:
    struct Frame {
        bool object;
        std::string key;         // objects: the member being read
        std::size_t index = 0;   // arrays: the element being read
        std::string module;      // objects: their "module" string, once read
        std::set<std::string> keys;
    };
    // The path of the first `depth` open frames.
    JsonPath here(std::size_t depth) const
    {
        JsonPath path;
        for (std::size_t i = 0; i < depth; ++i)
            path.push_back(frames_[i].object ? msg::io::fieldKey(frames_[i].key) : "[" + std::to_string(frames_[i].index) + "]");
        return path;
    }
    bool value()
    {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        return true;
    }
    bool open(bool object)
    {
        frames_.push_back({object, {}, 0, {}, {}});
        return true;
    }
    bool close()
    {
        frames_.pop_back();
        return value();
    }
    std::vector<Frame> frames_;
};

}  // namespace

ParsedDocument parseDocument(std::string_view text)
{
    ParsedDocument out;
    if (const auto deep = tooDeepAt(text)) {
        const auto [line, column] = lineAndColumn(text, *deep);
        out.error = msg::io::nestedTooDeep(*deep + 1, line, column, kMaxNesting);
        return out;
    }
    DocumentWalker walker;
    try {
        out.root = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        out.error = describe(e, text);
        return out;
    } catch (const json::exception& e) {
        // out_of_range 406: "number overflow parsing '1e400'"
        out.error = msg::io::numberTooLarge(between(e.what(), "parsing '", "'"));
        json::sax_parse(text.begin(), text.end(), &walker);
        out.errorPath = std::move(walker.errorPath);
        out.errorModule = std::move(walker.errorModule);
        return out;
    }
    json::sax_parse(text.begin(), text.end(), &walker);
    out.repeatedKeys = std::move(walker.repeated);
    return out;
}

}  // namespace taiwa::io
