// Tool choice for every step of a pocket unit, with the reason in words
// (modules/pocket_tools.h).
#include "modules/pocket_tools.h"

#include "model/codes.h"
#include "modules/inclined_face.h"
#include "tools/tool_fit.h"

#include "model/translate_noop.h"

#include <fmt/args.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace taiwa {

namespace {

using tools::Fit;

std::string mm(double v) { return fmt::format("{:g} mm", std::round(v * 1000) / 1000); }


// What a milling step needs of its end mill.
Fit fitFor(const Step& s)
{
    const MillingGeometry& g = millingOf(s);
    Fit f;
    f.depth = g.cutDepth - g.startDepth;
    f.centreCutting = s.kind == StepKind::FloorFinishing;  // it ramps into the beta2 left below the roughing
    if (g.outline) {
        f.cornerRadius = g.outline->cornerRadius;
        f.maxDiameter = inscribedRadius(g.outline->corners);  // at most half the pocket's width
    }
    if (g.region) {  // a contour: its narrowest channel and smallest inside corner; at most half its widest place
        f.cornerRadius = g.reach;
        f.maxDiameter = g.inscribed;
    }
    const InclinedFace* face = s.kind == StepKind::InclinedFaceFinishing ? s.payload.getIf<InclinedFace>() : nullptr;
    if (face) {
        // No corner radius to fit: the ball runs along the face (along Y);
        // its radius at most half the face's length and at most 6 mm.
        f.type = ToolType::BallEndMill;
        f.maxDiameter = std::min(12.0, distance(face->topEdge[0], face->topEdge[1]));
        f.cornerRadius = 0;
    } else if (s.kind == StepKind::WallFinishing && g.wallTaper > 0) {
        // The outline is at the top surface; the wall leans in by depth x
        // tan(taper), so the corner radius the tip must fit is the floor's.
        f.type = ToolType::TaperEndMill;
        f.taperAngle = g.wallTaper;
        if (g.outline) f.cornerRadius = std::max(1e-3, g.outline->cornerRadius - g.cutDepth * tanDeg(g.wallTaper));
    }
    return f;
}

// How a roughing end mill enters the material, said at the end of its reason.
enum class Entry { Unsaid, Ramps, PilotHole };

// "largest flat end mill (10 mm) whose radius 5 mm fits the corner radius 5.7 mm",
// each variant one whole sentence so that a translator reads it whole (the
// station translates the English back from these templates, ui/core_messages.h).
// shortOf: the depth its flutes do not reach (0 = they do); `what` the
// layers it roughs (chooseRoughingTool), `pilot` the hole it enters.
std::string describeEndMill(const Tool& t, const Fit& f, double shortOf = 0.0, Entry entry = Entry::Unsaid,
                            double pilot = 0.0, const std::string& what = {})
{
    const bool corner = f.cornerRadius > 0;
    const std::string size = corner ? mm(t.radius()) : mm(2 * f.maxDiameter);
    const std::string kind = toString(t.type), diameter = mm(t.diameter);
    if (!what.empty())
        return corner ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {} of the {}"), kind,
                                    diameter, size, mm(f.cornerRadius), what)
                      : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {} of the {}"),
                                    kind, diameter, size, what);
    // [corner][flutes short][entry]
    static constexpr const char* kTemplates[2][2][3] = {
        {{TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}; it cuts at its centre and "
                    "ramps in (no pilot hole)"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}; enters the {} pilot hole")},
         {TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter "
                    "than the depth {}, as are those of every end mill that fits: it cuts one layer at a time"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter "
                    "than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at "
                    "its centre and ramps in (no pilot hole)"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter "
                    "than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the "
                    "{} pilot hole")}},
        {{TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}; it cuts at its centre and ramps in (no "
                    "pilot hole)"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}; enters the {} pilot hole")},
         {TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the "
                    "depth {}, as are those of every end mill that fits: it cuts one layer at a time"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the "
                    "depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at its "
                    "centre and ramps in (no pilot hole)"),
          TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the "
                    "depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the {} "
                    "pilot hole")}}};
    const char* text = kTemplates[corner ? 1 : 0][shortOf > 0 ? 1 : 0][static_cast<int>(entry)];
    std::vector<std::string> args{kind, diameter, size};
    if (corner) args.push_back(mm(f.cornerRadius));
    if (shortOf > 0) {
        args.push_back(mm(t.fluteLength));
        args.push_back(mm(shortOf));
    }
    if (entry == Entry::PilotHole) args.push_back(mm(pilot));
    fmt::dynamic_format_arg_store<fmt::format_context> store;
    for (const auto& a : args) store.push_back(a);
    return fmt::vformat(text, store);
}

std::string describe(const Step& s, const Tool& t, const Fit& f, double shortOf, Entry entry)
{
    if (f.type == ToolType::TaperEndMill)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "taper end mill of the wall's taper {:g} deg per side (tip {}) whose tip radius {} "
                                     "fits the corner radius {} at the floor"),
                           f.taperAngle, mm(t.diameter), mm(t.radius()), mm(f.cornerRadius));
    const InclinedFace* face = s.kind == StepKind::InclinedFaceFinishing ? s.payload.getIf<InclinedFace>() : nullptr;
    if (face)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest ball end mill ({}) of radius at most 6 mm and half the inclined face's "
                                     "length {}"),
                           mm(t.diameter), mm(distance(face->topEdge[0], face->topEdge[1])));
    return describeEndMill(t, f, shortOf, entry);
}

// What the roughing layers of a unit need. They share one end mill (a
// layer is gamma x D of it deep): the tightest layer's corner and width, the
// thickest layer's depth, a stick-out reaching the deepest.
Fit roughingFit(const std::vector<Step>& steps)
{
    std::optional<Fit> all;
    for (const auto& s : steps) {
        if (s.kind != StepKind::Roughing) continue;
        const Fit layer = fitFor(s);
        if (!all) {
            all = layer;
        } else {
            if (layer.cornerRadius > 0)
                all->cornerRadius = all->cornerRadius > 0 ? std::min(all->cornerRadius, layer.cornerRadius) : layer.cornerRadius;
            all->maxDiameter = std::min(all->maxDiameter, layer.maxDiameter);
            all->depth = std::max(all->depth, layer.depth);
        }
        all->reach = std::max(all->reach, millingOf(s).cutDepth);
    }
    return all.value_or(Fit{});
}

// The largest end mill that fits, with flutes reaching the depth where
// possible; otherwise one whose stick-out reaches it, shortOf then the depth
// its flutes do not reach.
const Tool* roughingTool(const std::vector<Tool>& library, const Fit& f, const std::string& material, double& shortOf)
{
    shortOf = 0.0;
    if (const Tool* t = tools::largestFitting(library, f, material)) return t;
    Fit shorter = f;
    shorter.depth = 0.0;
    const Tool* t = tools::largestFitting(library, shorter, material);
    if (t) shortOf = f.depth;
    return t;
}

}  // namespace

std::optional<NarrowForcesShortFlutes> narrowForcesShortFlutes(const Step& s, const std::vector<Tool>& library,
                                                               const std::string& material)
{
    if (!millingOf(s).region || s.kind == StepKind::Roughing || s.kind == StepKind::PilotHole) return std::nullopt;
    const Fit f = fitFor(s);
    if (f.type != ToolType::FlatEndMill || f.cornerRadius <= 0 || tools::largestFitting(library, f, material)) return std::nullopt;
    Fit shallow = f, wide = f;
    shallow.depth = 0.0;
    wide.cornerRadius = 0.0;
    wide.maxDiameter = 1e9;
    NarrowForcesShortFlutes n;
    n.cornerRadius = f.cornerRadius;
    n.depth = f.depth;
    for (const Tool& t : library)  // of those that pass, the longest flutes
        if (tools::fits(t, shallow, material) && (!n.passing || t.fluteLength > n.passing->fluteLength)) n.passing = &t;
    n.reaching = tools::smallestFitting(library, wide, material);
    if (!n.passing || !n.reaching) return std::nullopt;
    return n;
}

ToolPick chooseRoughingTool(const Fit& f, const std::vector<Tool>& library, const std::string& material,
                            const std::string& what)
{
    if (const Tool* t = tools::largestFitting(library, f, material))
        return {ToolChoice{t->id, describeEndMill(*t, f, 0.0, Entry::Unsaid, 0.0, what)}, {}};
    return {std::nullopt, tools::noFitMessage(library, f, material, "roughing")};
}

std::vector<std::string> chooseTools(std::vector<Step>& steps, const ToolPins& pins, const std::vector<Tool>& library,
                                     const std::string& material)
{
    std::vector<std::string> problems;
    double plungeDiameter = 0;  // the first end mill that must enter the pilot hole
    double pocketLimit = 1e9;   // the pilot drill stays as narrow as that end mill had to be
    bool hasPilot = false;
    for (const auto& s : steps) hasPilot |= s.kind == StepKind::PilotHole;
    Fit roughing = roughingFit(steps);
    roughing.centreCutting = !hasPilot;  // without a pilot hole it ramps into solid material

    std::vector<double> shortOfs(steps.size(), 0.0);  // a roughing step's depth its flutes do not reach
    const auto pick = [&](Step& s, const Fit& f) {
        const auto pin = pins.find(toKey(s.kind));
        if (pin != pins.end()) {
            const Tool* t = findTool(library, pin->second);
            if (!t) problems.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: pinned tool T{} is not in the tool library"), s.label(), pin->second));
            else if (!tools::fits(*t, f, material))
                problems.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: pinned tool T{} ({}) does not fit: {}"), s.label(), t->id, t->name,
                                               tools::whyNot(*t, f, material)));
            else s.tool = ToolChoice{t->id, TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned by the operator")};
            return;
        }
        double shortOf = 0.0;
        if (const Tool* t = s.kind == StepKind::Roughing ? roughingTool(library, f, material, shortOf)
                                                         : tools::largestFitting(library, f, material)) {
            // Without a pilot hole a roughing end mill ramps in (one with enters it: said once it is chosen, below).
            const Entry entry = s.kind == StepKind::Roughing && !hasPilot ? Entry::Ramps : Entry::Unsaid;
            s.tool = ToolChoice{t->id, describe(s, *t, f, shortOf, entry)};
            shortOfs[static_cast<std::size_t>(&s - steps.data())] = shortOf;
        } else {
            problems.push_back(s.label() + ": " + tools::noFitMessage(library, f, material, toString(s.kind)));
        }
    };

    for (auto& s : steps) {
        if (s.kind == StepKind::PilotHole) continue;
        const Fit f = s.kind == StepKind::Roughing ? roughing : fitFor(s);
        pick(s, f);
        if (s.tool && plungeDiameter == 0) {
            plungeDiameter = findTool(library, s.tool->toolId)->diameter;
            pocketLimit = f.maxDiameter;
        }
    }
    // The pilot hole last: the smallest drill not smaller than the end mill that plunges into it.
    for (auto& s : steps) {
        if (s.kind != StepKind::PilotHole) continue;
        Fit f;
        f.type = ToolType::Drill;
        f.minDiameter = std::max(plungeDiameter, millingOf(s).holeDiameter);
        f.maxDiameter = pocketLimit;
        f.depth = millingOf(s).cutDepth;
        const auto pin = pins.find(toKey(s.kind));
        if (pin != pins.end()) {
            pick(s, f);
        } else if (const Tool* t = tools::smallestFitting(library, f, material)) {
            s.tool = ToolChoice{t->id, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "smallest drill ({}) not smaller than the {} end mill that plunges into it"),
                                                   mm(t->diameter), mm(plungeDiameter))};
        } else {
            problems.push_back(s.label() + ": " + tools::noFitMessage(library, f, material, "pilot hole"));
        }
        if (!s.tool) continue;
        editMilling(s).holeDiameter = findTool(library, s.tool->toolId)->diameter;
        for (auto& r : steps)
            if (r.kind == StepKind::Roughing && r.number == 1 && r.tool && pins.find(toKey(r.kind)) == pins.end())
                r.tool->reason = describeEndMill(*findTool(library, r.tool->toolId), roughing,
                                                 shortOfs[static_cast<std::size_t>(&r - steps.data())], Entry::PilotHole,
                                                 millingOf(s).holeDiameter);
    }
    return problems;
}

}  // namespace taiwa
