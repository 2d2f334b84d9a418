// Input checks of one FACE unit (face milling of the stock top): the codes,
// the depth against the stock's height, the finishing pass against the
// depth, the angle, step-over and margin, the pins, and a tool that takes
// the finishing pass in one cut. Every refusal names its field.
#include "model/translate_noop.h"
#include "modules/face/face.h"

#include "check/check_unit.h"
#include "check/messages.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;
using msg::quote;

constexpr double kEps = 1e-9;  // mm

bool checkCodes(const FaceUnit& f, Reporter& r)
{
    bool ok = true;
    if (f.toolUse != face::kStandard && f.toolUse != face::kRoughOnly) {
        r.unit("U",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "U {} is not a tool use of face milling; give 1 (roughing layers and a finishing pass) "
                               "or 9 (roughing only, the finishing allowance left)"),
                           f.toolUse));
        ok = false;
    }
    if (f.pattern != face::kOneWay && f.pattern != face::kZigzag) {
        r.unit("pattern",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "pattern {} is not a face-milling pattern; give 1 (one way, climb: every pass in "
                               "the same direction) or 2 (zigzag: back and forth)"),
                           f.pattern));
        ok = false;
    }
    return ok;
}

bool checkDepths(const FaceUnit& f, Reporter& r)
{
    if (!check::checkLength(f.depth, "depth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"), r))
        return false;
    if (!(f.depth > 0.0)) {
        r.unit("depth", msg::depthNotPositive(r.len(f.depth)));
        return false;
    }
    if (const Stock* st = r.ctx.stock; st && f.depth >= st->height - kEps) {
        r.unit("depth",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "the depth {} is not less than the stock's height {}: facing takes a layer off the "
                               "top, it does not mill the whole block away"),
                           quote(r.len(f.depth)), quote(r.len(st->height))));
        return false;
    }
    if (f.finish) {
        if (!check::checkLength(*f.finish, "finish", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the finishing pass"), r))
            return false;
        if (!(*f.finish > 0.0)) {
            r.unit("finish",
                   fmt::format(TAIWA_TRANSLATE_NOOP(
                                   "taiwa::msg",
                                   "the finishing pass is {}; it must be greater than zero (leave the field empty "
                                   "for the technology data's β2)"),
                               quote(r.len(*f.finish))));
            return false;
        }
    }
    if (!r.ctx.tech) return true;
    const double finish = face::finishDepth(f, *r.ctx.tech);
    if (finish >= f.depth - kEps) {
        r.unit("finish",
               fmt::format(
                   TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                        "the finishing pass {}{} is not less than the depth {}: roughing would have "
                                        "nothing to take; give a smaller finishing pass"),
                   quote(r.len(finish)), f.finish ? "" : " (the technology data's β2)", quote(r.len(f.depth))));
        return false;
    }
    return true;
}

void checkPasses(const FaceUnit& f, Reporter& r)
{
    if (!std::isfinite(f.angle))
        r.unit("angle", msg::notFinite(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the angle")));
    else if (std::abs(f.angle) > 360.0)
        r.unit("angle",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "the angle {} lies beyond ±360°; give the passes' direction from +X, e.g. 0 or 90"),
                           msg::quoteDeg(f.angle)));
    if (f.stepOver) {
        const double s = *f.stepOver;
        if (!std::isfinite(s))
            r.unit("stepOver", msg::notFinite(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over")));
        else if (!(s > 0.0))
            r.unit("stepOver", fmt::format(TAIWA_TRANSLATE_NOOP(
                                               "taiwa::msg",
                                               "the step-over {:g} × D must be greater than 0: passes that do not step "
                                               "sideways never cover the face"),
                                           s));
        else if (s < face::kStepOverLow)
            r.unit("stepOver",
                   fmt::format(TAIWA_TRANSLATE_NOOP(
                                   "taiwa::msg",
                                   "the step-over {:g} × D is less than {:g} × D: the face would take more than "
                                   "a hundred passes a tool diameter"),
                               s, face::kStepOverLow));
        else if (s > face::kStepOverHigh)
            r.unit("stepOver",
                   fmt::format(
                       TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "the step-over {:g} × D is more than {:g} × D: neighbouring passes would "
                                            "overlap by less than a tenth of the diameter, and the inserts' corners "
                                            "and the tool's run-out leave ridges between them"),
                       s, face::kStepOverHigh));
    }
    if (check::checkLength(f.margin, "margin", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the margin"), r) && f.margin < 0.0)
        r.unit("margin",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "the margin is {}; it must be 0 (the face is the stock's top) or more (the face "
                               "reaches beyond the stock's sides): less would leave the top's edges unfaced"),
                           quote(r.len(f.margin))));
}

// Pins: a face mill or a flat end mill. A pin of another step or of a
// tool not in the library is check::checkPins's (the door runs it): false,
// said there, so that the tool choice does not say it again.
bool checkPins(const FaceUnit& f, Reporter& r)
{
    bool ok = true;
    for (const auto& [key, id] : f.tools) {
        if (key != face::kStepKey) {
            ok = false;
            continue;
        }
        if (!r.ctx.library) continue;
        const Tool* t = findTool(*r.ctx.library, id);
        if (!t) {
            ok = false;
            continue;
        }
        if (t->type != ToolType::FaceMill && t->type != ToolType::FlatEndMill) {
            r.unit("tools." + key,
                   fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is pinned for \"face\" but is not a face mill or a flat end mill: a face is "
                                                                  "cut flat by the tool's flat bottom"),
                               msg::toolName(*t)));
            ok = false;
        }
    }
    return ok;
}

}  // namespace

check::UnitReport checkFace(const FaceUnit& f, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, FaceUnit::kName, ctx, [&](Reporter& r, check::UnitReport& report) {
        const bool codes = checkCodes(f, r);
        const bool depths = checkDepths(f, r);
        checkPasses(f, r);
        const bool pins = checkPins(f, r);
        // A face has no figure of its own in the plan: it takes no part in the
        // interference check (see face_kind.cpp's outline).
        report.figureValid = false;
        if (!codes || !depths || !pins || !ctx.tech || !ctx.library) return;
        const face::ToolPick pick = face::chooseTool(f, *ctx.tech, *ctx.library, "", ctx.shownUnit);
        if (!pick.tool) r.unit("tools.face", pick.problem);
    });
}

}  // namespace taiwa
