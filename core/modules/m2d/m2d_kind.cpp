// The door of module M2D (geometric 3-D pocket with two inclined walls): its
// job-file keys, checks, outline, planning and form, as module_kind.h asks.
// Registered in modules/registry.cpp.
#include "modules/m2d/m2d_kind.h"
#include "modules/inclined_face.h"
#include "modules/pocket_plan.h"
#include "model/codes.h"

#include "io/unit_keys.h"
#include "model/translate_noop.h"

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

namespace keys = io::keys;
const io::UnitKeys<M2DPocket> kKeys{
    {keys::point("corner", &M2DPocket::corner), keys::required("L1", &M2DPocket::lengthX),
     keys::required("L2", &M2DPocket::lengthY), keys::required("depth", &M2DPocket::depth),
     keys::required("theta1", &M2DPocket::theta1), keys::optional("theta2", &M2DPocket::theta2),
     keys::required("cornerRadius", &M2DPocket::cornerRadius), keys::requiredWhole("U", &M2DPocket::toolUse),
     keys::whole("H", &M2DPocket::pilotHole, 0), keys::number("scallop", &M2DPocket::scallop, 0.01),
     keys::optional("stepOver", &M2DPocket::stepOver), keys::pins(&M2DPocket::tools)}};

}  // namespace

ToolPick chooseM2DRoughingTool(const M2DPocket& p, const TechnologyData& tech, const std::vector<Tool>& library,
                               const std::string& material)
{
    const double bottom = p.depth - tech.beta2;
    const double width = p.lengthX - bottom * (tanDeg(p.theta1) + tanDeg(p.rightAngle())) - 2 * tech.alpha2;
    tools::Fit f;
    f.cornerRadius = p.cornerRadius - tech.alpha2;
    f.maxDiameter = 0.5 * std::min(width, p.lengthY - 2 * tech.alpha2);
    f.reach = bottom;  // the flutes cut one layer at a time
    f.centreCutting = pilotHoleFromCode(p.pilotHole) == PilotHole::None;
    return chooseRoughingTool(f, library, material, TAIWA_TRANSLATE_NOOP("taiwa::msg", "roughing layers"));
}

namespace {

class M2DKind final : public PocketKindOf<M2DPocket> {
public:
    M2DKind() : PocketKindOf(&kKeys, check::checkM2D) {}
    std::vector<std::string> stepKeys() const override { return check::millingStepKeys(); }
    // An inclined-face step's face: its edges, its angle and the scallop height.
    void describeStep(const Step& s, LengthUnit u, nlohmann::ordered_json& j) const override
    {
        const auto* face = s.payload.getIf<InclinedFace>();
        if (!face) return;
        nlohmann::ordered_json f;
        f["topEdge"] = {io::stepPoint(face->topEdge[0], u), io::stepPoint(face->topEdge[1], u)};
        f["floorEdge"] = {io::stepPoint(face->floorEdge[0], u), io::stepPoint(face->floorEdge[1], u)};
        f["angle"] = face->angle;
        f["scallop"] = io::stepLength(face->scallop, u);
        j["face"] = f;
    }

    ModuleInput makeDefault(const Stock& s) const override
    {
        return M2DPocket{.corner = {s.x + 10, s.y + 10}, .lengthX = 50, .lengthY = 30, .depth = 8, .theta1 = 10,
                         .cornerRadius = 8};
    }

protected:
    std::optional<Quad> outline(const M2DPocket& mm) const override { return m2dCrossSection(mm, 0.0); }

public:
    // The cross-section at depth d is the rounded rectangle whose left and
    // right sides have moved in by d tan θ1 and d tan θ2, its radius kept
    // (m2dCrossSection): a point lies in it while d stays under the bound
    // each inclined side sets, in closed form. Grown (or shrunk) by a slack,
    // the rectangle's sides move out by it and its radius grows with it.
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData& /*tech*/) const override
    {
        const M2DPocket& p = mm.as<M2DPocket>();
        Cavity c;
        c.min = p.corner;
        c.max = p.corner + Point2{p.lengthX, p.lengthY};
        c.depth = p.depth;
        c.wallAngle = std::max(p.theta1, p.rightAngle());
        c.surfaceTolerance = p.scallop;
        const double t1 = tanDeg(p.theta1), t2 = tanDeg(p.rightAngle());
        c.depthAt = [p, t1, t2](Point2 q, double slack) {
            const double rho = std::max(p.cornerRadius + slack, 0.0);
            const double y0 = p.corner.y - slack + rho, y1 = p.corner.y + p.lengthY + slack - rho;
            const double dy = std::max({y0 - q.y, q.y - y1, 0.0});
            if (dy > rho) return 0.0;
            const double w = std::sqrt(rho * rho - dy * dy);
            const double left = q.x - p.corner.x + slack - rho + w;                // d tan θ1 may grow to this
            const double right = p.corner.x + p.lengthX + slack - rho + w - q.x;   // d tan θ2 to this
            if (left < 0.0 || right < 0.0) return 0.0;
            double d = p.depth;
            if (t1 > 0.0) d = std::min(d, left / t1);
            if (t2 > 0.0) d = std::min(d, right / t2);
            return d;
        };
        return c;
    }

protected:
    void move(M2DPocket& m, Point2 delta) const override { m.corner = m.corner + delta; }

    std::vector<Step> planInput(const M2DPocket& m2d, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        // The layer count depends on the roughing tool: choose it first.
        double diameter = 0.0;
        if (const auto pin = m2d.tools.find(toKey(StepKind::Roughing)); pin != m2d.tools.end()) {
            if (const Tool* t = findTool(ctx.library, pin->second)) diameter = t->diameter;
        } else {
            const ToolPick pick = chooseM2DRoughingTool(m2d, ctx.tech, ctx.library, ctx.material);
            if (!pick.choice) {
                out.push_back({Severity::Error, ctx.unit + 1, M2DPocket::kName, "tools.roughing", pick.problem});
                return {};
            }
            diameter = findTool(ctx.library, pick.choice->toolId)->diameter;
        }
        std::vector<Step> steps = decomposeM2D(m2d, ctx.tech, diameter, ctx.unit);
        setStepOver(steps, m2d.stepOver);
        choosePocketTools(steps, m2d.tools, ctx, M2DPocket::kName, out);
        // The inclined-face passes must stop short of the vertical end walls'
        // corner rounding: give those steps the floor section (radius r1).
        for (auto& s : steps)
            if (s.kind == StepKind::InclinedFaceFinishing) editMilling(s).outline = m2dCrossSection(m2d, m2d.depth);
        return steps;
    }

};

}  // namespace

const ModuleKind& m2dModule() { return moduleInstance<M2DKind>(); }

}  // namespace taiwa
