// The door of module AREA (area clearing by drawn passes): its job-file
// keys, checks, outline, planning, cavity and form, as module_kind.h asks.
// Registered in modules/registry.cpp.
#include "model/translate_noop.h"
#include "modules/area/area.h"
#include "modules/module_kind.h"
#include "modules/named_region_form.h"
#include "paths/drawn_passes.h"

#include "io/job_messages.h"
#include "io/unit_keys.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace taiwa {

namespace {

// "points": the drawn passes' points [x, y]; a point that is not one is
// reported at its place ("points[3]") and left out. Absent: none yet.
io::UnitKey<AreaClearing> pointsKey()
{
    const auto read = [](const io::ObjectFields& f, AreaClearing& m) {
        const nlohmann::json* points = f.find("points");
        if (!points) return;
        if (!points->is_array()) {
            f.error("points", msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of points [x, y]"), *points));
            return;
        }
        for (std::size_t i = 0; i < points->size(); ++i) {
            const auto& v = (*points)[i];
            if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number())
                m.points.push_back({v[0].get<double>(), v[1].get<double>()});
            else
                f.error("points[" + std::to_string(i) + "]",
                        msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point [x, y]"), v));
        }
    };
    const auto write = [](const AreaClearing& m, nlohmann::ordered_json& u) {
        auto points = nlohmann::ordered_json::array();
        for (const Point2 p : m.points) points.push_back(io::point(p));
        u["points"] = points;
    };
    return io::keys::custom<AreaClearing>({"points"}, read, write);
}

const io::UnitKeys<AreaClearing> kKeys{
    {namedRegionKeys(&AreaClearing::area), pointsKey(), io::keys::required("depth", &AreaClearing::depth),
     io::keys::required("diameter", &AreaClearing::diameter), io::keys::pins(&AreaClearing::tools)}};

class AreaKind final : public ModuleKindOf<AreaClearing> {
public:
    AreaKind() : ModuleKindOf(&kKeys, checkAreaClearing, areaClearingPath) {}
    std::vector<std::string> stepKeys() const override { return {"area"}; }
    // A ramp and the drawn passes a layer.
    double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters&) const override
    {
        const auto* drawn = step.payload.getIf<DrawnPoints>();
        return estimatedLayers(step, tool, tech) * (static_cast<double>(drawn ? drawn->points.size() : 0) + 20);
    }

    void resolveContours(ModuleInput& mm, const ContourTable& table) const override
    {
        mm.as<AreaClearing>().area.resolve(table);
    }

    std::optional<DrawnPasses> drawnPasses(const ModuleInput& unit) const override
    {
        const AreaClearing& a = unit.as<AreaClearing>();
        return DrawnPasses{a.points, a.diameter / 2, a.area.outline, a.area.islands};
    }
    bool setDrawnPoints(ModuleInput& unit, std::vector<Point2> points) const override
    {
        AreaClearing& a = unit.as<AreaClearing>();
        a.points = std::move(points);
        a.badPoints.clear();
        return true;
    }

    std::vector<Point2> topPolygon(const ModuleInput& mm) const override
    {
        return regionPolygon(mm.as<AreaClearing>().area.region);
    }

    // What the passes were drawn to sweep: the strips one tool wide inside
    // the area, at depth T (the parts left unswept are reported by the
    // check, not cut).
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData&) const override
    {
        const AreaClearing& a = mm.as<AreaClearing>();
        if (!a.area.region || a.points.empty()) return std::nullopt;
        RegionCavity cut = regionCavity(*a.area.region, a.depth);
        cut.cavity.depthAt = [inside = cut.distance, points = a.points, r = a.diameter / 2,
                              depth = a.depth](Point2 q, double slack) {
            return (*inside)(q) <= slack && paths::distanceToPasses(points, q) <= r + slack ? depth : 0.0;
        };
        return std::move(cut.cavity);
    }

    // A rectangle over the middle of the stock.
    std::string defaultFigure(const Stock& s) const override
    {
        return "$$ The area of the drawn passes: a rectangle\n" + middleRectangleFigure(s) + "K1 = CONTOUR/L1, L2, L3, L4";
    }

    // The default figure's rectangle cleared back and forth in rows 0.8 D
    // apart, with the largest of the usual end mill sizes a quarter of its
    // narrower side allows.
    ModuleInput makeDefault(const Stock& s) const override
    {
        AreaClearing a;
        a.area.outline = "K1";
        a.depth = 5;
        const double r3 = 1000.0;
        const auto round3 = [r3](double v) { return std::round(v * r3) / r3; };
        const double x0 = round3(s.x + 0.2 * s.width), x1 = round3(s.x + 0.6 * s.width);
        const double y0 = round3(s.y + 0.2 * s.length), y1 = round3(s.y + 0.6 * s.length);
        const double side = std::min(x1 - x0, y1 - y0);
        a.diameter = side / 4;
        for (const double d : {25.0, 20.0, 16.0, 12.0, 10.0, 8.0, 6.0, 5.0, 4.0, 3.0, 2.0})
            if (d <= side / 4) {
                a.diameter = d;
                break;
            }
        const double r = a.diameter / 2;
        const int rows = std::max(1, static_cast<int>(std::ceil((y1 - y0 - 2 * r) / (0.8 * a.diameter)))) + 1;
        for (int i = 0; i < rows; ++i) {
            const double y = round3(y0 + r + (y1 - y0 - 2 * r) * i / (rows - 1));
            const bool back = i % 2 == 1;
            a.points.push_back({back ? x1 - r : x0 + r, y});
            a.points.push_back({back ? x0 + r : x1 - r, y});
        }
        return a;
    }

protected:
    std::optional<Quad> outline(const AreaClearing& mm) const override { return regionBox(mm.area.region); }

    // The area belongs to the job's figure; the drawn points to the area.
    void move(AreaClearing&, Point2) const override {}

    std::vector<Step> planInput(const AreaClearing& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        return planAreaClearing(mm, ctx.tech, ctx.library, ctx.material, ctx.unit, out);
    }

    // The area's contours by name (modules/named_region_form.h) and the
    // drawn points as text: the job file holds them in a grammar of their own.
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        if (t.bind == "points")
            return form::points<AreaClearing>(t.key, t.label, t.checks, &AreaClearing::points, &AreaClearing::badPoints,
                                              formatPoints, parsePoints);
        return form::namedRegionField(&AreaClearing::area, t);
    }
};

}  // namespace

const ModuleKind& areaModule() { return moduleInstance<AreaKind>(); }

}  // namespace taiwa
