// The steps of a SIDE unit and their end mill: roughing (Z layers of at
// most γ·D down to T, each with radial passes from W in to α2, at most
// stepOver·D apart) and the finishing pass at the contour (full depth, or
// F2's incisions). One flat end mill for both, pinned under "side" or the
// largest of the library that fits: its radius within the room the
// contour leaves on the tool's side, and every pass's tool-centre chain
// proved to keep its distance from the contour (a narrow channel the
// trimming of neighbours does not see makes the next smaller end mill).
#include "model/translate_noop.h"
#include "modules/side/side.h"

#include "check/messages.h"
#include "decompose/make_step.h"
#include "paths/contour_offset.h"
#include "tools/tool_fit.h"
#include "modules/side/side_messages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace taiwa {

namespace {

constexpr double kProofTolerance = 1e-6;

std::string mm(double v) { return fmt::format("{:g} mm", std::round(v * 1000.0) / 1000.0); }

// The offsets of each step for an end mill of diameter D.
struct Passes {
    std::vector<double> roughing;
    bool finishing = false;
};

Passes passesFor(const SideMill& m, const TechnologyData& tech, double D)
{
    Passes p;
    if (m.toolUse != 8) p.roughing = roughingOffsets(m.width, tech.alpha2, m.stepOver.value_or(tech.stepOver) * D);
    p.finishing = m.toolUse != 9;
    return p;
}

// The first place where a pass of the end mill of radius R would come
// nearer the contour than its offset, and by how much (the whole offset
// when the pass cannot be made); nothing when every pass keeps off.
struct Narrow {
    Point2 where;
    double by = 0.0;
};
std::optional<Narrow> tooNarrow(const side::Travel& t, const Passes& p, double R)
{
    std::vector<double> offsets = p.roughing;
    if (p.finishing) offsets.push_back(0.0);
    for (const double o : offsets) {
        const auto chains = paths::offsetSide(t.contour, t.toolOnLeft, R + o);
        if (!chains || chains->empty()) return Narrow{t.contour.start(), R + o};
        const paths::Clearance c = paths::chainClearance(t.contour, *chains);
        if (c.nearest < R + o - kProofTolerance) return Narrow{c.where, R + o - c.nearest};
    }
    return std::nullopt;
}

// The end mill of a SIDE unit and why: pinned under "side", or the largest
// of the library that fits the room and whose passes keep off the contour;
// a refusal on the field to mend when none will do.
struct SideToolChoice {
    struct Choice {
        const Tool* tool = nullptr;  // none: refused (problem() said why)
        std::string reason;
    };

    Choice choose() const
    {
        if (const auto pin = m.tools.find("side"); pin != m.tools.end()) return pinnedTool(pin->second);
        return largest();
    }

    Choice pinnedTool(int id) const
    {
        const Tool* tool = findTool(library, id);
        if (!tool) {
            problem("tools.side", msg::toolNotInLibrary(id));
            return {};
        }
        tools::Fit pinned = fit;
        if (layers) pinned.depth = 0.0;  // a pinned end mill may cut in layers shorter than its flutes
        if (!tools::fits(*tool, pinned, material)) {
            problem(
                "tools.side",
                msg::sideNoTool(TAIWA_TRANSLATE_NOOP("taiwa::msg", "side milling"),
                                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned tool T{} ({}) does not fit: {}"),
                                            tool->id, tool->name, tools::whyNot(*tool, pinned, material))));
            return {};
        }
        if (const auto at = tooNarrow(t, passesFor(m, tech, tool->diameter), tool->radius())) {
            problem("contour", msg::sideChannelTooNarrow(m.contour, msg::toolName(*tool), {at->where.x, shown}, {at->where.y, shown}));
            return {};
        }
        return {tool, "pinned by the operator"};
    }

    // The largest that fits, flutes reaching T first, then shorter flutes
    // (F2 and roughing cut in layers); each proved along the contour.
    Choice largest() const
    {
        const Tool* tool = nullptr;
        // The largest that fits, flutes reaching T first, then shorter
        // flutes (F2 and roughing cut in layers); each proved along the contour.
        std::vector<const Tool*> candidates;
        const Tool* smallestTried = nullptr;  // and where its passes came too near the contour
        Narrow smallestNarrow;
        for (const bool fullFlutes : {true, false}) {
            if (!fullFlutes && !layers) break;
            tools::Fit f = fit;
            if (!fullFlutes) f.depth = 0.0;
            for (const Tool& c : library)
                if (tools::fits(c, f, material) && std::find(candidates.begin(), candidates.end(), &c) == candidates.end())
                    candidates.push_back(&c);
            std::stable_sort(candidates.begin(), candidates.end(), [](const Tool* a, const Tool* b) { return a->diameter > b->diameter; });
            for (const Tool* c : candidates) {
                if (const auto narrow = tooNarrow(t, passesFor(m, tech, c->diameter), c->radius())) {
                    if (!smallestTried || c->diameter < smallestTried->diameter) smallestTried = c, smallestNarrow = *narrow;
                    continue;
                }
                tool = c;
                break;
            }
            if (tool) break;
            candidates.clear();
        }
        if (!tool && !layers) {
            // Would one with shorter flutes do, finishing in incisions (F2)?
            tools::Fit f = fit;
            f.depth = 0.0;
            const Tool* longest = nullptr;
            for (const Tool& c : library)
                if (tools::fits(c, f, material) && (!longest || c.fluteLength > longest->fluteLength) &&
                    !tooNarrow(t, passesFor(m, tech, c.diameter), c.radius()))
                    longest = &c;
            if (longest) {
                problem("F", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                              "no end mill that fits {} reaches the depth {} with its "
                                                              "flutes for the finishing at full depth (F 1): the "
                                                              "longest, {}, has flutes of {}; finish in several "
                                                              "incisions (F 2)"),
                                         m.contour, msg::quote({m.depth, shown}), msg::toolName(*longest),
                                         msg::quote({longest->fluteLength, shown})));
                return {};
            }
        }
        if (!tool && smallestTried) {
            // End mills fit the room, but even the smallest one's passes
            // would cut into the contour somewhere: say where and how deep.
            problem("contour",
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "{} leaves no room near ({}, {}): even the smallest end mill that "
                                                     "fits its arcs, {}, would cut {} into it there; widen the contour "
                                                     "there"),
                                m.contour, msg::quote({smallestNarrow.where.x, shown}),
                                msg::quote({smallestNarrow.where.y, shown}), msg::toolName(*smallestTried),
                                msg::quote({smallestNarrow.by, shown})));
            return {};
        }
        if (!tool) {
            // None fits at all: the reason of the nearest one with layers
            // allowed (its flutes may be short), an arc too tight by name.
            tools::Fit layered = fit;
            layered.depth = 0.0;
            const Tool* smallest = nullptr;
            for (const Tool& c : library)
                if (c.type == ToolType::FlatEndMill && (!smallest || c.diameter < smallest->diameter)) smallest = &c;
            std::string why;
            const bool arc = smallest && layered.cornerRadius > 0 && !fitsInto(smallest->radius(), layered.cornerRadius);
            if (arc) why = side::noRoomAt(m, *smallest, finishes ? 0.0 : -tech.alpha2, shown);
            const std::string field = arc && !why.empty() ? "contour" : "tools.side";
            if (why.empty())
                why = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} along {}"),
                                  tools::noFitMessage(library, layered, material,
                                                      TAIWA_TRANSLATE_NOOP("taiwa::msg", "side milling")),
                                  m.contour);
            problem(field, msg::sideNoTool(TAIWA_TRANSLATE_NOOP("taiwa::msg", "side milling"), why));
            return {};
        }
        // One whole sentence for each case, for the station's translation.
        const bool shortFlutes = tool->fluteLength > 0 && tool->fluteLength + 1e-9 < m.depth;
        std::string reason;
        if (room < 1e299)
            reason = shortFlutes
                         ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers"),
                                       mm(tool->diameter), mm(tool->radius()), mm(room), mm(tool->fluteLength))
                         : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour"),
                                       mm(tool->diameter), mm(tool->radius()), mm(room));
        else
            reason = shortFlutes
                         ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest flat end mill ({}) and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers"),
                                       mm(tool->diameter), mm(tool->fluteLength))
                         : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest flat end mill ({}) and whose passes keep off the contour"), mm(tool->diameter));
        return {tool, std::move(reason)};
    }

    const SideMill& m;
    const TechnologyData& tech;
    const std::vector<Tool>& library;
    const std::string& material;
    LengthUnit shown;
    std::function<void(const std::string&, const std::string&)> problem;  // on the unit's field
    side::Travel t;
    double room;     // the contour's smallest inside radius on the tool's side
    bool finishes;   // a finishing pass at the contour (U not 9)
    bool layers;     // every pass cuts in layers: shorter flutes will do
    tools::Fit fit;  // what the end mill must be
};

SideToolChoice sideToolChoice(const SideMill& m, const TechnologyData& tech, const std::vector<Tool>& library,
                              const std::string& material, LengthUnit shown,
                              std::function<void(const std::string&, const std::string&)> problem)
{
    const double room = side::toolRoom(m);
    const bool finishes = m.toolUse != 9;
    // Shorter flutes only where every pass cuts in layers: not a finishing
    // pass at full depth at once (F1), whose shank would rub the wall above
    // the flutes.
    const bool layers = !finishes || m.wallFinish == 2;
    // What the end mill must be: flat, within the room (the finishing pass
    // runs at the contour; roughing alone stays α2 off it), flutes over T.
    tools::Fit fit;
    fit.type = ToolType::FlatEndMill;
    if (room < 1e299) fit.cornerRadius = finishes ? room : room + tech.alpha2;
    fit.depth = m.depth;
    fit.reach = m.depth;
    return SideToolChoice{m, tech, library, material, shown, std::move(problem), side::travel(m), room, finishes, layers, fit};
}

}  // namespace

std::vector<double> roughingOffsets(double width, double alpha2, double maxStep)
{
    const double span = width - alpha2;
    const int n = std::max(1, static_cast<int>(std::ceil(span / maxStep - 1e-9)));
    std::vector<double> out;
    for (int i = n - 1; i >= 0; --i) out.push_back(alpha2 + span * i / n);
    return out;
}

std::vector<Step> planSideMill(const SideMill& m, const TechnologyData& tech, const std::vector<Tool>& library,
                               const std::string& material, int unit, LengthUnit shown, Diagnostics& out)
{
    using decompose::makeStep;
    const SideToolChoice choice = sideToolChoice(m, tech, library, material, shown, [&](const std::string& field, const std::string& message) {
        out.push_back({Severity::Error, unit + 1, SideMill::kName, field, message});
    });
    const SideToolChoice::Choice chosen = choice.choose();
    if (!chosen.tool) return {};
    const Tool* tool = chosen.tool;
    const std::string& reason = chosen.reason;
    const side::Travel& t = choice.t;

    const Passes passes = passesFor(m, tech, tool->diameter);
    const Point2 middle = t.contour.segments[t.contour.segments.size() / 2].at(0.5);
    std::vector<Step> steps;
    // wall: the allowance the step leaves; layered: cut in Z layers.
    const auto step = [&](int number, MachiningType type, std::vector<double> offsets, double wall, bool layered) {
        Step s = makeStep(unit, SideMill::kName, StepKind::SideMilling, number, type);
        s.payload = SidePasses{t.contour, t.toolOnLeft, std::move(offsets),
                               {.position = middle,
                                .startDepth = 0.0,
                                .cutDepth = m.depth,
                                .wallAllowance = wall,
                                .multiIncision = layered,
                                .stepOver = m.stepOver}};
        s.tool = ToolChoice{tool->id, reason};
        return s;
    };
    if (!passes.roughing.empty())  // in Z layers of at most γ·D
        steps.push_back(step(1, MachiningType::SideMilling, passes.roughing, tech.alpha2, true));
    if (passes.finishing)
        steps.push_back(step(static_cast<int>(steps.size()) + 1, MachiningType::SideFinishing, {0.0}, 0.0, m.wallFinish == 2));
    return steps;
}

}  // namespace taiwa
