// The door of module SURFACE (a 3-D surface ruled between two space curves,
// roughed by Z levels and finished at a scallop height): its checks,
// planning hooks and form, as module_kind.h asks; its job-file keys read
// and written by surface_file.cpp. Registered in modules/registry.cpp;
// docs/surfaces.md says what it makes.
#include "modules/module_kind.h"
#include "modules/surface/surface.h"
#include "modules/surface/surface_file.h"
#include "modules/surface/surface_messages.h"

#include "model/contour.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa {

namespace {

class SurfaceKind final : public ModuleKindOf<SurfaceUnit> {
public:
    SurfaceKind() : ModuleKindOf(&surfacemod::surfaceKeys(), checkSurface, surfacemod::surfacePath) {}
    // A projection given as a figure contour gets its points (mm), its
    // arcs flattened to surfacemod::kContourTolerance.
    void resolveContours(ModuleInput& mm, const ContourTable& table) const override
    {
        SurfaceUnit& u = mm.as<SurfaceUnit>();
        for (SurfaceCurve* c : {&u.curve1, &u.curve2})
            for (SurfaceProjection& pr : c->projections) {
                if (pr.contour.empty()) continue;
                pr.points.clear();
                pr.contourProblem.clear();
                const auto it = table.find(pr.contour);
                if (it == table.end()) {
                    std::string known;
                    for (const auto& [name, contour] : table)
                        if (!contour.closed) known += (known.empty() ? "" : ", ") + name;
                    pr.contourProblem = msg::surfaceNoContour(pr.contour, known);
                } else if (it->second.closed) {
                    pr.contourProblem = msg::surfaceContourClosed(pr.contour);
                } else {
                    pr.points = flatten(it->second, surfacemod::kContourTolerance);
                }
            }
    }

    std::vector<std::string> stepKeys() const override { return {surfacemod::kStepKey}; }
    // Finishing: the paths a scallop spacing apart, a point a step; roughing:
    // its levels' passes a step-over apart.
    double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech,
                         const PathParameters&) const override
    {
        const auto* sp = step.payload.getIf<SurfacePaths>();
        if (!sp || !sp->milling.outline) return 10;
        const Quad& q = *sp->milling.outline;
        const double w = std::abs(q.corners[2].x - q.corners[0].x), l = std::abs(q.corners[2].y - q.corners[0].y);
        const double D = std::max(tool.diameter, 1e-3);
        const double along = w / std::max(sp->step, 1e-3) + 4;
        if (step.kind == StepKind::SurfaceFinishing) {
            const double r = D / 2, h = std::max(sp->scallop, 1e-6);
            return (l / std::max(2 * std::sqrt(h * std::max(2 * r - h, h)), 1e-3) + 2) * along;
        }
        const double levels = sp->milling.cutDepth / std::max(tech.gamma * D, 1e-3) + 2;
        return levels * (l / std::max(tech.stepOver * D, 1e-3) + 2) * along;
    }
    // A nose point costs the export about six pocket moves (bench_largest_jobs,
    // 2026-11-30: 20 µs and 400 bytes a move at 2.8 M moves, against the
    // contour pocket's 3.4 µs and 160 bytes at 9.9 M): a drop-cutter each,
    // and in the verification a ball's whole disc for each short move.
    double workPerMove() const override { return 6.0; }
    // The field to change when the job's paths would not fit the budget:
    // the finishing's points are a scallop spacing apart; the roughing's
    // levels and passes come from the technology data, and only a smaller
    // surface makes fewer.
    std::string movesField(const ModuleInput&, const Step& step) const override
    {
        return step.kind == StepKind::SurfaceFinishing ? "scallop" : "curve1";
    }
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData&) const override
    {
        return surfacemod::surfaceCavity(mm.as<SurfaceUnit>());
    }
    // The finishing step's surface (the M surface) for the 3-D view.
    std::vector<std::vector<Point3>> machinedSurface(const Step& step) const override
    {
        const auto* sp = step.payload.getIf<SurfacePaths>();
        if (!sp || step.kind != StepKind::SurfaceFinishing) return {};
        return sp->surface;
    }
    // Finishing after roughing.
    bool stepWaitsFor(const Step& later, const Step& earlier) const override
    {
        return later.kind == StepKind::SurfaceFinishing && earlier.kind == StepKind::SurfaceRoughing;
    }

    ModuleInput makeDefault(const Stock& stock) const override
    {
        const bool given = stock.width > 0 && stock.length > 0 && stock.height > 0;
        const double x = given ? stock.x : 0, y = given ? stock.y : 0, w = given ? stock.width : 100,
                     l = given ? stock.length : 60, h = given ? stock.height : 30;
        const double d = std::min(10.0, h / 3);
        SurfaceUnit u;
        u.curve1.points = {{x + 5, y + 5, -d * 0.6}, {x + w / 2, y + 5, -d}, {x + w - 5, y + 5, -d * 0.6}};
        u.curve2.points = {{x + 5, y + l - 5, -d * 0.4}, {x + w - 5, y + l - 5, -d * 0.4}};
        u.n = 4;
        u.m = 16;
        u.scallop = 0.05;
        u.allowance = 0.3;
        return u;
    }

protected:
    // The box around the curves in XY (the surface lies within it).
    std::optional<Quad> outline(const SurfaceUnit& u) const override
    {
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (const SurfaceCurve* c : {&u.curve1, &u.curve2})
            for (const Point3& p : c->points)
                x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        if (!(x0 < x1 && y0 < y1)) return std::nullopt;
        return Quad{{Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}}, 0.0};
    }

    void move(SurfaceUnit& u, Point2 d) const override
    {
        for (SurfaceCurve* c : {&u.curve1, &u.curve2}) {
            for (Point3& p : c->points) p.x += d.x, p.y += d.y;
        }
        for (auto& path : u.boundary)
            for (Point3& p : path) p.x += d.x, p.y += d.y;
    }

    std::vector<Step> planInput(const SurfaceUnit& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        return planSurface(mm, ctx.tech, ctx.library, ctx.unit, ctx.shownUnit, out);
    }

    // The two curves and the boundary as text (surface_text.cpp), N, M and
    // the ball end mill pinned; curveStep, scallop and allowance are the
    // job-file table's.
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        if (t.bind == "curve1") return curveField(t, &SurfaceUnit::curve1, &SurfaceUnit::curve1Bad);
        if (t.bind == "curve2") return curveField(t, &SurfaceUnit::curve2, &SurfaceUnit::curve2Bad);
        if (t.bind == "n") return form::intMember<SurfaceUnit>(t.key, t.label, &SurfaceUnit::n);
        if (t.bind == "m") return piecesField(t);
        if (t.bind == "boundary") return boundaryField(t);
        if (t.bind == "tool") return toolField(t);
        return std::nullopt;
    }

private:
    // M: whole, empty when the step along the curves gives it.
    static FormField piecesField(const form::FieldText& t)
    {
        FormField m = form::number<SurfaceUnit>(
            t.key, t.label, t.checks,
            [](const SurfaceUnit& u) { return u.m ? std::optional<double>(*u.m) : std::nullopt; },
            [](SurfaceUnit&, double) {});
        m.set = [](ModuleInput& mi, std::optional<double> v) {
            if (SurfaceUnit* u = mi.getIf<SurfaceUnit>())
                u->m = v ? std::optional<int>(static_cast<int>(std::lround(std::clamp(*v, -1e6, 1e6)))) : std::nullopt;
        };
        m.kind = FormFieldKind::OptionalNumber;
        m.whole = true;
        return m;
    }

    // The boundary's paths as text; what does not parse is kept for the
    // check to refuse.
    static FormField boundaryField(const form::FieldText& t)
    {
        FormField b = form::detail::textField(t.key, t.label, t.checks, FormFieldKind::Points);
        b.getText = [](const ModuleInput& in) -> std::string {
            const SurfaceUnit* u = in.getIf<SurfaceUnit>();
            if (!u) return {};
            return u->boundaryBad.empty() ? surfacemod::formatBoundary(u->boundary) : u->boundaryBad;
        };
        b.setText = [](ModuleInput& in, const std::string& text) {
            SurfaceUnit* u = in.getIf<SurfaceUnit>();
            if (!u) return;
            if (auto paths = surfacemod::parseBoundary(text)) {
                u->boundary = std::move(*paths);
                u->boundaryBad.clear();
            } else {
                u->boundaryBad = text;
            }
        };
        return b;
    }

    // The ball end mill pinned for the surface's steps, empty: chosen.
    static FormField toolField(const form::FieldText& t)
    {
        FormField tool = form::number<SurfaceUnit>(
            t.key, t.label, t.checks,
            [](const SurfaceUnit& u) {
                const auto pin = u.tools.find(surfacemod::kStepKey);
                return pin == u.tools.end() ? std::nullopt : std::optional<double>(pin->second);
            },
            [](SurfaceUnit&, double) {});
        tool.set = [](ModuleInput& mi, std::optional<double> v) {
            SurfaceUnit* u = mi.getIf<SurfaceUnit>();
            if (!u) return;
            if (v) u->tools[surfacemod::kStepKey] = static_cast<int>(std::lround(std::clamp(*v, -1e9, 1e9)));
            else u->tools.erase(surfacemod::kStepKey);
        };
        tool.kind = FormFieldKind::OptionalNumber;
        tool.whole = true;
        return tool;
    }

    static FormField curveField(const form::FieldText& t, SurfaceCurve SurfaceUnit::*curve,
                                std::string SurfaceUnit::*bad)
    {
        // A unit whose surface is a STEP face set shows empty curves (the
        // placeholder says why; its refusals show under curve 1); a curve
        // typed there makes the curves the surface again.
        FormField f = form::detail::textField(t.key, t.label, t.checks, FormFieldKind::Points);
        f.getText = [curve, bad](const ModuleInput& in) -> std::string {
            const SurfaceUnit* u = in.getIf<SurfaceUnit>();
            if (!u || (!u->surface.empty() && (u->*bad).empty())) return {};
            return (u->*bad).empty() ? surfacemod::formatCurve(u->*curve) : u->*bad;
        };
        f.setText = [curve, bad](ModuleInput& in, const std::string& text) {
            SurfaceUnit* u = in.getIf<SurfaceUnit>();
            if (!u) return;
            if (!u->surface.empty() && text.empty()) return;  // the face set stays
            if (auto c = surfacemod::parseCurve(text)) {
                u->*curve = std::move(*c);
                (u->*bad).clear();
                u->surface.clear();
            } else {
                u->*bad = text;
            }
        };
        return f;
    }
};

}  // namespace

const ModuleKind& surfaceModule() { return moduleInstance<SurfaceKind>(); }

}  // namespace taiwa
