// Space curves from two projections, division by length and ruled surfaces
// (surface_curves.h), with OpenCASCADE's B-spline interpolation
// (Geom2dAPI_Interpolate, GeomAPI_Interpolate), division by arc length
// (GCPnts_UniformAbscissa) and planarity test (GeomLib_IsPlanarSurface).
#include "occt/surface_curves.h"

#include <fmt/format.h>

#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

namespace taiwa::surface {

namespace {

constexpr double kSame = 1e-9;  // mm: two points closer than this are one

const char* planeName(ProjectionPlane p)
{
    switch (p) {
    case ProjectionPlane::XY: return "XY";
    case ProjectionPlane::YZ: return "YZ";
    case ProjectionPlane::ZX: return "ZX";
    }
    return "?";
}

// The space axes (0 x, 1 y, 2 z) of a plane's two coordinates.
std::array<int, 2> axesOf(ProjectionPlane p)
{
    switch (p) {
    case ProjectionPlane::XY: return {0, 1};
    case ProjectionPlane::YZ: return {1, 2};
    case ProjectionPlane::ZX: return {2, 0};
    }
    return {0, 1};
}

const char* axisName(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

// Knots and multiplicities of a curve of degree 1 through points at `params`.
Handle(Geom2d_BSplineCurve) polyline2d(const std::vector<Point2>& pts, const std::vector<double>& params)
{
    const int n = static_cast<int>(pts.size());
    TColgp_Array1OfPnt2d poles(1, n);
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger mults(1, n);
    for (int i = 0; i < n; ++i) {
        poles.SetValue(i + 1, gp_Pnt2d(pts[static_cast<std::size_t>(i)].x, pts[static_cast<std::size_t>(i)].y));
        knots.SetValue(i + 1, params[static_cast<std::size_t>(i)]);
        mults.SetValue(i + 1, i == 0 || i == n - 1 ? 2 : 1);
    }
    return new Geom2d_BSplineCurve(poles, knots, mults, 1);
}

// A projection as a plane curve with its points' parameters (chord length).
struct PlaneCurve {
    Handle(Geom2d_BSplineCurve) curve;
    std::vector<double> params;  // of the given points
    bool smooth = true;
};

PlaneCurve makePlaneCurve(const std::vector<Point2>& pts, bool smooth)
{
    PlaneCurve c;
    c.smooth = smooth;
    c.params.push_back(0.0);
    for (std::size_t i = 1; i < pts.size(); ++i)
        c.params.push_back(c.params.back() + std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y));
    if (smooth && pts.size() > 2) {
        Handle(TColgp_HArray1OfPnt2d) p = new TColgp_HArray1OfPnt2d(1, static_cast<int>(pts.size()));
        Handle(TColStd_HArray1OfReal) t = new TColStd_HArray1OfReal(1, static_cast<int>(pts.size()));
        for (std::size_t i = 0; i < pts.size(); ++i) {
            p->SetValue(static_cast<int>(i) + 1, gp_Pnt2d(pts[i].x, pts[i].y));
            t->SetValue(static_cast<int>(i) + 1, c.params[i]);
        }
        Geom2dAPI_Interpolate interp(p, t, Standard_False, kSame);
        interp.Perform();
        if (!interp.IsDone()) throw Standard_Failure("interpolation failed");
        c.curve = interp.Curve();
    } else {
        c.curve = polyline2d(pts, c.params);
    }
    return c;
}

// The parameter of `c` where its coordinate `k` (0 or 1) is `value`, the
// value lying between the given points i and i + 1: Newton's steps kept
// within a shrinking bracket (bisection when a step leaves it).
double parameterAt(const PlaneCurve& c, const std::vector<Point2>& pts, int k, double value)
{
    const auto coord = [k](const gp_Pnt2d& p) { return k == 0 ? p.X() : p.Y(); };
    const auto of = [k](const Point2& p) { return k == 0 ? p.x : p.y; };
    std::size_t i = 0;
    const bool rising = of(pts.back()) > of(pts.front());
    while (i + 2 < pts.size() && (rising ? of(pts[i + 1]) < value : of(pts[i + 1]) > value)) ++i;
    double lo = c.params[i], hi = c.params[i + 1];
    if (std::abs(of(pts[i]) - value) < kSame) return lo;
    if (std::abs(of(pts[i + 1]) - value) < kSame) return hi;
    double u = lo + (hi - lo) * (value - of(pts[i])) / (of(pts[i + 1]) - of(pts[i]));
    for (int iter = 0; iter < 100; ++iter) {
        gp_Pnt2d p;
        gp_Vec2d d;
        c.curve->D1(u, p, d);
        const double f = coord(p) - value;
        if (std::abs(f) < 1e-12) break;
        // Keep the bracket: f has the sign of (u − root) when rising.
        if ((f > 0) == rising) hi = u; else lo = u;
        const double dv = k == 0 ? d.X() : d.Y();
        double next = dv != 0.0 ? u - f / dv : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (hi - lo < 1e-15) break;
        u = next;
    }
    return u;
}

// Points dividing the plane curve between parameters a and b into pieces of
// at most `step` along it; a curve of straight lines keeps its corners.
std::vector<gp_Pnt2d> dividePlaneCurve(const PlaneCurve& c, double a, double b, double step)
{
    std::vector<double> cuts{a};
    if (!c.smooth)
        for (double t : c.params)
            if (t > a + kSame && t < b - kSame) cuts.push_back(t);
    cuts.push_back(b);
    Geom2dAdaptor_Curve adaptor(c.curve);
    std::vector<gp_Pnt2d> out{c.curve->Value(a)};
    for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
        const double len = GCPnts_AbscissaPoint::Length(adaptor, cuts[s], cuts[s + 1]);
        const int pieces = std::max(1, static_cast<int>(std::ceil(len / step - 1e-9)));
        GCPnts_UniformAbscissa div(adaptor, pieces + 1, cuts[s], cuts[s + 1]);
        if (!div.IsDone() || div.NbPoints() != pieces + 1) throw Standard_Failure("division failed");
        for (int i = 2; i <= div.NbPoints(); ++i) out.push_back(c.curve->Value(div.Parameter(i)));
    }
    return out;
}

std::optional<std::string> monotonicRefusal(const Projection& p, int which, int k, int axis)
{
    const auto of = [k](const Point2& q) { return k == 0 ? q.x : q.y; };
    if (p.points.size() < 2)
        return fmt::format("projection {} ({}): it needs at least two points, it has {}", which, planeName(p.plane),
                           p.points.size());
    const double dir = of(p.points[1]) - of(p.points[0]);
    for (std::size_t i = 1; i < p.points.size(); ++i) {
        const double d = of(p.points[i]) - of(p.points[i - 1]);
        if (std::abs(d) < kSame || (d > 0) != (dir > 0))
            return fmt::format("projection {} ({}), point {} ({} {:.4f}): {} must rise or fall all along the curve, "
                               "it {} after point {}",
                               which, planeName(p.plane), i + 1, axisName(axis), of(p.points[i]), axisName(axis),
                               std::abs(d) < kSame ? "stands still" : "turns back", i);
    }
    return std::nullopt;
}

Handle(Geom_BSplineCurve) spaceCurve(const SpaceCurve& c)
{
    const int n = static_cast<int>(c.points.size());
    std::vector<double> t{0.0};
    for (int i = 1; i < n; ++i) {
        const Point3& p = c.points[static_cast<std::size_t>(i - 1)];
        const Point3& q = c.points[static_cast<std::size_t>(i)];
        t.push_back(t.back() + std::sqrt((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) +
                                         (q.z - p.z) * (q.z - p.z)));
    }
    if (c.smooth && n > 2) {
        Handle(TColgp_HArray1OfPnt) p = new TColgp_HArray1OfPnt(1, n);
        Handle(TColStd_HArray1OfReal) tt = new TColStd_HArray1OfReal(1, n);
        for (int i = 0; i < n; ++i) {
            const Point3& q = c.points[static_cast<std::size_t>(i)];
            p->SetValue(i + 1, gp_Pnt(q.x, q.y, q.z));
            tt->SetValue(i + 1, t[static_cast<std::size_t>(i)]);
        }
        GeomAPI_Interpolate interp(p, tt, Standard_False, kSame);
        interp.Perform();
        if (!interp.IsDone()) throw Standard_Failure("interpolation failed");
        return interp.Curve();
    }
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger mults(1, n);
    for (int i = 0; i < n; ++i) {
        const Point3& q = c.points[static_cast<std::size_t>(i)];
        poles.SetValue(i + 1, gp_Pnt(q.x, q.y, q.z));
        knots.SetValue(i + 1, t[static_cast<std::size_t>(i)]);
        mults.SetValue(i + 1, i == 0 || i == n - 1 ? 2 : 1);
    }
    return new Geom_BSplineCurve(poles, knots, mults, 1);
}

Result<std::vector<Point3>> divideNamed(const SpaceCurve& curve, int pieces, const std::string& name)
{
    if (pieces < 1) return Failure{fmt::format("{}: it must be divided into at least 1 piece, not {}", name, pieces)};
    if (curve.points.size() < 2)
        return Failure{fmt::format("{}: it needs at least two points, it has {}", name, curve.points.size())};
    for (std::size_t i = 1; i < curve.points.size(); ++i) {
        const Point3& p = curve.points[i - 1];
        const Point3& q = curve.points[i];
        if (std::abs(q.x - p.x) + std::abs(q.y - p.y) + std::abs(q.z - p.z) < kSame)
            return Failure{fmt::format("{}: points {} and {} are the same point", name, i, i + 1)};
    }
    try {
        Handle(Geom_BSplineCurve) c = spaceCurve(curve);
        GeomAdaptor_Curve adaptor(c);
        GCPnts_UniformAbscissa div(adaptor, pieces + 1);
        if (!div.IsDone() || div.NbPoints() != pieces + 1)
            return Failure{fmt::format("{}: OpenCASCADE could not divide it into {} pieces", name, pieces)};
        std::vector<Point3> out;
        for (int i = 1; i <= div.NbPoints(); ++i) {
            const gp_Pnt p = c->Value(div.Parameter(i));
            out.push_back({p.X(), p.Y(), p.Z()});
        }
        return out;
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format("{}: OpenCASCADE refused it ({})", name, e.GetMessageString())};
    }
}

}  // namespace

Result<SpaceCurve> spaceCurveFromProjections(const Projection& first, const Projection& second, double step)
{
    if (!(step > 0.0)) return Failure{fmt::format("the division step must be above 0, not {}", step)};
    const std::array<int, 2> a1 = axesOf(first.plane), a2 = axesOf(second.plane);
    if (first.plane == second.plane)
        return Failure{fmt::format("projection 2 lies in the same plane ({}) as projection 1: a space curve needs two "
                                   "planes",
                                   planeName(first.plane))};
    // The shared axis and where it is in each projection's coordinates.
    int shared = -1, k1 = -1, k2 = -1;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            if (a1[static_cast<std::size_t>(i)] == a2[static_cast<std::size_t>(j)]) {
                shared = a1[static_cast<std::size_t>(i)];
                k1 = i;
                k2 = j;
            }
    const int own1 = a1[static_cast<std::size_t>(1 - k1)];
    const int own2 = a2[static_cast<std::size_t>(1 - k2)];
    if (auto r = monotonicRefusal(first, 1, k1, shared)) return Failure{*r};
    if (auto r = monotonicRefusal(second, 2, k2, shared)) return Failure{*r};

    const auto range = [](const Projection& p, int k) {
        const double s = k == 0 ? p.points.front().x : p.points.front().y;
        const double e = k == 0 ? p.points.back().x : p.points.back().y;
        return std::pair{std::min(s, e), std::max(s, e)};
    };
    const auto [lo1, hi1] = range(first, k1);
    const auto [lo2, hi2] = range(second, k2);
    const double lo = std::max(lo1, lo2), hi = std::min(hi1, hi2);
    if (hi - lo < 1e-6)
        return Failure{fmt::format("projection 2 ({}): its {} range {:.4f} to {:.4f} does not overlap projection 1's "
                                   "({}) {:.4f} to {:.4f}",
                                   planeName(second.plane), axisName(shared), lo2, hi2, planeName(first.plane), lo1,
                                   hi1)};
    try {
        const PlaneCurve c1 = makePlaneCurve(first.points, first.smooth);
        const PlaneCurve c2 = makePlaneCurve(second.points, second.smooth);
        double ua = parameterAt(c1, first.points, k1, lo), ub = parameterAt(c1, first.points, k1, hi);
        if (ua > ub) std::swap(ua, ub);
        SpaceCurve out;
        out.smooth = first.smooth && second.smooth;
        for (const gp_Pnt2d& p : dividePlaneCurve(c1, ua, ub, step)) {
            const double b = std::clamp(k1 == 0 ? p.X() : p.Y(), lo, hi);
            const gp_Pnt2d q = c2.curve->Value(parameterAt(c2, second.points, k2, b));
            std::array<double, 3> xyz{};
            xyz[static_cast<std::size_t>(shared)] = b;
            xyz[static_cast<std::size_t>(own1)] = k1 == 0 ? p.Y() : p.X();
            xyz[static_cast<std::size_t>(own2)] = k2 == 0 ? q.Y() : q.X();
            out.points.push_back({xyz[0], xyz[1], xyz[2]});
        }
        return out;
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format("projections {} and {}: OpenCASCADE refused them ({})", planeName(first.plane),
                                   planeName(second.plane), e.GetMessageString())};
    }
}

Result<std::vector<Point3>> divideByLength(const SpaceCurve& curve, int pieces)
{
    return divideNamed(curve, pieces, "the curve");
}

Point3 RuledSurface::point(double u, double v) const
{
    const int n = pieces();
    const int i = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
    const double f = u - i;
    const auto lerp = [](const Point3& a, const Point3& b, double t) {
        return Point3{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
    };
    const auto ui = static_cast<std::size_t>(i);
    return lerp(lerp(first[ui], first[ui + 1], f), lerp(second[ui], second[ui + 1], f), v);
}

std::vector<std::vector<Point3>> pathsOfRuled(const RuledSurface& s, int alongRulings, int betweenRulings)
{
    alongRulings = std::max(1, alongRulings);
    betweenRulings = std::max(1, betweenRulings);
    const int cols = s.pieces() * betweenRulings + 1;
    std::vector<std::vector<Point3>> rows;
    for (int k = 0; k <= alongRulings; ++k) {
        const double v = static_cast<double>(k) / alongRulings;
        std::vector<Point3> row;
        for (int j = 0; j < cols; ++j) row.push_back(s.point(static_cast<double>(j) / betweenRulings, v));
        rows.push_back(std::move(row));
    }
    return rows;
}

Result<int> piecesForStepOver(const SpaceCurve& first, const SpaceCurve& second, double stepOver)
{
    if (!(stepOver > 0.0)) return Failure{fmt::format("the step-over must be above 0, not {}", stepOver)};
    double longest = 0.0;
    int which = 1;
    for (const SpaceCurve* c : {&first, &second}) {
        const std::string name = fmt::format("curve {}", which++);
        if (c->points.size() < 2) return Failure{fmt::format("{}: it needs at least two points", name)};
        try {
            Handle(Geom_BSplineCurve) curve = spaceCurve(*c);
            GeomAdaptor_Curve adaptor(curve);
            longest = std::max(longest, GCPnts_AbscissaPoint::Length(adaptor));
        } catch (const Standard_Failure& e) {
            return Failure{fmt::format("{}: OpenCASCADE could not measure it ({})", name, e.GetMessageString())};
        }
    }
    return std::max(1, static_cast<int>(std::ceil(longest / stepOver - 1e-9)));
}

Result<RuledSurface> ruledSurface(const SpaceCurve& first, const SpaceCurve& second, int pieces)
{
    auto a = divideNamed(first, pieces, "curve 1");
    if (!a) return Failure{a.error()};
    auto b = divideNamed(second, pieces, "curve 2");
    if (!b) return Failure{b.error()};
    return RuledSurface{std::move(*a), std::move(*b)};
}

Result<RoughAndFinish> roughAndFinishSurfaces(const SpaceCurve& first, const SpaceCurve& second, int n, int m)
{
    if (n < 1) return Failure{fmt::format("N: the roughing surface needs at least 1 piece, not {}", n)};
    if (m <= n)
        return Failure{fmt::format("M: the finishing surface's pieces (M = {}) must be more than the roughing "
                                   "surface's (N = {})",
                                   m, n)};
    auto r = ruledSurface(first, second, n);
    if (!r) return Failure{r.error()};
    auto f = ruledSurface(first, second, m);
    if (!f) return Failure{f.error()};
    return RoughAndFinish{std::move(*r), std::move(*f)};
}

Result<Plane3> planeOf(const RuledSurface& s, double tolerance)
{
    const int n = static_cast<int>(s.first.size());
    if (n < 2 || s.second.size() != s.first.size())
        return Failure{"the ruled surface needs two curves of the same number of points, at least two"};
    try {
        TColgp_Array2OfPnt poles(1, n, 1, 2);
        TColStd_Array1OfReal uk(1, n);
        TColStd_Array1OfInteger um(1, n);
        for (int i = 0; i < n; ++i) {
            const Point3& a = s.first[static_cast<std::size_t>(i)];
            const Point3& b = s.second[static_cast<std::size_t>(i)];
            poles.SetValue(i + 1, 1, gp_Pnt(a.x, a.y, a.z));
            poles.SetValue(i + 1, 2, gp_Pnt(b.x, b.y, b.z));
            uk.SetValue(i + 1, i);
            um.SetValue(i + 1, i == 0 || i == n - 1 ? 2 : 1);
        }
        TColStd_Array1OfReal vk(1, 2);
        TColStd_Array1OfInteger vm(1, 2);
        vk.SetValue(1, 0.0);
        vk.SetValue(2, 1.0);
        vm.SetValue(1, 2);
        vm.SetValue(2, 2);
        Handle(Geom_BSplineSurface) surf = new Geom_BSplineSurface(poles, uk, vk, um, vm, 1, 1);
        GeomLib_IsPlanarSurface planar(surf, tolerance);
        if (!planar.IsPlanar()) return Failure{fmt::format("the ruled surface is not a plane within {} mm", tolerance)};
        const gp_Pln pln = planar.Plan();
        gp_Dir d = pln.Axis().Direction();
        if (d.Z() < 0 || (d.Z() == 0 && (d.Y() < 0 || (d.Y() == 0 && d.X() < 0)))) d.Reverse();
        const gp_Pnt o = pln.Location();
        return Plane3{{o.X(), o.Y(), o.Z()}, {d.X(), d.Y(), d.Z()}};
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format("the ruled surface: OpenCASCADE refused it ({})", e.GetMessageString())};
    }
}

}  // namespace taiwa::surface
