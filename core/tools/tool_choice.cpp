// Tool choice for every step of a unit, with the reason in words.
#include "tools/tool_choice.h"

#include "tools/tool_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

using tools::Fit;

std::string mm(double v) { return fmt::format("{:g} mm", std::round(v * 1000) / 1000); }

const Tool* byId(const std::vector<Tool>& library, int id)
{
    const auto it = std::find_if(library.begin(), library.end(), [id](const Tool& t) { return t.id == id; });
    return it == library.end() ? nullptr : &*it;
}

// What a milling step needs of its end mill.
Fit fitFor(const Step& s)
{
    Fit f;
    f.depth = s.cutDepth - s.startDepth;
    if (s.outline) {
        f.cornerRadius = s.outline->cornerRadius;
        f.maxDiameter = inscribedRadius(s.outline->corners);  // at most half the pocket's width
    }
    if (s.kind == StepKind::InclinedFaceFinishing && s.face) {
        f.type = ToolType::BallEndMill;
        f.maxDiameter = std::min(12.0, 0.25 * distance(s.face->topEdge[0], s.face->topEdge[1]));
        f.cornerRadius = 0;
    } else if (s.kind == StepKind::WallFinishing && s.wallTaper > 0) {
        f.type = ToolType::TaperEndMill;
        f.taperAngle = s.wallTaper;
    }
    return f;
}

std::string describe(const Step& s, const Tool& t, const Fit& f)
{
    std::string r = fmt::format("largest {} ({}) ", toString(t.type), mm(t.diameter));
    if (f.type == ToolType::TaperEndMill) r += fmt::format("of the wall's taper {:g} deg per side", f.taperAngle);
    else if (f.cornerRadius > 0) r += fmt::format("whose radius {} fits the corner radius {}", mm(t.radius()), mm(f.cornerRadius));
    else r += fmt::format("that fits the {}", s.kind == StepKind::InclinedFaceFinishing ? "inclined face" : "pocket");
    return r;
}

}  // namespace

ToolPick chooseM2DRoughingTool(const M2DPocket& p, const TechnologyData& tech, const std::vector<Tool>& library,
                               const std::string& material)
{
    const double bottom = p.depth - tech.beta2;
    const double tanL = tanDeg(p.theta1), tanR = tanDeg(p.rightAngle());
    const double width = p.lengthX - bottom * (tanL + tanR) - 2 * tech.alpha2;
    Fit f;
    f.cornerRadius = p.cornerRadius - tech.alpha2;
    f.maxDiameter = 0.5 * std::min(width, p.lengthY - 2 * tech.alpha2);
    f.depth = bottom;
    if (const Tool* t = tools::largestFitting(library, f, material))
        return {ToolChoice{t->id, fmt::format("largest flat end mill ({}) whose radius fits the corner radius {} of the "
                                              "roughing layers", mm(t->diameter), mm(f.cornerRadius))}, {}};
    return {std::nullopt, tools::noFitMessage(library, f, material, "roughing")};
}

std::vector<std::string> chooseTools(std::vector<Step>& steps, const ToolPins& pins, const std::vector<Tool>& library,
                                     const std::string& material)
{
    std::vector<std::string> problems;
    double plungeDiameter = 0;  // the first end mill that must enter the pilot hole
    bool hasPilot = false;
    for (const auto& s : steps) hasPilot |= s.kind == StepKind::PilotHole;

    const auto pick = [&](Step& s, const Fit& f) {
        const auto pin = pins.find(toKey(s.kind));
        if (pin != pins.end()) {
            const Tool* t = byId(library, pin->second);
            if (!t) problems.push_back(fmt::format("{}: pinned tool T{} is not in the tool library", s.label(), pin->second));
            else if (!tools::fits(*t, f, material))
                problems.push_back(fmt::format("{}: pinned tool T{} ({}) does not fit: {}", s.label(), t->id, t->name,
                                               tools::whyNot(*t, f, material)));
            else s.tool = ToolChoice{t->id, "pinned by the operator"};
            return;
        }
        if (const Tool* t = tools::largestFitting(library, f, material)) {
            s.tool = ToolChoice{t->id, describe(s, *t, f)};
        } else {
            problems.push_back(s.label() + ": " + tools::noFitMessage(library, f, material, toString(s.kind)));
        }
    };

    for (auto& s : steps) {
        if (s.kind == StepKind::PilotHole) continue;
        pick(s, fitFor(s));
        if (s.tool && plungeDiameter == 0) {
            plungeDiameter = byId(library, s.tool->toolId)->diameter;
            if (s.kind == StepKind::Roughing && pins.find(toKey(s.kind)) == pins.end())
                s.tool->reason += hasPilot ? "; plunges into the pilot hole" : "; ramps in helically (no pilot hole)";
        }
    }
    // The pilot hole last: the smallest drill not smaller than the end mill that plunges into it.
    for (auto& s : steps) {
        if (s.kind != StepKind::PilotHole) continue;
        Fit f;
        f.type = ToolType::Drill;
        f.minDiameter = plungeDiameter;
        f.depth = s.cutDepth;
        f.maxDiameter = s.holeDiameter > 0 ? s.holeDiameter : 1e9;
        const auto pin = pins.find(toKey(s.kind));
        if (pin != pins.end()) {
            pick(s, f);
        } else if (const Tool* t = tools::smallestFitting(library, f, material)) {
            s.tool = ToolChoice{t->id, fmt::format("smallest drill ({}) not smaller than the {} end mill that plunges into it",
                                                   mm(t->diameter), mm(plungeDiameter))};
        } else {
            problems.push_back(s.label() + ": " + tools::noFitMessage(library, f, material, "pilot hole"));
        }
        if (s.tool) s.holeDiameter = byId(library, s.tool->toolId)->diameter;
    }
    return problems;
}

}  // namespace taiwa
