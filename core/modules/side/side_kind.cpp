// The door of module SIDE (side milling along an open or closed contour):
// its job-file keys, checks, figure, cavity, planning and form, as
// module_kind.h asks. Registered in modules/registry.cpp.
#include "modules/side/side.h"
#include "modules/module_kind.h"

#include "figure/figure_text.h"
#include "io/unit_keys.h"
#include "paths/contour_offset.h"
#include "paths/region.h"

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

namespace keys = io::keys;
const io::UnitKeys<SideMill> kKeys{{keys::text("contour", &SideMill::contour), keys::whole("side", &SideMill::side, 1),
                                    keys::whole("direction", &SideMill::direction, 1),
                                    keys::required("depth", &SideMill::depth),
                                    keys::required("width", &SideMill::width), keys::whole("U", &SideMill::toolUse, 1),
                                    keys::whole("F", &SideMill::wallFinish, 1),
                                    keys::optional("stepOver", &SideMill::stepOver), keys::pins(&SideMill::tools)}};

class SideKind final : public ModuleKindOf<SideMill> {
public:
    SideKind() : ModuleKindOf(&kKeys, checkSideMill, side::millingPath) {}
    // One end mill for roughing and finishing: pins and speeds under "side".
    std::vector<std::string> stepKeys() const override { return {"side"}; }
    // Each pass: about a move a segment, two a joint, and the leads.
    double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters&) const override
    {
        const auto* side = step.payload.getIf<SidePasses>();
        if (!side) return 10;
        const double passes = static_cast<double>(std::max<std::size_t>(side->offsets.size(), 1));
        return (millingOf(step).multiIncision ? estimatedLayers(step, tool, tech) : 1) * passes *
               (2 * static_cast<double>(side->contour.segments.size()) + 8);
    }

    void resolveContours(ModuleInput& mm, const ContourTable& table) const override
    {
        SideMill& m = mm.as<SideMill>();
        m.resolved = true;
        m.figureContours.clear();
        m.path.reset();
        m.reach = 0.0;
        if (const auto it = table.find(m.contour); it != table.end()) m.path = withoutDegenerateSegments(it->second);
        if (!m.path || m.path->segments.empty()) {
            // The message that the contour is not the figure's names the
            // figure's contours; a unit that finds its own keeps no list
            // (thousands of units each held every name: quadratic).
            m.path.reset();
            for (const auto& [name, contour] : table) m.figureContours.push_back(name);
            return;
        }
        // With the tool inside a closed contour, its reach limits the end mill as CP's does.
        const side::Travel t = side::travel(m);
        if (t.contour.closed && paths::toolInside(t.contour, t.toolOnLeft)) {
            const Region r = normalised(Region{t.contour, {}});
            m.reach = paths::reachRadius(r, paths::inscribedRadius(r));
        }
    }

    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData& tech) const override
    {
        const SideMill& m = mm.as<SideMill>();
        if (!m.path) return std::nullopt;
        return sideCavity(m, tech);
    }

    // An open contour along the stock's far side in Y, run in +X with the
    // stock edge on its left, starting and ending beyond the stock.
    std::string defaultFigure(const Stock& s) const override
    {
        const auto n = [](double v) { return figure::formatNumber(std::round(v * 1000.0) / 1000.0); };
        const double y = s.y + 0.9 * s.length;
        const double x0 = s.x - 10.0, x1 = s.x + s.width + 10.0;
        return "$$ The side milling's contour: a line along the far side of the stock, past both ends\n"
               "P1 = POINT/" + n(x0) + ", " + n(y) + "\n" +
               "P2 = POINT/" + n(x1) + ", " + n(y) + "\n" +
               "L1 = LINE/P1, P2\n"
               "K1 = CONTOUR/P1, L1, P2";
    }

    ModuleInput makeDefault(const Stock& s) const override
    {
        SideMill m;
        m.contour = "K1";
        m.depth = std::min(10.0, std::floor(s.height / 2));
        m.width = std::round(0.1 * s.length * 1000.0) / 1000.0;
        return m;
    }

protected:
    // The box round the contour grown by W (the unit order, the preview).
    std::optional<Quad> outline(const SideMill& mm) const override
    {
        if (!mm.path || mm.path->empty()) return std::nullopt;
        const Box2 b = bounds(*mm.path);
        const double w = std::max(mm.width, 0.0);
        const Point2 lo{b.min.x - w, b.min.y - w}, hi{b.max.x + w, b.max.y + w};
        return Quad{{lo, Point2{hi.x, lo.y}, hi, Point2{lo.x, hi.y}}, 0.0};
    }

    // The contour belongs to the job's figure: the unit stays where it is.
    void move(SideMill&, Point2) const override {}

    std::vector<Step> planInput(const SideMill& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        return planSideMill(mm, ctx.tech, ctx.library, ctx.material, ctx.unit, ctx.shownUnit, out);
    }

};

}  // namespace

const ModuleKind& sideModule() { return moduleInstance<SideKind>(); }

}  // namespace taiwa
