// Space curves from two projections and their division by length
// (surface_curves.h), with OpenCASCADE's B-spline interpolation
// (Geom2dAPI_Interpolate, GeomAPI_Interpolate) and division by arc length
// (GCPnts_UniformAbscissa). The ruled surfaces between two curves:
// surface_ruled.cpp.
#include "occt/surface_curves.h"
#include "occt/surface_division.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>

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
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "projection {} ({}): {}"), which, planeName(p.plane),
                           fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it needs at least two points, it has {}"),
                                       p.points.size()));
    const double dir = of(p.points[1]) - of(p.points[0]);
    for (std::size_t i = 1; i < p.points.size(); ++i) {
        const double d = of(p.points[i]) - of(p.points[i - 1]);
        if (std::abs(d) < kSame || (d > 0) != (dir > 0))
            return fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "projection {} ({}), point {} ({} {:.4f}): {} must rise or fall all "
                                                   "along the curve, it {} after point {}"),
                which, planeName(p.plane), i + 1, axisName(axis), of(p.points[i]), axisName(axis),
                std::abs(d) < kSame ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "stands still")
                                    : TAIWA_TRANSLATE_NOOP("taiwa::msg", "turns back"),
                i);
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

}  // namespace

Result<SpaceCurve> spaceCurveFromProjections(const Projection& first, const Projection& second, double step)
{
    if (!(step > 0.0))
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the division step must be above 0, not {}"), step)};
    const std::array<int, 2> a1 = axesOf(first.plane), a2 = axesOf(second.plane);
    if (first.plane == second.plane)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                        "projection 2 lies in the same plane ({}) as projection 1: a "
                                                        "space curve needs two planes"),
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
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "projection 2 ({}): its {} range {:.4f} to {:.4f} does not "
                                                           "overlap projection 1's ({}) {:.4f} to {:.4f}"),
                        planeName(second.plane), axisName(shared), lo2, hi2, planeName(first.plane), lo1, hi1)};
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
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "projections {} and {}: OpenCASCADE refused them ({})"),
                        planeName(first.plane), planeName(second.plane), e.GetMessageString())};
    }
}

Result<std::vector<Point3>> divideByLength(const SpaceCurve& curve, int pieces)
{
    return divideNamed(curve, pieces, 0);
}

Result<int> piecesForStepOver(const SpaceCurve& first, const SpaceCurve& second, double stepOver)
{
    if (!(stepOver > 0.0))
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over must be above 0, not {}"), stepOver)};
    double longest = 0.0;
    for (const SpaceCurve* c : {&first, &second}) {
        const int which = c == &first ? 1 : 2;
        if (c->points.size() < 2)
            return Failure{curveRefusal(which, TAIWA_TRANSLATE_NOOP("taiwa::msg", "it needs at least two points"))};
        try {
            Handle(Geom_BSplineCurve) curve = spaceCurve(*c);
            GeomAdaptor_Curve adaptor(curve);
            longest = std::max(longest, GCPnts_AbscissaPoint::Length(adaptor));
        } catch (const Standard_Failure& e) {
            return Failure{curveRefusal(
                which, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "OpenCASCADE could not measure it ({})"),
                                   e.GetMessageString()))};
        }
    }
    return std::max(1, static_cast<int>(std::ceil(longest / stepOver - 1e-9)));
}

std::string curveRefusal(int which, const std::string& why)
{
    if (which == 1)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "curve 1: {}"), why);
    if (which == 2)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "curve 2: {}"), why);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the curve: {}"), why);
}

// A curve divided into `pieces` equal lengths; refusals name it (curveRefusal).
Result<std::vector<Point3>> divideNamed(const SpaceCurve& curve, int pieces, int which)
{
    const auto refuse = [which](const std::string& why) { return Failure{curveRefusal(which, why)}; };
    if (pieces < 1)
        return refuse(fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "it must be divided into at least 1 piece, not {}"), pieces));
    if (curve.points.size() < 2)
        return refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it needs at least two points, it has {}"),
                                  curve.points.size()));
    for (std::size_t i = 1; i < curve.points.size(); ++i) {
        const Point3& p = curve.points[i - 1];
        const Point3& q = curve.points[i];
        if (std::abs(q.x - p.x) + std::abs(q.y - p.y) + std::abs(q.z - p.z) < kSame)
            return refuse(
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "points {} and {} are the same point"), i, i + 1));
    }
    try {
        Handle(Geom_BSplineCurve) c = spaceCurve(curve);
        GeomAdaptor_Curve adaptor(c);
        GCPnts_UniformAbscissa div(adaptor, pieces + 1);
        if (!div.IsDone() || div.NbPoints() != pieces + 1)
            return refuse(fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "OpenCASCADE could not divide it into {} pieces"), pieces));
        std::vector<Point3> out;
        for (int i = 1; i <= div.NbPoints(); ++i) {
            const gp_Pnt p = c->Value(div.Parameter(i));
            out.push_back({p.X(), p.Y(), p.Z()});
        }
        return out;
    } catch (const Standard_Failure& e) {
        return refuse(
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "OpenCASCADE refused it ({})"), e.GetMessageString()));
    }
}

}  // namespace taiwa::surface
