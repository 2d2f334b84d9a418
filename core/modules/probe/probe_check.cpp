// Input checks of one PROBE unit (work-centre probing): codes, the touches
// entered (whole, P1 at the origin, a side for each on a rectangle), the
// machine coordinates, the cycle's values, the probe, and the fit of the
// touches, whose refusal names the touch on its own field.
#include "model/translate_noop.h"
#include "modules/probe/probe_kind.h"

#include "check/check_unit.h"
#include "check/messages.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa {

// What the check, the setup and the sketch share (probe_kind.h).
std::vector<probe::Touch> touchesOf(const ProbeUnit& p)
{
    std::vector<probe::Touch> t;
    for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i)
        if (p.x[i] && p.y[i]) t.push_back({{*p.x[i], *p.y[i]}, static_cast<probe::Side>(p.side[i])});
    return t;
}

const Tool* probeTool(const ProbeUnit& p, const std::vector<Tool>& library)
{
    const Tool* found = nullptr;
    for (const Tool& t : library)
        if (t.type == ToolType::Probe && (p.tool == 0 || t.id == p.tool)) {
            if (found && p.tool == 0) return nullptr;  // several probes: which one must be said
            found = &t;
        }
    return found;
}

UnitFit fitOf(const ProbeUnit& p, const std::vector<probe::Touch>& touches, const Tool& probe)
{
    const probe::FitSettings fs{probe.radius(), p.where == 2, p.tolerance};
    const auto widen = [](auto&& fit) { return std::visit([](auto&& v) -> UnitFit { return v; }, fit); };
    return p.shape == 1 ? widen(probe::fitCircle(touches, fs)) : widen(probe::fitRectangle(touches, fs));
}

namespace check {

UnitReport checkProbe(const ProbeUnit& p, int unitNo, const Context& ctx)
{
    return checkUnit(unitNo, ProbeUnit::kName, ctx, [&](Reporter& r, UnitReport& report) {
        if (p.shape != 1 && p.shape != 2)
            r.unit("shape",
                   fmt::format(TAIWA_TRANSLATE_NOOP(
                                   "taiwa::msg",
                                   "shape {} is not defined: 1 round (boss or bore), 2 rectangular (block or pocket)"),
                               p.shape));
        if (p.where != 1 && p.where != 2)
            r.unit("where", fmt::format(TAIWA_TRANSLATE_NOOP(
                                            "taiwa::msg",
                                            "where {} is not defined: 1 touched from outside (boss, block), 2 from inside "
                                            "(bore, pocket)"),
                                        p.where));
        bool finite = true;
        for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i) {
            const std::string field = "touches[" + std::to_string(i) + "]", point = "P" + std::to_string(i + 1);
            if (p.x[i]) finite &= checkLength(*p.x[i], field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the X of {}"), point), r);
            if (p.y[i]) finite &= checkLength(*p.y[i], field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the Y of {}"), point), r);
            if (static_cast<bool>(p.x[i]) != static_cast<bool>(p.y[i])) {
                r.unit(field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {}: its {} is missing"), i + 1,
                                          p.x[i] ? "Y" : "X"));
                finite = false;
            }
            if (p.shape == 2 && p.x[i] && p.y[i] && (p.side[i] < 1 || p.side[i] > 4)) {
                r.unit("sides[" + std::to_string(i) + "]",
                       fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                        "point {}: say which side it touches: 1 -X, 2 +X, 3 -Y, 4 +Y"),
                                   i + 1));
                finite = false;
            }
        }
        if (!p.x[0] || !p.y[0] || *p.x[0] != 0.0 || *p.y[0] != 0.0) {
            r.unit("touches[0]",
                   TAIWA_TRANSLATE_NOOP(
                       "taiwa::msg", "point 1 is the measuring origin: it is at 0, 0 and the others are measured from it"));
            finite = false;
        }
        finite &= checkLength(p.origin.x, "origin", "the machine X of point 1", r) &&
                  checkLength(p.origin.y, "origin", "the machine Y of point 1", r);
        if (p.top)
            finite &= checkLength(*p.top, "top", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the machine Z of the top face"), r);
        const auto positive = [&](double v, const char* field, const char* what, double most) {
            if (!std::isfinite(v) || v <= 0 || v > most) {
                r.unit(field,
                       fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} must be above 0 and at most {:g} mm, not {:g}"),
                                   what, most, v));
                return false;
            }
            return true;
        };
        positive(p.sizeX, "sizeX",
                 p.shape == 2 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the nominal width along X")
                              : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the nominal diameter"),
                 kMaxLength);
        if (p.shape == 2)
            positive(p.sizeY, "sizeY", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the nominal length along Y"), kMaxLength);
        positive(p.touchDepth, "touchDepth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth of the side touches"), 1000);
        positive(p.clearance, "clearance", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the clearance"), 1000);
        positive(p.search, "search", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the search distance"), 1000);
        if (!std::isfinite(p.feed) || p.feed <= 0 || p.feed > 5000)
            r.unit("feed",
                   fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "the probing feed must be above 0 and at most 5000 mm/min, not {:g}"),
                               p.feed));
        if (!std::isfinite(p.tolerance) || p.tolerance < 0.001 || p.tolerance > 1)
            r.unit("tolerance", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                 "the tolerance must lie between 0.001 and 1 mm, not {:g}"),
                                            p.tolerance));

        const Tool* tool = ctx.library ? probeTool(p, *ctx.library) : nullptr;
        if (ctx.library && !tool) {
            if (p.tool != 0)
                r.unit("T",
                       fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} is not a probe in the tool library"), p.tool));
            else
                r.unit("T", TAIWA_TRANSLATE_NOOP(
                                "taiwa::msg",
                                "the tool library has no probe, or several: add one of type \"probe\" or say which (T)"));
        }
        if (!finite || !tool || hasErrors(report.diagnostics)) return;

        // The fit of the touches entered (none but the origin: the cycle only).
        const auto touches = touchesOf(p);
        if (touches.size() <= 1) return;
        const UnitFit fit = fitOf(p, touches, *tool);
        if (const auto* e = std::get_if<probe::FitProblem>(&fit))
            r.unit(e->point > 0 ? "touches[" + std::to_string(e->point - 1) + "]" : "touches", e->message);
    });
}

}  // namespace check

}  // namespace taiwa
