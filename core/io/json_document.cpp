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

// Follows the parser's events to know where it is, so that a repeated key
// can be named by its path. One frame per open object or array.
class KeyTracker {
public:
    bool event(json::parse_event_t e, const json& parsed)
    {
        switch (e) {
        case json::parse_event_t::object_start: frames_.push_back({true, {}, {}, 0}); break;
        case json::parse_event_t::array_start: frames_.push_back({false, {}, {}, 0}); break;
        case json::parse_event_t::key: onKey(parsed.get_ref<const std::string&>()); break;
        case json::parse_event_t::value: elementDone(); break;
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end:
            if (!frames_.empty()) frames_.pop_back();
            elementDone();
            break;
        }
        return true;  // keep everything
    }
    std::vector<JsonPath> repeated;

private:
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key;    // objects: the member being read
        std::size_t index;  // arrays: the element being read
    };

    void elementDone()
    {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    }
    void onKey(const std::string& key)
    {
        Frame& top = frames_.back();
        if (!top.keys.insert(key).second && repeated.size() < 100) {
            JsonPath path;
            for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
                path.push_back(frames_[i].object ? msg::io::fieldKey(frames_[i].key)
                                                 : "[" + std::to_string(frames_[i].index) + "]");
            path.push_back(msg::io::fieldKey(key));
            repeated.push_back(std::move(path));
        }
        top.key = key;
    }

    std::vector<Frame> frames_;
};

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

// Where a number too large for a double stands: a SAX pass that follows the
// keys and indices, and stops at the parse error nlohmann reports there. It
// also remembers the last "module" string of each open object (the unit's).
class OverflowLocator : public nlohmann::json_sax<json> {
public:
    JsonPath path;
    std::string module;

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
        frames_.back().key = k;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override
    {
        for (const Frame& f : frames_) {
            path.push_back(f.object ? msg::io::fieldKey(f.key) : "[" + std::to_string(f.index) + "]");
            if (f.object && !f.module.empty()) module = f.module;
        }
        return false;
    }

private:
    struct Frame {
        bool object;
        std::string key;
        std::size_t index = 0;
        std::string module;
    };
    bool value()
    {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        return true;
    }
    bool open(bool object)
    {
        frames_.push_back({object, {}, 0, {}});
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
    KeyTracker tracker;
    try {
        out.root = json::parse(
            text.begin(), text.end(),
            [&tracker](int, json::parse_event_t e, json& parsed) { return tracker.event(e, parsed); });
        out.repeatedKeys = std::move(tracker.repeated);
    } catch (const json::parse_error& e) {
        out.error = describe(e, text);
    } catch (const json::exception& e) {
        // out_of_range 406: "number overflow parsing '1e400'"
        out.error = msg::io::numberTooLarge(between(e.what(), "parsing '", "'"));
        OverflowLocator where;
        json::sax_parse(text.begin(), text.end(), &where);
        out.errorPath = std::move(where.path);
        out.errorModule = std::move(where.module);
    }
    return out;
}

}  // namespace taiwa::io
