// The SURFACE unit's geometry, checks, tool choice and steps: the two space
// curves built (points or projections), the ruled roughing (N) and
// finishing (M) surfaces as point paths, the refusals naming their field
// (curves, N ≥ M, a boundary that never meets the surface, undercuts, a tool
// larger than the smallest concave radius with no smaller one), and the
// roughing and finishing steps with their one ball end mill.
#include "modules/surface/surface.h"

#include "check/check_unit.h"
#include "decompose/make_step.h"
#include "modules/surface/surface_messages.h"
#include "occt/surface_checks.h"
#include "occt/surface_curves.h"
#include "occt/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace taiwa {

namespace surfacemod {

namespace {

constexpr double kProjectionStep = 0.5;  // mm: the first projection's division
constexpr double kMeshSpacing = 1.0;     // mm: the surface's paths about this far apart
constexpr double kTwistSag = 0.2e-3;     // mm: the triangles off the bilinear patches
constexpr double kEps = 1e-9;

double dist(Point3 a, Point3 b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

Result<surface::SpaceCurve> spaceCurve(const SurfaceCurve& c, int which)
{
    const std::string name = msg::surfaceCurveName(which);
    if (!c.points.empty()) {
        if (c.points.size() < 2) return Failure{msg::surfaceCurveOnePoint(name)};
        return surface::SpaceCurve{c.points, c.smooth};
    }
    if (c.projections.size() != 2)
        return Failure{msg::surfaceCurveNeither(name)};
    surface::Projection p[2];
    for (int i = 0; i < 2; ++i) {
        const std::string& plane = c.projections[static_cast<std::size_t>(i)].plane;
        if (plane == "XY") p[i].plane = surface::ProjectionPlane::XY;
        else if (plane == "YZ") p[i].plane = surface::ProjectionPlane::YZ;
        else if (plane == "ZX") p[i].plane = surface::ProjectionPlane::ZX;
        else return Failure{msg::surfaceProjectionPlane(name, i + 1, plane)};
        const SurfaceProjection& given = c.projections[static_cast<std::size_t>(i)];
        if (!given.contourProblem.empty())
            return Failure{msg::surfaceProjectionProblem(which, i + 1, given.contourProblem)};
        p[i].points = given.points;
        // A contour's points lie on its lines and arcs: straight between them.
        p[i].smooth = c.smooth && given.contour.empty();
    }
    auto curve = surface::spaceCurveFromProjections(p[0], p[1], kProjectionStep);
    if (!curve) return Failure{surface::curveRefusal(which, curve.error())};
    return curve;
}

// The surface as paths along the curves, about kMeshSpacing apart both ways.
std::vector<std::vector<Point3>> pathsOf(const surface::RuledSurface& s)
{
    double ruling = 0.0, along = 0.0;
    for (std::size_t i = 0; i < s.first.size(); ++i) ruling = std::max(ruling, dist(s.first[i], s.second[i]));
    for (std::size_t i = 1; i < s.first.size(); ++i)
        along = std::max(along, std::max(dist(s.first[i - 1], s.first[i]), dist(s.second[i - 1], s.second[i])));
    const int a = std::clamp(static_cast<int>(std::ceil(ruling / kMeshSpacing)), 2, 400);
    // A bilinear patch's twist w bows it off the two triangles of a cell of
    // du × dv of it by |w·n|·du·dv/4 along its normal n: enough cells
    // between the rulings to keep that within kTwistSag (the tests' oracle,
    // OpenCASCADE's exact patches, saw 1.3 µm at the sample's curve end with
    // five cells).
    double twist = 0.0;
    for (std::size_t i = 0; i + 1 < s.first.size(); ++i) {
        const Point3 f0 = s.first[i], f1 = s.first[i + 1], s0 = s.second[i], s1 = s.second[i + 1];
        const double wx = f1.x - f0.x - (s1.x - s0.x), wy = f1.y - f0.y - (s1.y - s0.y), wz = f1.z - f0.z - (s1.z - s0.z);
        const double ux = f1.x - f0.x + s1.x - s0.x, uy = f1.y - f0.y + s1.y - s0.y, uz = f1.z - f0.z + s1.z - s0.z;
        const double vx = s0.x - f0.x + s1.x - f1.x, vy = s0.y - f0.y + s1.y - f1.y, vz = s0.z - f0.z + s1.z - f1.z;
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const double nl = std::hypot(nx, ny, nz);
        if (nl > 0) twist = std::max(twist, std::abs(wx * nx + wy * ny + wz * nz) / nl);
    }
    const int b = std::clamp(static_cast<int>(std::ceil(std::max(along / kMeshSpacing, twist / (4 * kTwistSag * a)))), 1, 200);
    return surface::pathsOfRuled(s, a, b);
}

// The built surface machined from above: under the stock top and no
// undercut, else refused on `field`.
Built heightField(Built b, const char* field, LengthUnit shown)
{
    double top = -std::numeric_limits<double>::infinity();
    for (const auto& p : b.finishing)
        for (const Point3& q : p) top = std::max(top, q.z);
    const auto refuse = [&](std::string problem) {
        b.field = field;
        b.problem = std::move(problem);
        return b;
    };
    if (top > kEps)
        return refuse(msg::surfaceAboveTop({top, shown}));
    // Where, and that the verification cannot see it (occt/surface_checks.cpp).
    if (auto undercut = surface::findUndercut(b.finishing)) return refuse(*undercut);
    return b;
}

}  // namespace

Built buildSurfaces(const SurfaceUnit& u, LengthUnit shown)
{
    Built b;
    const auto refuse = [&](std::string field, std::string problem) {
        b.field = std::move(field);
        b.problem = std::move(problem);
        return b;
    };
    using Unread = std::tuple<const char*, const std::string*, int>;
    for (const auto& [field, bad, which] : {Unread{"curve1", &u.curve1Bad, 1}, Unread{"curve2", &u.curve2Bad, 2}})
        if (!bad->empty()) return refuse(field, msg::surfaceCurveUnread(msg::surfaceCurveName(which), *bad));
    // A face set's paths (taiwa import --surface): as they are, for both steps.
    if (!u.surface.empty()) {
        const std::size_t points = u.surface.front().size();
        if (u.surface.size() < 2 || points < 2)
            return refuse("surface", msg::surfaceTooFewPaths());
        for (std::size_t k = 1; k < u.surface.size(); ++k)
            if (u.surface[k].size() != points)
                return refuse("surface", msg::surfacePathPoints(k + 1, u.surface[k].size(), points));
        b.roughing = b.finishing = u.surface;
        b.m = static_cast<int>(u.surface.size()) - 1;
        return heightField(std::move(b), "surface", shown);
    }
    auto c1 = spaceCurve(u.curve1, 1);
    if (!c1) return refuse("curve1", c1.error());
    auto c2 = spaceCurve(u.curve2, 2);
    if (!c2) return refuse("curve2", c2.error());
    if (u.n < 1) return refuse("n", msg::surfaceNBelowOne(u.n));
    int m = 0;
    if (u.m) m = *u.m;
    else if (u.curveStep) {
        auto pieces = surface::piecesForStepOver(*c1, *c2, *u.curveStep);
        if (!pieces) return refuse("curveStep", pieces.error());
        m = *pieces;
    } else
        return refuse("m", msg::surfaceNoM());
    if (u.n >= m)
        return refuse("n", msg::surfaceNNotBelowM(u.n, m));
    auto surfaces = surface::roughAndFinishSurfaces(*c1, *c2, u.n, m);
    if (!surfaces) return refuse("curve1", surfaces.error());
    b.m = m;
    b.roughing = pathsOf(surfaces->roughing);
    b.finishing = pathsOf(surfaces->finishing);
    return heightField(std::move(b), "curve1", shown);
}

ToolPick chooseTool(const SurfaceUnit& u, double rho, const std::string& where, const std::vector<Tool>& library,
                    LengthUnit shown)
{
    ToolPick pick;
    const auto ball = [](const Tool& t) { return t.type == ToolType::BallEndMill && t.diameter > 0.0; };
    const auto fits = [&](const Tool& t) { return t.radius() < rho - kEps; };
    const Tool* smaller = nullptr;
    for (const Tool& t : library)
        if (ball(t) && fits(t) && (!smaller || t.diameter > smaller->diameter)) smaller = &t;
    if (const auto pin = u.tools.find(kStepKey); pin != u.tools.end()) {
        const Tool* t = findTool(library, pin->second);
        if (!t) pick.problem = msg::toolNotInLibrary(pin->second);
        else if (!ball(*t))
            pick.problem = msg::surfacePinnedNotBall(*t);
        else if (!fits(*t))
            pick.problem = msg::surfacePinnedTooLarge(*t, {t->radius(), shown}, {rho, shown}, where, smaller);
        else {
            pick.tool = t;
            pick.reason = msg::surfacePinnedByOperator();
        }
        return pick;
    }
    if (!smaller) {
        pick.problem = msg::surfaceNoBall({rho, shown}, where);
        return pick;
    }
    pick.tool = smaller;
    pick.reason = msg::surfaceToolReason(*smaller, {rho, shown}, where);
    return pick;
}

}  // namespace surfacemod

check::UnitReport checkSurface(const SurfaceUnit& u, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, SurfaceUnit::kName, ctx, [&](check::Reporter& r, check::UnitReport& report) {
        report.figureValid = false;
        bool ok = true;
        if (!(std::isfinite(u.scallop) && u.scallop > 0.0)) {
            r.unit("scallop", msg::surfaceScallopNotPositive(r.len(u.scallop)));
            ok = false;
        }
        if (!(std::isfinite(u.allowance) && u.allowance >= 0.0)) {
            r.unit("allowance", msg::surfaceAllowanceNegative(r.len(u.allowance)));
            ok = false;
        }
        // A pin of another step: said by check::checkPins (the door runs it).
        for (const auto& [key, id] : u.tools) ok = ok && key == surfacemod::kStepKey;
        const surfacemod::Built b = surfacemod::buildSurfaces(u, ctx.shownUnit);
        if (!b.problem.empty()) {
            r.unit(b.field, b.problem);
            return;
        }
        if (const Stock* st = ctx.stock) {
            double low = std::numeric_limits<double>::infinity();
            for (const auto& p : b.finishing)
                for (const Point3& q : p) low = std::min(low, q.z);
            if (low <= -st->height)
                r.unit(u.surface.empty() ? "curve1" : "surface", msg::surfaceThroughBottom(r.len(low), r.len(st->height)));
        }
        if (!u.boundaryBad.empty())
            r.unit("boundary", msg::surfaceBoundaryUnread(u.boundaryBad));
        else if (!u.boundary.empty()) {
            surface::TriangleMesh mesh = surface::meshFromPaths(u.boundary);
            if (mesh.triangles.empty())
                r.unit("boundary", msg::surfaceBoundaryNoSurface());
            else if (!surface::boundaryMeetsSurface(b.finishing, surface::MeshIndex(std::move(mesh))))
                r.unit("boundary", msg::surfaceBoundaryMissesSurface());
        }
        report.figureValid = true;
        if (!ok || !ctx.library) return;
        const surface::ConcaveRadius rho = surface::smallestConcaveRadius(b.finishing);
        const surfacemod::ToolPick pick = surfacemod::chooseTool(u, rho.radius, rho.where, *ctx.library, ctx.shownUnit);
        if (!pick.tool) r.unit("tools.surface", pick.problem);
    });
}

std::vector<Step> planSurface(const SurfaceUnit& u, const TechnologyData& tech, const std::vector<Tool>& library,
                              int unit, LengthUnit shown, Diagnostics& out)
{
    const auto problem = [&](std::string field, std::string message) {
        out.push_back({Severity::Error, unit + 1, SurfaceUnit::kName, std::move(field), std::move(message)});
        return std::vector<Step>{};
    };
    (void)tech;
    const surfacemod::Built b = surfacemod::buildSurfaces(u, shown);
    if (!b.problem.empty()) return problem(b.field, b.problem);
    const surface::ConcaveRadius rho = surface::smallestConcaveRadius(b.finishing);
    const surfacemod::ToolPick pick = surfacemod::chooseTool(u, rho.radius, rho.where, library, shown);
    if (!pick.tool) return problem("tools.surface", pick.problem);
    // Straight moves between nose points cut a convex bend of radius ρ by
    // L²/(8ρ): the step along a path keeps that within 1 µm, 0.25 mm at most (the ball over the surface's edges needs it).
    const double step = std::clamp(std::sqrt(8.0 * rho.radius * 1e-3), 0.1, 0.25);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    const auto make = [&](StepKind kind, MachiningType type, const std::vector<std::vector<Point3>>& paths,
                          const std::vector<std::vector<Point3>>& finished) {
        double low = 1e300;
        for (const auto& p : paths)
            for (const Point3& q : p) {
                low = std::min(low, q.z);
                x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
            }
        Step s = decompose::makeStep(unit, SurfaceUnit::kName, kind, 1, type);
        s.tool = ToolChoice{pick.tool->id, pick.reason};
        s.payload = SurfacePaths{paths, finished, u.boundary, u.scallop, u.allowance, rho.radius, step,
                                 {.outline = Quad{{Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}}, 0.0},
                                  .position = {(x0 + x1) / 2, (y0 + y1) / 2},
                                  .startDepth = 0.0,
                                  .cutDepth = -low}};
        return s;
    };
    std::vector<Step> steps;
    steps.push_back(make(StepKind::SurfaceRoughing, MachiningType::SurfaceRoughing, b.roughing, b.finishing));
    editMilling(steps.back()).floorAllowance = u.allowance;
    steps.push_back(make(StepKind::SurfaceFinishing, MachiningType::SurfaceFinishing, b.finishing, {}));
    return steps;
}

}  // namespace taiwa
