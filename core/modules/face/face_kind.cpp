// The door of module FACE (face milling of the stock top): its job-file
// keys, checks, planning, cavity and form, as module_kind.h asks.
// Registered in modules/registry.cpp.
#include "modules/face/face.h"
#include "modules/module_kind.h"

#include "check/unit_checks.h"
#include "io/unit_keys.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

namespace keys = io::keys;
const io::UnitKeys<FaceUnit> kKeys{
    {keys::required("depth", &FaceUnit::depth), keys::whole("U", &FaceUnit::toolUse, face::kStandard),
     keys::optional("finish", &FaceUnit::finish), keys::number("angle", &FaceUnit::angle, 0.0),
     keys::whole("pattern", &FaceUnit::pattern, face::kOneWay), keys::optional("stepOver", &FaceUnit::stepOver),
     keys::number("margin", &FaceUnit::margin, 0.0).when([](const FaceUnit& u) { return u.margin != 0.0; }),
     keys::pins(&FaceUnit::tools)}};

class FaceKind final : public ModuleKindOf<FaceUnit> {
public:
    FaceKind() : ModuleKindOf(&kKeys, checkFace, face::millingPath) {}
    std::vector<std::string> stepKeys() const override { return {face::kStepKey}; }
    // The top is faced before anything else is cut.
    bool cutsBeforeOtherUnits() const override { return true; }
    // Passes across the face, four moves each.
    double estimateMoves(const Step& step, const Tool& tool, const TechnologyData&, const PathParameters&) const override
    {
        const auto* passes = step.payload.getIf<FacePasses>();
        if (!passes || !passes->milling.outline) return 10;
        const double a = passes->angle * std::numbers::pi / 180.0;
        double lo = 1e300, hi = -1e300;
        for (const Point2 c : passes->milling.outline->corners) {
            const double v = -std::sin(a) * c.x + std::cos(a) * c.y;
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        const double D = std::max(tool.diameter, 1e-3);
        return (std::ceil((hi - lo) / std::max(passes->milling.stepOver.value_or(0.75) * D, 1e-3)) + 2) * 4 + 4;
    }

    // The margin when it widens the face more than the stock does, else the
    // unit's step-over when it has one, else the depth (the layers).
    std::string movesField(const ModuleInput& mm, const Step& step) const override
    {
        const FaceUnit& f = mm.as<FaceUnit>();
        if (const Boxed<Quad>& rect = millingOf(step).outline) {
            double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
            for (const Point2 c : rect->corners)
                x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
            const double narrow = std::min(x1 - x0, y1 - y0);
            if (2.0 * f.margin > narrow - 2.0 * f.margin) return "margin";
        }
        return f.stepOver ? "stepOver" : "depth";
    }

    // The face is the whole stock top (grown by the margin, beyond the
    // stock where there is nothing to cut): the finished surface lies at
    // the depth wherever the stock is. The unit does not know the stock, so
    // its box reaches as far as any length may; the verification keeps to
    // the stock's cells.
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData&) const override
    {
        const FaceUnit& f = mm.as<FaceUnit>();
        Cavity c;
        c.min = {-check::kMaxLength, -check::kMaxLength};
        c.max = {check::kMaxLength, check::kMaxLength};
        c.depth = f.depth;
        c.depthAt = [depth = f.depth](Point2, double) { return depth; };
        return c;
    }

    ModuleInput makeDefault(const Stock& stock) const override
    {
        FaceUnit f;
        f.depth = std::min(1.0, stock.height / 10.0);
        return f;
    }

protected:
    // No figure for the interference check: a face covers the whole top,
    // and every other unit lies under it (their depths are measured from
    // Z0 either way). Overlapping them all is what a face does, not a
    // conflict; the step order (tools/step_order.cpp) faces the top before
    // any other unit's steps instead.
    std::optional<Quad> outline(const FaceUnit&) const override { return std::nullopt; }

    // The face follows the stock, not a position of its own.
    void move(FaceUnit&, Point2) const override {}

    std::vector<Step> planInput(const FaceUnit& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        const auto problem = [&](std::string field, std::string message) {
            out.push_back({Severity::Error, ctx.unit + 1, FaceUnit::kName, std::move(field), std::move(message)});
            return std::vector<Step>{};
        };
        if (!ctx.job) return problem("", "face milling needs the job's stock to plan");
        const face::ToolPick pick = face::chooseTool(mm, ctx.tech, ctx.library, ctx.material, ctx.shownUnit);
        if (!pick.tool) return problem("tools.face", pick.problem);
        std::vector<Step> steps = decomposeFace(mm, ctx.job->stock, ctx.tech, *pick.tool, ctx.unit);
        for (Step& s : steps) s.tool = ToolChoice{pick.tool->id, pick.reason};
        return steps;
    }

};

}  // namespace

const ModuleKind& faceModule() { return moduleInstance<FaceKind>(); }

}  // namespace taiwa
