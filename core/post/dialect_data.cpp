// The dialect definitions as data files (dialect.h: readDialect,
// dialectLibrary): the shipped ones compiled in from resources/dialects/,
// the shop's own from ~/.config/taiwa/dialects, each checked key by key.
#include "post/dialect.h"

#include "builtin_data.h"
#include "io/data_files.h"
#include "io/data_reader.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <tuple>
#include <stdexcept>

namespace taiwa::post {

namespace {

using json = nlohmann::json;

// How a word's text is judged against the dialect's syntax.
enum class Role {
    MFunctions,  // spindle, coolant, program end: M words only
    NoMotion,    // tool change, offsets, cycles, frame: no axis word, no G0 to G3
    Retract,     // may move (it is the retract)
};

// One "{name:spec}" of a template.
struct Placeholder {
    std::string name, spec;
};

class Reader {
public:
    Reader(const std::string& text, const std::string& source) : r_(text, source) {}

    Dialect read()
    {
        const json& j = r_.root();
        for (const auto& [key, value] : j.items())
            if (!kKeys.contains(key)) fail(key, "not a key of a dialect (a typo?)");
        if (r_.text("format", "") != "taiwa-dialect") fail("format", "must be \"taiwa-dialect\"");
        const json& version = r_.at(j, "version", "version");
        if (!version.is_number_integer() || version.get<long long>() != 1) fail("version", "this program reads dialect definitions of version 1");
        Dialect d;
        d.source = r_.source();
        d.name = r_.text("name", "", 32);
        if (d.name.empty() || d.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
            fail("name", "must be a lower-case name of letters, digits and '-'");
        d.description = r_.text("description", "");
        d.macroSyntax = r_.text("macroSyntax", d.macroSyntax);
        if (d.macroSyntax != "fanuc" && d.macroSyntax != "linuxcnc") fail("macroSyntax", "must be \"fanuc\" or \"linuxcnc\"");
        const std::string syntax = r_.text("syntax", "iso");
        if (syntax == "iso") d.syntax = Syntax::Iso;
        else if (syntax == "sinumerik") d.syntax = Syntax::Sinumerik;
        else if (syntax == "klartext") d.syntax = Syntax::Klartext;
        else fail("syntax", "must be \"iso\", \"sinumerik\" or \"klartext\"");
        syntax_ = d.syntax;
        d.fileExtension = r_.text("fileExtension", d.fileExtension);
        if (d.fileExtension.empty() || d.fileExtension.size() > 8 ||
            d.fileExtension.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos)
            fail("fileExtension", "must be 1 to 8 lower-case letters or digits, without the dot");
        // The tape must not take the name of another file of the export set,
        // nor of the job beside it: an export removes other dialects' tapes.
        static const std::set<std::string> taken{"taiwa", "json", "html", "pdf", "txt", "tbl", "lock", "set", "dxf", "step", "stp", "sqlite", "png"};
        if (taken.contains(d.fileExtension))
            fail("fileExtension", "'" + d.fileExtension + "' is the kind of another file (the job, the sheet, the steps); give the tape's own");
        d.percentFraming = r_.flag("percentFraming", d.percentFraming);
        d.sequenceNumbers = r_.flag("sequenceNumbers", d.sequenceNumbers);
        d.sequenceStart = r_.whole("sequenceStart", d.sequenceStart, 0, 99999);
        d.sequenceIncrement = r_.whole("sequenceIncrement", d.sequenceIncrement, 1, 1000);
        d.sequenceMax = r_.whole("sequenceMax", d.sequenceMax, d.sequenceStart, 99999999);
        d.maxLineLength = static_cast<std::size_t>(r_.whole("maxLineLength", static_cast<int>(d.maxLineLength), 40, 100000));
        maxLine_ = d.maxLineLength;
        d.decimalPointAlways = r_.flag("decimalPointAlways", d.decimalPointAlways);
        d.lengthDecimals = decimals("lengthDecimals", d.lengthDecimals);
        d.feedDecimals = decimals("feedDecimals", d.feedDecimals);
        d.upperCaseComments = r_.flag("upperCaseComments", d.upperCaseComments);
        d.semicolonComments = r_.flag("semicolonComments", d.semicolonComments || d.syntax == Syntax::Klartext);
        d.metricWord = word("metricWord", d.metricWord, Role::NoMotion, true);
        d.inchWord = word("inchWord", d.inchWord, Role::NoMotion, true);
        d.plainWorkOffsets = r_.whole("plainWorkOffsets", d.plainWorkOffsets, 1, 6);
        d.moreWorkOffsets = texts("moreWorkOffsets", d.moreWorkOffsets);
        static const std::regex offsetOrRange(R"(G[0-9]{1,4}(\.[0-9])?|G[0-9]{1,4}\.\.G[0-9]{1,4})");
        for (const auto& w : d.moreWorkOffsets)
            if (!std::regex_match(w, offsetOrRange))
                fail("moreWorkOffsets", "'" + w + "' is neither a G code (\"G59.1\") nor a range (\"G505..G599\")");
        d.extendedWorkOffsets = r_.whole("extendedWorkOffsets", d.extendedWorkOffsets, 0, 300);
        d.extendedWorkOffset = r_.text("extendedWorkOffset", d.extendedWorkOffset);
        if (d.extendedWorkOffsets > 0 || r_.find(r_.root(), "extendedWorkOffset"))
            expand("extendedWorkOffset", d.extendedWorkOffset, Role::NoMotion, {"n"}, {"n"},
                   fmt::arg("n", std::max(d.extendedWorkOffsets, 1)));
        // The widest work offset this dialect writes, for the preamble's {workOffset}.
        std::string widestOffset = d.extendedWorkOffsets > 0
                                       ? fmt::format(fmt::runtime(d.extendedWorkOffset), fmt::arg("n", d.extendedWorkOffsets))
                                       : std::string("G59");
        for (const auto& w : d.moreWorkOffsets)
            if (w.size() > widestOffset.size() && w.find("..") == std::string::npos) widestOffset = w;
        const std::string programNumberLine = r_.text("programNumberLine", d.programNumberLine);
        if (!programNumberLine.empty())
            expand("programNumberLine", programNumberLine, Role::NoMotion, {"number", "name"}, {"number"},
                   fmt::arg("number", 99999), fmt::arg("name", std::string(40, 'N')));
        d.programNumberLine = programNumberLine;
        d.preamble = texts("preamble", d.preamble);
        for (const auto& t : d.preamble)
            for (const std::string* units : {&d.metricWord, &d.inchWord})
                expand("preamble", t, Role::NoMotion, {"units", "workOffset"}, {}, fmt::arg("units", *units),
                       fmt::arg("workOffset", widestOffset));
        d.retract = texts("retract", d.retract);
        if (d.retract.empty()) fail("retract", "must name at least one block: the tape retracts before each tool change");
        for (const auto& t : d.retract) plain("retract", t, Role::Retract, true);
        d.toolChange = r_.text("toolChange", d.toolChange);
        expand("toolChange", d.toolChange, Role::NoMotion, {"tool"}, {"tool"}, fmt::arg("tool", 99999));
        d.lengthOffset = r_.text("lengthOffset", d.lengthOffset);
        if (!d.lengthOffset.empty()) expand("lengthOffset", d.lengthOffset, Role::NoMotion, {"tool"}, {}, fmt::arg("tool", 99999));
        d.lengthOffsetWithZ = r_.flag("lengthOffsetWithZ", d.lengthOffsetWithZ);
        for (auto [key, field, role, required] : std::initializer_list<std::tuple<const char*, std::string*, Role, bool>>{
                 {"spindleClockwise", &d.spindleClockwise, Role::MFunctions, true},
                 {"spindleCounterClockwise", &d.spindleCounterClockwise, Role::MFunctions, true},
                 {"spindleStop", &d.spindleStop, Role::MFunctions, true},
                 {"coolantOn", &d.coolantOn, Role::MFunctions, true},
                 {"coolantOff", &d.coolantOff, Role::MFunctions, true},
                 {"programEnd", &d.programEnd, Role::MFunctions, true},
                 {"drill", &d.drill, Role::NoMotion, true}, {"peckDrill", &d.peckDrill, Role::NoMotion, true},
                 {"cycleCancel", &d.cycleCancel, Role::NoMotion, false},
                 {"cycleRetract", &d.cycleRetract, Role::NoMotion, false}, {"tap", &d.tap, Role::NoMotion, true},
                 {"ream", &d.ream, Role::NoMotion, true}, {"bore", &d.bore, Role::NoMotion, true}})
            *field = word(key, *field, role, required);
        d.rigidTapping = r_.text("rigidTapping", d.rigidTapping);
        if (!d.rigidTapping.empty()) expand("rigidTapping", d.rigidTapping, Role::NoMotion, {"rpm"}, {"rpm"}, fmt::arg("rpm", "99999"));
        d.boreDwell = r_.flag("boreDwell", d.boreDwell);
        const std::string dwell = r_.text("dwellWord", std::string(1, d.dwellWord));
        if (dwell != "P" && dwell != "X" && dwell != "F") fail("dwellWord", "must be \"P\", \"X\" or \"F\"");
        d.dwellWord = dwell[0];
        d.oneBlockRoughingCycle = r_.flag("oneBlockRoughingCycle", d.oneBlockRoughingCycle);
        if (const json* h = r_.find(j, "highlighting")) d.highlighting = highlighting(*h);
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
        "programEnd", "tap", "rigidTapping", "ream", "bore", "boreDwell", "highlighting"};

    // The station's colours: {"keywords": ["BLK FORM", ...], "addressesApart": false}.
    Highlighting highlighting(const json& h) const
    {
        r_.onlyKeys(h, "highlighting", {"keywords", "addressesApart"});
        Highlighting out;
        if (const json* k = r_.find(h, "keywords")) out.keywords = r_.texts(*k, "highlighting.keywords", 60, 32);
        for (const std::string& w : out.keywords)
            if (w.front() == ' ' || w.back() == ' ' || w.find_first_of(";()") != std::string::npos)
                fail("highlighting.keywords", "'" + w + "' must be a word of the tape, without spaces around it, ';' or parentheses");
        if (const json* a = r_.find(h, "addressesApart")) out.addressesApart = r_.boolean(*a, "highlighting.addressesApart");
        return out;
    }

    [[noreturn]] void fail(const std::string& key, const std::string& what) const { r_.fail(key, what); }

    std::vector<std::string> texts(const char* key, const std::vector<std::string>& fallback) const
    {
        const json* v = r_.find(r_.root(), key);
        if (!v) return fallback;
        if (!v->is_array() || v->size() > 20) fail(key, "must be a list of at most 20 texts");
        std::vector<std::string> out;
        for (const json& x : *v) out.push_back(r_.text(x, key, 200, true));
        return out;
    }
    Decimals decimals(const char* key, Decimals fallback) const
    {
        const json* v = r_.find(r_.root(), key);
        if (!v) return fallback;
        const std::string form = "must be {\"mm\": n, \"inch\": n} with n from 0 to 6";
        if (!v->is_object() || v->size() != 2 || !v->contains("mm") || !v->contains("inch")) fail(key, form);
        return {static_cast<int>(r_.whole((*v)["mm"], std::string(key) + ".mm", 0, 6)),
                static_cast<int>(r_.whole((*v)["inch"], std::string(key) + ".inch", 0, 6))};
    }

    // A word without fields (a brace would reach the tape as it stands).
    std::string word(const char* key, const std::string& fallback, Role role, bool required) const
    {
        const std::string w = r_.text(key, fallback);
        plain(key, w, role, required);
        return w;
    }
    void plain(const char* key, const std::string& w, Role role, bool required) const
    {
        if (w.find_first_of("{}") != std::string::npos) fail(key, "takes no fields: '{' and '}' are not words of a tape");
        if (required && w.find_first_not_of(' ') == std::string::npos)
            fail(key, "must not be empty: a tape without it would lack a word the machine needs");
        judge(key, w, role);
    }

    // The fields a template uses; refuses a field it may not use, a width or
    // precision over 16 and fields inside a field's format (its width would
    // be taken from an argument), before anything is expanded.
    std::set<std::string> fieldsOf(const char* key, const std::string& t, const std::vector<std::string>& allowed) const
    {
        static const std::regex spec(R"((.?[<>^])?[-+ ]?#?0?([0-9]*)(\.([0-9]+))?[a-zA-Z]?)");
        std::set<std::string> used;
        const auto list = [&] {
            std::string s;
            for (const auto& a : allowed) s += (s.empty() ? "{" : ", {") + a + "}";
            return s.empty() ? std::string("none") : s;
        };
        for (std::size_t i = 0; i < t.size(); ++i) {
            if (t[i] == '}') {
                if (i + 1 < t.size() && t[i + 1] == '}') { ++i; continue; }
                fail(key, "has a '}' that closes no field (write '}}' for the character)");
            }
            if (t[i] != '{') continue;
            if (i + 1 < t.size() && t[i + 1] == '{') { ++i; continue; }
            const auto close = t.find('}', i);
            if (close == std::string::npos) fail(key, "has a '{' that is never closed (write '{{' for the character)");
            const std::string inside = t.substr(i + 1, close - i - 1);
            if (inside.find('{') != std::string::npos) fail(key, "has a field inside a field; fields: " + list());
            const auto colon = inside.find(':');
            Placeholder p{inside.substr(0, colon), colon == std::string::npos ? "" : inside.substr(colon + 1)};
            if (std::find(allowed.begin(), allowed.end(), p.name) == allowed.end())
                fail(key, "not a template this program can fill: it uses {" + p.name + "}, which this word cannot be given; its fields: " + list());
            std::smatch m;
            if (!std::regex_match(p.spec, m, spec)) fail(key, "{" + inside + "}: not a format this program reads (as {number:04d})");
            if ((m[2].matched && m[2].length() > 2) || (m[2].matched && m[2].length() > 0 && std::stoi(m[2].str()) > 16) ||
                (m[4].matched && (m[4].length() > 2 || std::stoi(m[4].str()) > 16)))
                fail(key, "{" + inside + "}: a width or precision over 16 characters is not a word of a tape");
            used.insert(p.name);
            i = close;
        }
        return used;
    }
    // Refuses `t` unless it uses only the fields `allowed`, each it must
    // (`required`), and expands, with the widest values the tape can give
    // (`args`), into a block within the line length and the dialect's syntax.
    template <class... Args>
    void expand(const char* key, const std::string& t, Role role, const std::vector<std::string>& allowed,
                const std::vector<std::string>& required, const Args&... args) const
    {
        const std::set<std::string> used = fieldsOf(key, t, allowed);
        for (const auto& r : required)
            if (!used.contains(r)) fail(key, "must use {" + r + "}");
        std::string expanded;
        try {
            expanded = fmt::format(fmt::runtime(t), args...);
        } catch (const fmt::format_error& e) {
            fail(key, std::string("not a template this program can fill: ") + e.what());
        }
        if (expanded.size() > maxLine_)
            fail(key, fmt::format("becomes a block of {} characters; the dialect's maxLineLength is {}", expanded.size(), maxLine_));
        if (expanded.find_first_not_of(' ') == std::string::npos) fail(key, "must not be empty");
        judge(key, expanded, role);
    }

    // The words as the dialect's reader will take them: no '%' (the tape's
    // frame) nor ';' (a comment that would swallow the rest of the block),
    // comments closed (ISO: '(' to ')', never nested; Siemens and
    // HEIDENHAIN: parentheses balanced), and no motion where none belongs.
    void judge(const char* key, const std::string& w, Role role) const
    {
        if (w.find('%') != std::string::npos) fail(key, "holds '%', which frames the tape; the dialect's percentFraming writes it");
        if (w.find(';') != std::string::npos) fail(key, "holds ';', which would turn the rest of the block into a comment");
        std::string words;  // outside comments
        int depth = 0;
        for (const char c : w) {
            if (c == '(') {
                if (syntax_ == Syntax::Iso && depth > 0) fail(key, "opens a comment inside a comment; ISO comments do not nest");
                ++depth;
            } else if (c == ')') {
                if (depth == 0) fail(key, "closes a parenthesis it never opened");
                --depth;
            } else if (depth == 0 || syntax_ != Syntax::Iso) {
                words += c;
            }
        }
        if (depth != 0) fail(key, "opens a parenthesis it never closes");
        std::string upper;
        for (const char c : words) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (role == Role::MFunctions) {
            static const std::regex mWords(R"(\s*(M[0-9]{1,3}\s*)+)");
            if (!std::regex_match(upper, mWords)) fail(key, "must be M words only (as \"M8\"), not '" + w + "'");
            return;
        }
        if (role == Role::Retract) return;
        if (syntax_ == Syntax::Klartext) {
            static const std::regex motion(R"((^|\s)(L|LP|C|CP|CC|CR|CT|CTP|RND|CHF|APPR|DEP|FK|FL|FC)(\s|$)|(^|\s)[XYZABCUVW][-+]?[0-9])");
            if (std::regex_search(upper, motion)) fail(key, "moves an axis; only the retract may");
            return;
        }
        // ISO and Siemens: an axis word or G0 to G3 (as "X0", "G00", "G1").
        static const std::regex motion(R"((^|[^A-Z])([XYZABCUVWIJK]\s*[-+]?[0-9.]|G\s*0*[0-3](\.0*)?([^0-9.]|$)))");
        if (std::regex_search(upper, motion)) fail(key, "moves an axis; only the retract may");
    }

    io::DataReader r_;
    Syntax syntax_ = Syntax::Iso;
    std::size_t maxLine_ = 255;
};

// The shipped dialects, then the shop's (io::addShopFiles).
const io::DataLibrary<Dialect>& library()
{
    static const auto lib = io::loadDataLibrary<Dialect>(builtin::kDialects, io::userDataFolder("dialects"), readDialect,
                                                         [](const Dialect& d) { return d.name; }, "dialects");
    return lib;
}

}  // namespace

Result<Dialect> readDialect(const std::string& text, const std::string& source)
{
    return io::readData<Reader>(text, source);
}

const std::vector<Dialect>& dialectLibrary() { return library().items; }
const std::vector<std::string>& dialectLibraryProblems() { return library().problems; }

const Dialect& fanucDialect() { return *findDialect("fanuc"); }
const Dialect& linuxcncDialect() { return *findDialect("linuxcnc"); }

}  // namespace taiwa::post
