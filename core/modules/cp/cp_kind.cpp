// The door of module CP (contour pocket of any outline, with islands): its
// job-file keys, checks, outline, planning and form, as module_kind.h asks.
// Registered in modules/registry.cpp.
#include "modules/cp/cp.h"
#include "modules/module_kind.h"
#include "modules/named_region.h"
#include "modules/pocket_plan.h"
#include "modules/named_region_form.h"
#include "paths/narrowest.h"
#include "paths/region.h"

#include "figure/figure_text.h"
#include "io/unit_keys.h"
#include "model/codes.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace taiwa {

namespace {

namespace keys = io::keys;
const io::UnitKeys<ContourPocket> kKeys{
    {namedRegionKeys(&ContourPocket::contours), keys::required("depth", &ContourPocket::depth),
     keys::whole("U", &ContourPocket::toolUse, 1), keys::whole("F", &ContourPocket::wallFinish, 1),
     keys::optional("stepOver", &ContourPocket::stepOver), keys::pins(&ContourPocket::tools)}};

class CpKind final : public PocketKindOf<ContourPocket> {
public:
    CpKind() : PocketKindOf(&kKeys, checkContourPocket) {}
    std::vector<std::string> stepKeys() const override { return {"roughing", "floor", "wall"}; }

    void resolveContours(ModuleInput& mm, const ContourTable& table) const override
    {
        ContourPocket& p = mm.as<ContourPocket>();
        p.contours.resolve(table);
        p.reach = p.inscribed = 0.0;
        // Too many segments: not sized (the checks refuse it, named_region.h).
        if (!p.contours.region || !regionWithinLimits(*p.contours.region)) return;
        const Region normal = normalised(*p.contours.region);
        p.inscribed = paths::inscribedRadius(normal);
        p.reach = paths::reachRadius(normal, p.inscribed);
        // An island touching the outline (or another) leaves no room between
        // them, whatever the rolling saw (it takes the touching point for room).
        p.reach = std::min(p.reach, 0.5 * paths::smallestIslandGap(normal));
    }

    std::vector<Point2> topPolygon(const ModuleInput& mm) const override
    {
        return regionPolygon(mm.as<ContourPocket>().contours.region);
    }

    // Vertical walls: the full depth wherever the point is in the region.
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData& tech) const override
    {
        const ContourPocket& p = mm.as<ContourPocket>();
        if (!p.contours.region) return std::nullopt;
        RegionCavity r = regionCavity(*p.contours.region, p.depth);
        r.cavity.depthAt = [distance = r.distance, depth = p.depth](Point2 q, double slack) {
            return distance->within(q, slack) ? depth : 0.0;
        };
        // Walls only (U8): the pocket is open to the floor within α2 of its walls.
        if (toolUseFromCode(p.toolUse).value_or(ToolUse::Standard) == ToolUse::WallOnly)
            r.cavity.openAt = [distance = r.distance, depth = p.depth, a2 = tech.alpha2](Point2 q) {
                return distance->within(q, -a2) ? depth : 0.0;
            };
        return std::move(r.cavity);
    }

    // A rectangle rounded at its corners over the middle of the stock.
    std::string defaultFigure(const Stock& s) const override
    {
        const auto n = [](double v) { return figure::formatNumber(std::round(v * 1000.0) / 1000.0); };
        const double r = 0.05 * std::min(s.width, s.length);
        return "$$ The contour pocket's outline: a rectangle rounded at its corners\n" + middleRectangleFigure(s) +
               "K1 = CONTOUR/L1, ROUND, " + n(r) + ", L2, ROUND, " + n(r) + ", L3, ROUND, " + n(r) + ", L4, ROUND, " + n(r);
    }

    ModuleInput makeDefault(const Stock&) const override
    {
        ContourPocket p;
        p.contours.outline = "K1";
        p.depth = 10;
        return p;
    }

protected:
    // The box around the outline (its polygon is topPolygon).
    std::optional<Quad> outline(const ContourPocket& mm) const override { return regionBox(mm.contours.region); }

    // The contours belong to the job's figure: moving the unit alone cannot
    // move them, so a contour pocket stays where its contours are.
    void move(ContourPocket&, Point2) const override {}

    std::vector<Step> planInput(const ContourPocket& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        std::vector<Step> steps = decomposeContourPocket(mm, ctx.tech, ctx.unit);
        setStepOver(steps, mm.stepOver);
        choosePocketTools(steps, mm.tools, ctx, ContourPocket::kName, out);
        nameNarrowPlaceOfShortFlutes(mm, steps, ctx.library, ctx.material, ctx.shownUnit, ctx.unit + 1, out);
        return steps;
    }

    // The pocket's contours by name (modules/named_region_form.h).
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        return form::namedRegionField(&ContourPocket::contours, t);
    }
};

}  // namespace

const ModuleKind& cpModule() { return moduleInstance<CpKind>(); }

}  // namespace taiwa
