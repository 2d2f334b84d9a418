// The steps of a HOLES unit and their tools: the drill first (its diameter
// sets the others), then the centre drill that spots for it, then the tap,
// reamer or boring tool. Every step holds all the unit's holes; a pinned
// tool must be of the step's type and size, an unpinned one is the
// library's best fit. A missing tool is a diagnostic naming what to add.
#include "model/translate_noop.h"
#include "modules/holes/holes.h"

#include "check/messages.h"
#include "decompose/make_step.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace taiwa {

namespace {

constexpr double kSame = 1e-3;  // mm: a tool "of" a diameter

// Reamers take 0.1-0.5 mm on the diameter, boring tools 0.5-4 mm: the
// pre-drill is the largest library drill within that much under the hole.
constexpr double kReamUnderMin = 0.1, kReamUnderMax = 0.5;
constexpr double kBoreUnderMin = 0.5, kBoreUnderMax = 4.0;

std::string mm(double v) { return fmt::format("{:g} mm", std::round(v * 1000.0) / 1000.0); }

struct Planner {
    const HolePattern& h;
    int unit;
    const std::vector<Tool>& library;
    const std::string& material;
    Diagnostics& out;
    bool failed = false;

    void problem(const std::string& key, const std::string& message)
    {
        out.push_back({Severity::Error, unit + 1, HolePattern::kName, "tools." + key, message});
        failed = true;
    }

    // The pinned tool for `key` when it `fits`, else the fitting library
    // tool that `better` prefers (tools with cutting data for the material
    // first, then the lowest id). `wanted` says what it must be.
    const Tool* pick(const std::string& key, const std::function<bool(const Tool&)>& fits,
                     const std::function<bool(const Tool&, const Tool&)>& better, const std::string& wanted)
    {
        if (const auto pin = h.tools.find(key); pin != h.tools.end()) {
            const Tool* t = findTool(library, pin->second);
            if (!t) {
                problem(key, msg::toolNotInLibrary(pin->second));
                return nullptr;
            }
            if (!fits(*t)) {
                problem(key,
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({}) is pinned for \"{}\" but is not a {}"),
                                    t->id, t->name, key, wanted));
                return nullptr;
            }
            return t;
        }
        const Tool* best = nullptr;
        for (const Tool& t : library) {
            if (!fits(t)) continue;
            if (!best) {
                best = &t;
                continue;
            }
            const bool data = t.cuttingFor(material) != nullptr, bestData = best->cuttingFor(material) != nullptr;
            if (data != bestData ? data : better(t, *best)) best = &t;
        }
        if (!best)
            problem(key, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no {} in the tool library; add one"), wanted));
        return best;
    }
};

bool reaches(const Tool& t, double depth) { return !(t.fluteLength > 0.0) || t.fluteLength + 1e-9 >= depth; }
bool lowerId(const Tool& a, const Tool& b) { return a.id < b.id; }


// A tool picked for a step, and why.
struct Picked {
    const Tool* tool = nullptr;
    std::string reason;
};
struct Finish : Picked {
    StepKind kind = StepKind::Tapping;
    MachiningType type = MachiningType::Tapping;
};

// How deep a drill's tip goes: the full diameter's depth and its point.
double tipOf(const holes::Depths& d, const Tool& drill) { return d.drillFull + holes::pointLength(drill.diameter, drill.pointAngle); }

// The drill: of the hole's (or the tap drill's) diameter, or the largest
// pre-drill within the reamer's or boring tool's allowance.
Picked pickDrill(Planner& p, const holes::Depths& d, const holes::Thread* thread)
{
    const HolePattern& h = p.h;
    Picked out;
    if (d.drillDiameter > 0.0) {
        const std::string what =
            thread ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tap drill of {}"), thread->name)
                   : std::string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the hole's"));
        out.tool = p.pick(
            "drill",
            [&](const Tool& t) {
                return t.type == ToolType::Drill && std::abs(t.diameter - d.drillDiameter) <= kSame &&
                       reaches(t, tipOf(d, t));
            },
            lowerId,
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "drill of Ø{} ({}) whose flutes reach {}"),
                        mm(d.drillDiameter), what, mm(d.drillFull + d.drillDiameter / 2)));
        out.reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "drill of Ø{}: {}"), mm(d.drillDiameter), what);
    } else {
        const bool ream = h.hole == "reamed";
        const double lo = h.diameter - (ream ? kReamUnderMax : kBoreUnderMax);
        const double hi = h.diameter - (ream ? kReamUnderMin : kBoreUnderMin);
        out.tool = p.pick(
            "drill",
            [&](const Tool& t) {
                return t.type == ToolType::Drill && t.diameter >= lo - 1e-9 && t.diameter <= hi + 1e-9 && reaches(t, tipOf(d, t));
            },
            [](const Tool& a, const Tool& b) {
                return a.diameter > b.diameter || (a.diameter == b.diameter && a.id < b.id);
            },
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                             "drill from Ø{} to Ø{} (to {} Ø{}: {} to {} under) whose flutes reach {}"),
                        mm(lo), mm(hi), ream ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "ream") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "bore"), mm(h.diameter),
                        mm(ream ? kReamUnderMin : kBoreUnderMin), mm(ream ? kReamUnderMax : kBoreUnderMax),
                        mm(d.drillFull + hi / 2)));
        if (out.tool)
            out.reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest drill {} to {} under Ø{} to {}"),
                                     mm(ream ? kReamUnderMin : kBoreUnderMin),
                                     mm(ream ? kReamUnderMax : kBoreUnderMax), mm(h.diameter), ream ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "ream") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "bore"));
    }
    return out;
}

// The finishing tool of a tapped, reamed or bored hole; none for a drilled one.
Finish pickFinish(Planner& p, const holes::Depths& d, const holes::Thread* thread)
{
    const HolePattern& h = p.h;
    Finish out;
    if (h.hole == "tapped" && thread) {
        out.tool = p.pick(
            "tap",
            [&](const Tool& t) {
                return t.type == ToolType::Tap && std::abs(t.diameter - thread->size) <= kSame &&
                       std::abs(t.turning.pitchMin - thread->pitch) <= 1e-6 && reaches(t, d.finish);
            },
            lowerId,
            fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "tap {}x{:g} (type tap, Ø{}, pitch {}) whose flutes reach {}"),
                thread->name, thread->pitch, mm(thread->size), mm(thread->pitch), mm(d.finish)));
        out.reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tap {}x{:g}"), thread->name, thread->pitch);
    } else if (h.hole == "reamed" || h.hole == "bored") {
        const bool ream = h.hole == "reamed";
        out.kind = ream ? StepKind::Reaming : StepKind::Boring;
        out.type = ream ? MachiningType::Reaming : MachiningType::Boring;
        const ToolType type = ream ? ToolType::Reamer : ToolType::BoringBar;
        out.tool = p.pick(
            ream ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "ream") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "bore"),
            [&](const Tool& t) {
                return t.type == type && std::abs(t.diameter - h.diameter) <= kSame && reaches(t, d.finish);
            },
            lowerId,
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} of Ø{} whose flutes reach {}"),
                        ream ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "reamer")
                             : TAIWA_TRANSLATE_NOOP("taiwa::msg", "boring bar (set to the bore)"),
                        mm(h.diameter), mm(d.finish)));
        out.reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} of the hole's Ø{}"),
                                 ream ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "reamer") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "boring tool"),
                                 mm(h.diameter));
    }
    return out;
}

}  // namespace

std::vector<Step> planHolePattern(const HolePattern& h, int unit, const std::vector<Tool>& library,
                                  const std::string& material, LengthUnit shown, Diagnostics& out)
{
    (void)shown;
    using decompose::makeStep;
    Planner p{h, unit, library, material, out};
    const holes::Depths d = holes::depths(h);
    const holes::Thread* thread = holes::findThread(h.thread);
    const std::vector<Point2> at = holes::positions(h);
    Point2 middle{};
    for (const Point2& q : at) middle = middle + (1.0 / static_cast<double>(at.size())) * q;

    // The drill first: its diameter sets the centre drill's.
    const Picked drilling = pickDrill(p, d, thread);
    const Tool* drill = drilling.tool;

    // The centre drill: the largest no wider than the drill (else the
    // smallest), spotting a cone as wide as the drill or itself.
    const double drillD = drill ? drill->diameter : (d.drillDiameter > 0 ? d.drillDiameter : h.diameter);
    bool narrowOne = false;
    for (const Tool& t : library)
        if (t.type == ToolType::CentreDrill && t.diameter <= drillD + 1e-9) narrowOne = true;
    const Tool* centre = p.pick(
        "centre-drill",
        [&](const Tool& t) { return t.type == ToolType::CentreDrill && (!narrowOne || t.diameter <= drillD + 1e-9 || h.tools.count("centre-drill")); },
        [&](const Tool& a, const Tool& b) {
            return narrowOne ? a.diameter > b.diameter || (a.diameter == b.diameter && a.id < b.id)
                             : a.diameter < b.diameter || (a.diameter == b.diameter && a.id < b.id);
        },
        "centre drill");
    const Finish finishing = pickFinish(p, d, thread);
    const Tool* finish = finishing.tool;
    if (p.failed || !drill || !centre) return {};

    const auto step = [&](StepKind kind, MachiningType type, const Tool& tool, double depth, double diameter,
                          std::string reason) {
        Step s = makeStep(unit, HolePattern::kName, kind, 1, type);
        s.payload = HoleCentres{at, 0.0, {.position = middle, .holeDiameter = diameter, .startDepth = 0.0, .cutDepth = depth}};
        s.tool = ToolChoice{tool.id, h.tools.count(toKey(kind)) ? "pinned by the operator" : std::move(reason)};
        return s;
    };
    std::vector<Step> steps;
    const double spot = std::min(centre->diameter, drill->diameter);
    steps.push_back(step(StepKind::CentreDrilling, MachiningType::CentreDrilling, *centre,
                         holes::pointLength(spot, centre->pointAngle), spot,
                         fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "centre drill spotting Ø{} for the Ø{} drill"),
                                     mm(spot), mm(drill->diameter))));
    steps.push_back(step(StepKind::Drilling, MachiningType::Drilling, *drill, tipOf(d, *drill), drill->diameter, drilling.reason));
    if (finish) {
        Step s = step(finishing.kind, finishing.type, *finish, d.finish, d.finishDiameter, finishing.reason);
        if (finishing.kind == StepKind::Tapping) s.payload = HoleCentres{at, thread->pitch, millingOf(s)};
        steps.push_back(s);
    }
    return steps;
}

}  // namespace taiwa
