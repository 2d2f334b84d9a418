// The table of dialects and its lookups (post.h: dialectNames, isDialect),
// and the work offsets a dialect's controller offers (workOffsetProblem).
#include "post/dialect.h"

#include "post/post.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <regex>
#include <stdexcept>

namespace taiwa::post {


std::string workOffsetWords(const Dialect& d, const std::string& requested)
{
    // One spelling: upper case, no spaces, then "G54.1 P7".
    std::string code;
    for (const char c : requested) {
        const auto u = static_cast<unsigned char>(c);
        if (!std::isspace(u)) code += static_cast<char>(std::toupper(u));
    }
    std::string offers = "G54 to G59";
    for (std::size_t i = 0; i < d.moreWorkOffsets.size(); ++i)
        offers += (i + 1 == d.moreWorkOffsets.size() ? " and " : ", ") + d.moreWorkOffsets[i];
    if (d.extendedWorkOffsets > 0) offers += fmt::format(" and G54.1 P1 to P{}", d.extendedWorkOffsets);
    const auto refuse = [&](const std::string& why) {
        return std::invalid_argument(
            fmt::format("work offset '{}' cannot be posted for {}: {}; {} offers {}", requested, d.name, why, d.name,
                        offers));
    };

    static const std::regex plain(R"(G5[4-9])"), more(R"(G59\.[0-9])"), extended(R"(G54\.1P([0-9]{1,3}))");
    std::smatch m;
    if (std::regex_match(code, plain)) return code;
    if (std::regex_match(code, more)) {
        if (std::find(d.moreWorkOffsets.begin(), d.moreWorkOffsets.end(), code) == d.moreWorkOffsets.end())
            throw refuse(fmt::format("{} has no {}", d.name, code));
        return code;
    }
    if (std::regex_match(code, m, extended)) {
        if (d.extendedWorkOffsets == 0)
            throw refuse(fmt::format("{} has no G54.1 P (FANUC's extended work offsets)", d.name));
        const int p = std::stoi(m[1].str());
        if (p < 1 || p > d.extendedWorkOffsets) throw refuse(fmt::format("there is no G54.1 P{}", p));
        return fmt::format("G54.1 P{}", p);
    }
    throw refuse("not a work offset");
}

const Dialect* findDialect(const std::string& name)
{
    for (const Dialect& d : dialectLibrary())
        if (d.name == name) return &d;
    return nullptr;
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
    } catch (const std::invalid_argument& e) {
        return Diagnostic{Severity::Error, std::nullopt, "", "workOffset", e.what()};
    }
    return std::nullopt;
}

}  // namespace taiwa
