// The step of one AREA unit and its tool: the drawn passes in layers down to
// the depth, cut with a centre-cutting flat end mill of the diameter the
// passes were drawn for; and the points as the form reads and writes them.
#include "modules/area/area.h"
#include "model/translate_noop.h"

#include "decompose/make_step.h"
#include "figure/figure_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace taiwa {

std::string formatPoints(const std::vector<Point2>& points)
{
    std::string text;
    for (const Point2 p : points)
        text += (text.empty() ? "" : "; ") + figure::formatNumber(p.x) + ", " + figure::formatNumber(p.y);
    return text;
}

std::optional<std::vector<Point2>> parsePoints(const std::string& text)
{
    std::vector<Point2> points;
    std::size_t from = 0;
    const auto number = [](std::string_view s) -> std::optional<double> {
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
        while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
        if (!s.empty() && s.front() == '+') s.remove_prefix(1);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
        return v;
    };
    while (from <= text.size()) {
        const std::size_t semi = std::min(text.find(';', from), text.size());
        const std::string_view piece(text.data() + from, semi - from);
        if (piece.find_first_not_of(" \t") != std::string_view::npos) {
            const std::size_t comma = piece.find(',');
            if (comma == std::string_view::npos) return std::nullopt;
            const auto x = number(piece.substr(0, comma)), y = number(piece.substr(comma + 1));
            if (!x || !y) return std::nullopt;
            points.push_back({*x, *y});
        }
        from = semi + 1;
    }
    return points;
}

std::vector<Step> planAreaClearing(const AreaClearing& a, const TechnologyData&, const std::vector<Tool>& library,
                                   const std::string& material, int unit, Diagnostics& out)
{
    Step s = decompose::makeStep(unit, AreaClearing::kName, StepKind::AreaClearing, 1, MachiningType::AreaClearing);
    s.payload = DrawnPoints{a.points,
                            {.region = normalised(a.area.region.value()),
                             .position = a.points.front(),
                             .startDepth = 0.0,
                             .cutDepth = a.depth}};
    const auto fits = [&](const Tool& t) { return cutsDrawnPasses(t, a.diameter); };
    const auto problem = [&](std::string message) {
        out.push_back({Severity::Error, unit + 1, AreaClearing::kName, "tools", std::move(message)});
    };
    if (const auto pin = a.tools.find("area"); pin != a.tools.end()) {
        const Tool* t = findTool(library, pin->second);
        if (!t || !fits(*t)) {
            problem(fmt::format("T{} is pinned for \"area\" but is not a centre-cutting flat end mill of {} mm",
                                pin->second, a.diameter));
            return {s};
        }
        s.tool = ToolChoice{t->id, "pinned by the operator"};
        return {s};
    }
    // Of the tools of that diameter: one with cutting data for the material,
    // then the one whose flutes take the layers, then the lowest id.
    const Tool* best = nullptr;
    for (const Tool& t : library) {
        if (!fits(t)) continue;
        const auto key = [&](const Tool& x) {
            return std::make_tuple(x.cuttingFor(material) != nullptr, x.fluteLength, -x.id);
        };
        if (!best || key(t) > key(*best)) best = &t;
    }
    if (!best) {
        problem(fmt::format("no centre-cutting flat end mill of {} mm in the tool library for the drawn passes", a.diameter));
        return {s};
    }
    s.tool = ToolChoice{best->id, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the passes were drawn {} mm wide"), figure::formatNumber(a.diameter))};
    return {s};
}

}  // namespace taiwa
