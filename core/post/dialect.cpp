// The table of dialects and its lookups (post.h: dialectNames, isDialect),
// and the work offsets a dialect's controller offers (workOffsetProblem).
#include "post/dialect.h"

#include "post/post.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <regex>
#include <stdexcept>

namespace taiwa::post {


namespace {

// A range entry of moreWorkOffsets ("G505..G599") as its two numbers.
std::optional<std::pair<int, int>> rangeOf(const std::string& entry)
{
    static const std::regex range(R"(G([0-9]+)\.\.G([0-9]+))");
    std::smatch m;
    if (!std::regex_match(entry, m, range)) return std::nullopt;
    return std::pair{std::stoi(m[1].str()), std::stoi(m[2].str())};
}

}  // namespace

std::string workOffsetWords(const Dialect& d, const std::string& requested)
{
    // One spelling: upper case, no spaces, then "G54.1 P7".
    std::string code;
    for (const char c : requested) {
        const auto u = static_cast<unsigned char>(c);
        if (!std::isspace(u)) code += static_cast<char>(std::toupper(u));
    }
    // The offsets as codes, joined by templates ("G54 to G59, G59.1 and
    // G59.3"), so that the station shows the list in its language.
    const auto to = [](const std::string& first, const std::string& last) {
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} to {}"), first, last);
    };
    const auto and_ = [](const std::string& list, const std::string& item) {
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {}"), list, item);
    };
    std::string offers = d.plainWorkOffsets == 1 ? std::string("G54") : to("G54", fmt::format("G{}", 53 + d.plainWorkOffsets));
    for (std::size_t i = 0; i < d.moreWorkOffsets.size(); ++i) {
        const auto range = rangeOf(d.moreWorkOffsets[i]);
        const std::string entry = range ? to(fmt::format("G{}", range->first), fmt::format("G{}", range->second)) : d.moreWorkOffsets[i];
        offers = i + 1 == d.moreWorkOffsets.size() ? and_(offers, entry)
                                                   : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}, {}"), offers, entry);
    }
    const auto extendedWords = [&](int n) { return fmt::format(fmt::runtime(d.extendedWorkOffset), fmt::arg("n", n)); };
    if (d.extendedWorkOffsets > 0) {
        // "G54.1 P1 to P48": the last word of the template, the number in it.
        const std::string last = extendedWords(d.extendedWorkOffsets);
        offers = and_(offers, to(extendedWords(1), last.substr(last.rfind(' ') + 1)));
    }
    const auto refuse = [&](const std::string& why) {  // the operator's work offset
        return Refusal(
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "work offset '{}' cannot be posted for {}: {}; {} offers {}"), requested, d.name, why, d.name,
                        offers));
    };

    // G54.1 P7 (FANUC) and G154 P7 (Haas) are the same extended offset.
    static const std::regex plain(R"(G5[4-9])"), other(R"(G59\.[0-9]|G5[0-9]{2})"), extended(R"(G(54\.1|154)P([0-9]{1,3}))");
    std::smatch m;
    if (std::regex_match(code, plain)) {
        if (code[2] - '4' < d.plainWorkOffsets) return code;
        throw refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no {}"), d.name, code));
    }
    if (std::regex_match(code, m, extended)) {
        if (d.extendedWorkOffsets == 0)
            throw refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no {}"), d.name,
                                     m[1].str() == "154" ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "G154 P (Haas' extended work offsets)")
                                                         : TAIWA_TRANSLATE_NOOP("taiwa::msg", "G54.1 P (FANUC's extended work offsets)")));
        const int p = std::stoi(m[2].str());
        if (p < 1 || p > d.extendedWorkOffsets) throw refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "there is no {}"), extendedWords(p)));
        return extendedWords(p);
    }
    if (std::regex_match(code, other)) {
        for (const auto& entry : d.moreWorkOffsets) {
            if (entry == code) return code;
            const auto range = rangeOf(entry);
            if (range && code.find('.') == std::string::npos) {
                const int g = std::stoi(code.substr(1));
                if (g >= range->first && g <= range->second) return code;
            }
        }
        throw refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has no {}"), d.name, code));
    }
    throw refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a work offset"));
}

namespace {

bool posts(const Dialect& d, Task task)
{
    switch (task) {
    case Task::MillingTape: return true;
    case Task::LatheTape: return d.syntax != Syntax::Klartext;
    case Task::ProbingPrograms: return d.syntax == Syntax::Iso;
    }
    return false;
}

// Why a language gets no probing programs: what the manual pages read for it
// (docs/probing.md, a section per dialect) did not confirm. A probing
// program written from memory can drive the stylus into the part.
std::string whyNoProbing(Syntax syntax)
{
    switch (syntax) {
    case Syntax::Sinumerik:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the SINUMERIK manual pages at hand do not say which probe edge MEAS=1 and MEAS=-1 take, how "
               "$AC_MEA reports a touch not made, nor that STOPRE must come before $AA_MW is read; "
               "see docs/probing.md");
    case Syntax::Klartext:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the TNC manual pages at hand do not say what TCH PROBE 0 does when nothing is touched, and the "
               "one way found to write a preset from a program, FN 17: SYSWRITE, is locked behind the machine "
               "maker's code number; see docs/probing.md");
    case Syntax::Iso: break;
    }
    return "see docs/probing.md";
}

}  // namespace

Result<void> canPost(const Dialect& d, Task task)
{
    if (posts(d, task)) return {};
    std::string can;
    for (const Dialect& other : dialectLibrary())
        if (posts(other, task)) can += (can.empty() ? "" : ", ") + other.name;
    if (task == Task::LatheTape)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} dialect writes no lathe tapes (Klartext is a milling control's language); {} can"), d.name, can)};
    return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} dialect writes no probing unit's programs; {} can ({})"), d.name, can,
                       whyNoProbing(d.syntax))};
}

const Dialect* findDialect(const std::string& name)
{
    for (const Dialect& d : dialectLibrary())
        if (d.name == name) return &d;
    return nullptr;
}

const Dialect& dialectNamed(const std::string& name)
{
    if (const Dialect* d = findDialect(name)) return *d;
    throw Refusal("unknown dialect '" + name + "'");
}

}  // namespace taiwa::post

namespace taiwa {

std::vector<std::string> dialectNames()
{
    std::vector<std::string> names;
    for (const post::Dialect& d : post::dialectLibrary()) names.push_back(d.name);
    return names;
}

bool isDialect(const std::string& name) { return post::findDialect(name) != nullptr; }

std::optional<Diagnostic> workOffsetProblem(const std::string& dialect, const std::string& workOffset)
{
    const post::Dialect* d = post::findDialect(dialect);
    if (!d) return std::nullopt;
    try {
        post::workOffsetWords(*d, workOffset);
    } catch (const Refusal& e) {
        return Diagnostic{Severity::Error, std::nullopt, "", "workOffset", e.what()};
    }
    return std::nullopt;
}

}  // namespace taiwa
