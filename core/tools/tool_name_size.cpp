// Whether a tool's name still says its size (tool_name_size.h).
#include "tools/tool_name_size.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>

namespace taiwa {

namespace {

std::string trimmed(double v) { return fmt::format("{:g}", v); }

}  // namespace

std::vector<double> diametersInName(const std::string& name)
{
    // UTF-8 bytes: Ø is C3 98, ⌀ E2 8C 80. A size: digits, a decimal point or comma.
    static const std::regex size(R"(([0-9]+(?:[.,][0-9]+)?)\s*mm\b|(?:\xC3\x98|\xE2\x8C\x80|\bD)\s*([0-9]+(?:[.,][0-9]+)?)|\bR\s*([0-9]+(?:[.,][0-9]+)?))");
    std::vector<double> out;
    for (auto it = std::sregex_iterator(name.begin(), name.end(), size); it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        const int group = m[1].matched ? 1 : m[2].matched ? 2 : 3;
        std::string digits = m[group].str();
        for (char& c : digits)
            if (c == ',') c = '.';
        const double v = std::stod(digits);
        out.push_back(group == 3 ? 2 * v : v);
    }
    return out;
}

std::optional<std::string> nameSizeWarning(const std::optional<Tool>& before, const Tool& after)
{
    switch (after.type) {
    case ToolType::TurningInsert:
    case ToolType::Grooving:
    case ToolType::Threading: return std::nullopt;
    default: break;
    }
    if (before && before->diameter == after.diameter && before->name == after.name && before->names == after.names)
        return std::nullopt;
    std::vector<std::string> names{after.name};
    for (const auto& [language, text] : after.names) names.push_back(text);
    for (const std::string& name : names) {
        const std::vector<double> sizes = diametersInName(name);
        if (sizes.empty()) continue;
        bool says = false;
        for (const double d : sizes) says = says || std::abs(d - after.diameter) <= kFitTolerance;
        if (says) continue;
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{}'s name \"{}\" states {} mm; its diameter is {} mm"), after.id,
                           name, trimmed(sizes.front()), trimmed(after.diameter));
    }
    return std::nullopt;
}

}  // namespace taiwa
