// The dialect definitions as data files (dialect.h: readDialect,
// dialectLibrary): the shipped ones compiled in from resources/dialects/,
// the shop's own from ~/.config/taiwa/dialects, each checked key by key.
#include "post/dialect.h"

#include "builtin_data.h"
#include "io/data_files.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>

namespace taiwa::post {

namespace {

using json = nlohmann::json;

struct Refusal {
    std::string message;
};

class Reader {
public:
    Reader(const json& j, const std::string& source, const std::string& text) : j_(j), source_(source), text_(text) {}

    Dialect read()
    {
        if (!j_.is_object()) fail("(file)", "not a JSON object");
        for (const auto& [key, value] : j_.items())
            if (!kKeys.contains(key)) fail(key, "not a key of a dialect (a typo?)");
        if (j_.value("format", "") != "taiwa-dialect") fail("format", "must be \"taiwa-dialect\"");
        if (!j_.contains("version") || !j_["version"].is_number_integer() || j_["version"].get<int>() != 1)
            fail("version", "this program reads dialect definitions of version 1");
        Dialect d;
        d.source = source_;
        d.name = text("name", "");
        if (d.name.empty() || d.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
            fail("name", "must be a lower-case name of letters, digits and '-'");
        d.description = text("description", "");
        d.macroSyntax = text("macroSyntax", d.macroSyntax);
        if (d.macroSyntax != "fanuc" && d.macroSyntax != "linuxcnc") fail("macroSyntax", "must be \"fanuc\" or \"linuxcnc\"");
        const std::string syntax = text("syntax", "iso");
        if (syntax == "iso") d.syntax = Syntax::Iso;
        else if (syntax == "sinumerik") d.syntax = Syntax::Sinumerik;
        else if (syntax == "klartext") d.syntax = Syntax::Klartext;
        else fail("syntax", "must be \"iso\", \"sinumerik\" or \"klartext\"");
        d.fileExtension = text("fileExtension", d.fileExtension);
        if (d.fileExtension.empty() || d.fileExtension.size() > 8 ||
            d.fileExtension.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos)
            fail("fileExtension", "must be 1 to 8 lower-case letters or digits, without the dot");
        d.percentFraming = flag("percentFraming", d.percentFraming);
        d.programNumberLine = templ("programNumberLine", d.programNumberLine);
        d.sequenceNumbers = flag("sequenceNumbers", d.sequenceNumbers);
        d.sequenceStart = whole("sequenceStart", d.sequenceStart, 0, 99999);
        d.sequenceIncrement = whole("sequenceIncrement", d.sequenceIncrement, 1, 1000);
        d.sequenceMax = whole("sequenceMax", d.sequenceMax, d.sequenceStart, 99999999);
        d.maxLineLength = static_cast<std::size_t>(whole("maxLineLength", static_cast<int>(d.maxLineLength), 40, 100000));
        d.decimalPointAlways = flag("decimalPointAlways", d.decimalPointAlways);
        d.lengthDecimals = decimals("lengthDecimals", d.lengthDecimals);
        d.feedDecimals = decimals("feedDecimals", d.feedDecimals);
        d.upperCaseComments = flag("upperCaseComments", d.upperCaseComments);
        d.semicolonComments = flag("semicolonComments", d.semicolonComments || d.syntax == Syntax::Klartext);
        d.metricWord = text("metricWord", d.metricWord);
        d.inchWord = text("inchWord", d.inchWord);
        d.preamble = templates("preamble", d.preamble);
        d.plainWorkOffsets = whole("plainWorkOffsets", d.plainWorkOffsets, 1, 6);
        d.moreWorkOffsets = texts("moreWorkOffsets", d.moreWorkOffsets);
        static const std::regex offsetOrRange(R"(G[0-9]+(\.[0-9])?|G[0-9]+\.\.G[0-9]+)");
        for (const auto& w : d.moreWorkOffsets)
            if (!std::regex_match(w, offsetOrRange))
                fail("moreWorkOffsets", "'" + w + "' is neither a G code (\"G59.1\") nor a range (\"G505..G599\")");
        d.extendedWorkOffsets = whole("extendedWorkOffsets", d.extendedWorkOffsets, 0, 300);
        d.extendedWorkOffset = text("extendedWorkOffset", d.extendedWorkOffset);
        mustFill("extendedWorkOffset", d.extendedWorkOffset, "{n}", fmt::arg("n", 1));
        d.retract = templates("retract", d.retract);
        d.toolChange = templ("toolChange", d.toolChange);
        d.lengthOffset = templ("lengthOffset", d.lengthOffset);
        d.lengthOffsetWithZ = flag("lengthOffsetWithZ", d.lengthOffsetWithZ);
        for (auto [key, field] : std::initializer_list<std::pair<const char*, std::string*>>{
                 {"spindleClockwise", &d.spindleClockwise}, {"spindleCounterClockwise", &d.spindleCounterClockwise},
                 {"spindleStop", &d.spindleStop}, {"coolantOn", &d.coolantOn}, {"coolantOff", &d.coolantOff},
                 {"drill", &d.drill}, {"peckDrill", &d.peckDrill}, {"cycleCancel", &d.cycleCancel},
                 {"cycleRetract", &d.cycleRetract}, {"programEnd", &d.programEnd}, {"tap", &d.tap},
                 {"ream", &d.ream}, {"bore", &d.bore}})
            *field = text(key, *field);
        d.rigidTapping = text("rigidTapping", d.rigidTapping);
        mustFill("rigidTapping", d.rigidTapping, "{rpm}", fmt::arg("rpm", 100));
        d.boreDwell = flag("boreDwell", d.boreDwell);
        const std::string dwell = text("dwellWord", std::string(1, d.dwellWord));
        if (dwell != "P" && dwell != "X" && dwell != "F") fail("dwellWord", "must be \"P\", \"X\" or \"F\"");
        d.dwellWord = dwell[0];
        d.oneBlockRoughingCycle = flag("oneBlockRoughingCycle", d.oneBlockRoughingCycle);
        return d;
    }

private:
    static inline const std::set<std::string> kKeys{
        "format", "version", "name", "description", "macroSyntax", "syntax", "fileExtension", "percentFraming",
        "programNumberLine", "semicolonComments", "metricWord", "inchWord", "plainWorkOffsets", "extendedWorkOffset",
        "oneBlockRoughingCycle",
        "sequenceNumbers", "sequenceStart", "sequenceIncrement", "sequenceMax", "maxLineLength", "decimalPointAlways",
        "lengthDecimals", "feedDecimals", "upperCaseComments", "preamble", "moreWorkOffsets", "extendedWorkOffsets",
        "retract", "toolChange", "lengthOffset", "lengthOffsetWithZ", "spindleClockwise", "spindleCounterClockwise",
        "spindleStop", "coolantOn", "coolantOff", "drill", "peckDrill", "cycleCancel", "cycleRetract", "dwellWord",
        "programEnd", "tap", "rigidTapping", "ream", "bore", "boreDwell"};

    [[noreturn]] void fail(const std::string& key, const std::string& what) const
    {
        const int line = io::lineOfKey(text_, key);
        throw Refusal{source_ + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + key + ": " + what};
    }
    const json* find(const char* key) const { return j_.contains(key) ? &j_[key] : nullptr; }
    std::string text(const char* key, const std::string& fallback) const
    {
        const json* v = find(key);
        if (!v) return fallback;
        if (!v->is_string()) fail(key, "must be a text");
        return v->get<std::string>();
    }
    bool flag(const char* key, bool fallback) const
    {
        const json* v = find(key);
        if (!v) return fallback;
        if (!v->is_boolean()) fail(key, "must be true or false");
        return v->get<bool>();
    }
    int whole(const char* key, int fallback, int low, int high) const
    {
        const json* v = find(key);
        if (!v) return fallback;
        if (!v->is_number_integer() || v->get<long long>() < low || v->get<long long>() > high)
            fail(key, fmt::format("must be a whole number from {} to {}", low, high));
        return v->get<int>();
    }
    // A template with the named fields the writer fills in; a broken one is
    // refused now rather than at the first export.
    // Refuses `t` unless fmt can fill it with `args` (the fields `fields` names).
    template <class... Args>
    void mustFill(const char* key, const std::string& t, const char* fields, const Args&... args) const
    {
        try {
            static_cast<void>(fmt::format(fmt::runtime(t), args...));
        } catch (const fmt::format_error& e) {
            fail(key, std::string("not a template this program can fill: ") + e.what() + " (fields: " + fields + ")");
        }
    }
    // A template of the program's frame: {units} {workOffset} {tool} {number} {name}.
    void mustFillFrame(const char* key, const std::string& t) const
    {
        mustFill(key, t, "{units} {workOffset} {tool} {number} {name}", fmt::arg("units", "G21"), fmt::arg("workOffset", "G54"),
                 fmt::arg("tool", 1), fmt::arg("number", 1000), fmt::arg("name", "JOB"));
    }
    std::string templ(const char* key, const std::string& fallback) const
    {
        const std::string t = text(key, fallback);
        mustFillFrame(key, t);
        return t;
    }
    std::vector<std::string> texts(const char* key, const std::vector<std::string>& fallback) const
    {
        const json* v = find(key);
        if (!v) return fallback;
        if (!v->is_array() || !std::all_of(v->begin(), v->end(), [](const json& x) { return x.is_string(); }))
            fail(key, "must be a list of texts");
        return v->get<std::vector<std::string>>();
    }
    std::vector<std::string> templates(const char* key, const std::vector<std::string>& fallback) const
    {
        const std::vector<std::string> ts = texts(key, fallback);
        for (const auto& t : ts) mustFillFrame(key, t);
        return ts;
    }
    Decimals decimals(const char* key, Decimals fallback) const
    {
        const json* v = find(key);
        if (!v) return fallback;
        if (!v->is_object() || !v->contains("mm") || !v->contains("inch") || !(*v)["mm"].is_number_integer() ||
            !(*v)["inch"].is_number_integer() || (*v)["mm"].get<int>() < 0 || (*v)["mm"].get<int>() > 6 ||
            (*v)["inch"].get<int>() < 0 || (*v)["inch"].get<int>() > 6)
            fail(key, "must be {\"mm\": n, \"inch\": n} with n from 0 to 6");
        return {(*v)["mm"].get<int>(), (*v)["inch"].get<int>()};
    }

    const json& j_;
    const std::string& source_;
    const std::string& text_;
};

struct Library {
    std::vector<Dialect> dialects;
    std::vector<std::string> problems;
};

const Library& library()
{
    static const Library lib = [] {
        Library l;
        for (const auto& [text, source] : builtin::kDialects) {
            auto d = readDialect(text, source);
            if (!d) throw std::logic_error("a shipped dialect definition is broken: " + d.error());
            l.dialects.push_back(std::move(*d));
        }
        io::addShopFiles(l.dialects, l.problems, io::userDataFolder("dialects"), readDialect,
                         [](const Dialect& d) { return d.name; }, "dialects");
        return l;
    }();
    return lib;
}

}  // namespace

Result<Dialect> readDialect(const std::string& text, const std::string& source)
{
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Failure{source + ":" + std::to_string(io::lineOfByte(text, e.byte)) + ": not valid JSON"};
    }
    try {
        return Reader(j, source, text).read();
    } catch (const Refusal& r) {
        return Failure{r.message};
    }
}

const std::vector<Dialect>& dialectLibrary() { return library().dialects; }
const std::vector<std::string>& dialectLibraryProblems() { return library().problems; }

const Dialect& fanucDialect() { return *findDialect("fanuc"); }
const Dialect& linuxcncDialect() { return *findDialect("linuxcnc"); }

}  // namespace taiwa::post
