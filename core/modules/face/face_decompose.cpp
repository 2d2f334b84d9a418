// The tool and the steps of a FACE unit: the tool first (its diameter and
// cutting length set the layers), then roughing layers of equal depth, at
// most γ·D and no deeper than the tool cuts, down to depth - finish, and
// the finishing pass at the depth (U1). Every step is the whole face.
#include "model/translate_noop.h"
#include "modules/face/face.h"

#include "check/messages.h"
#include "decompose/make_step.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace taiwa {

namespace face {

namespace {

constexpr double kEps = 1e-9;  // mm
// The tool's flat bottom must reach 0.1 D beyond the face's sides
// (paths/face_milling.cpp): a corner radius up to 0.4 D leaves room for it.
constexpr double kMaxCornerShare = 0.4;

std::string mm(double v) { return fmt::format("{:g} mm", std::round(v * 1000.0) / 1000.0); }

bool flatBottomed(const Tool& t)
{
    return (t.type == ToolType::FaceMill || t.type == ToolType::FlatEndMill) && t.diameter > 0.0 &&
           t.cornerRadius < kMaxCornerShare * t.diameter;
}

}  // namespace

Quad faceOutline(const Stock& s, double margin)
{
    const double x0 = s.x - margin, y0 = s.y - margin, x1 = s.x + s.width + margin, y1 = s.y + s.length + margin;
    return Quad{{Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}}, 0.0};
}

double finishDepth(const FaceUnit& f, const TechnologyData& tech) { return f.finish.value_or(tech.beta2); }

double cuttingLength(const Tool& t) { return t.fluteLength > 0.0 ? t.fluteLength : 0.0; }

double layerLimit(const Tool& t, const TechnologyData& tech)
{
    const double byGamma = tech.gamma * t.diameter;
    const double length = cuttingLength(t);
    return length > 0.0 ? std::min(byGamma, length) : byGamma;
}

double stepOverFor(const FaceUnit& f, const Tool& t, const TechnologyData& tech)
{
    if (f.stepOver) return *f.stepOver;
    return t.type == ToolType::FaceMill ? kFaceMillStepOver : tech.stepOver;
}

ToolPick chooseTool(const FaceUnit& f, const TechnologyData& tech, const std::vector<Tool>& library,
                    const std::string& material, LengthUnit shown)
{
    const bool finishing = f.toolUse == kStandard;
    const double pass = finishDepth(f, tech);
    const auto takesPass = [&](const Tool& t) { return !finishing || cuttingLength(t) == 0.0 || cuttingLength(t) + kEps >= pass; };
    const auto quoted = [&](double v) { return msg::quote({v, shown}); };
    ToolPick pick;
    if (const auto pin = f.tools.find(kStepKey); pin != f.tools.end()) {
        const Tool* t = findTool(library, pin->second);
        if (!t) pick.problem = msg::toolNotInLibrary(pin->second);
        else if (!flatBottomed(*t))
            pick.problem = fmt::format(
                TAIWA_TRANSLATE_NOOP(
                    "taiwa::msg", "{} is pinned for \"face\" but is not a face mill or a flat end mill with a corner "
                                  "radius under 0.4 D: a face is cut flat by the tool's flat bottom"),
                msg::toolName(*t));
        else if (!takesPass(*t))
            pick.problem = fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                     "{} is pinned for \"face\" but cuts {} at most, less than the finishing pass {}; "
                                     "give a smaller finishing pass or another tool"),
                msg::toolName(*t), quoted(cuttingLength(*t)), quoted(pass));
        else {
            pick.tool = t;
            pick.reason = "pinned by the operator";
        }
        return pick;
    }
    const auto key = [&](const Tool& t) {
        return std::tuple(t.cuttingFor(material) != nullptr, t.type == ToolType::FaceMill, t.diameter, -t.id);
    };
    for (const Tool& t : library)
        if (flatBottomed(t) && takesPass(t) && (!pick.tool || key(t) > key(*pick.tool))) pick.tool = &t;
    if (!pick.tool) {
        pick.problem = finishing
                           ? fmt::format(TAIWA_TRANSLATE_NOOP(
                                             "taiwa::msg",
                                             "the tool library has no face mill or flat end mill that cuts the "
                                             "finishing pass {} in one cut; add one or give a smaller finishing pass"),
                                         quoted(pass))
                           : std::string("the tool library has no face mill or flat end mill; add one");
        return pick;
    }
    const Tool& t = *pick.tool;
    pick.reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest {} in the library (Ø{}), cutting {} a layer"),
                              toString(t.type), mm(t.diameter), mm(layerLimit(t, tech)));
    return pick;
}

}  // namespace face

std::vector<Step> decomposeFace(const FaceUnit& f, const Stock& stock, const TechnologyData& tech, const Tool& tool,
                                int unit)
{
    using decompose::makeStep;
    const Quad outline = face::faceOutline(stock, f.margin);
    const double finish = face::finishDepth(f, tech);
    const double rough = f.depth - finish;
    const double limit = face::layerLimit(tool, tech);
    const int layers = std::max(1, static_cast<int>(std::ceil(rough / limit - 1e-9)));
    std::vector<Step> steps;
    const auto step = [&](int number, MachiningType type, double from, double to) {
        Step s = makeStep(unit, FaceUnit::kName, StepKind::FaceMilling, number, type);
        s.payload = FacePasses{f.angle, f.pattern == face::kZigzag,
                               {.outline = outline,
                                .position = centroid(outline.corners),
                                .startDepth = from,
                                .cutDepth = to,
                                .floorAllowance = std::max(f.depth - to, 0.0),
                                .stepOver = face::stepOverFor(f, tool, tech)}};
        return s;
    };
    double from = 0.0;
    for (int k = 1; k <= layers; ++k) {
        const double to = k == layers ? rough : rough * k / layers;  // the last exactly depth - finish
        steps.push_back(step(k, MachiningType::FaceMilling, from, to));
        from = to;
    }
    if (f.toolUse == face::kStandard) steps.push_back(step(layers + 1, MachiningType::FaceFinishing, rough, f.depth));
    return steps;
}

}  // namespace taiwa
