// Ruled surfaces between two space curves (surface_curves.h): the surface
// joining their matching division points, its points and paths, the
// roughing and finishing pair, and whether it is a plane
// (OpenCASCADE's GeomLib_IsPlanarSurface).
#include "occt/surface_curves.h"
#include "occt/surface_division.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>

namespace taiwa::surface {

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

Result<RuledSurface> ruledSurface(const SpaceCurve& first, const SpaceCurve& second, int pieces)
{
    auto a = divideNamed(first, pieces, 1);
    if (!a) return Failure{a.error()};
    auto b = divideNamed(second, pieces, 2);
    if (!b) return Failure{b.error()};
    return RuledSurface{std::move(*a), std::move(*b)};
}

Result<RoughAndFinish> roughAndFinishSurfaces(const SpaceCurve& first, const SpaceCurve& second, int n, int m)
{
    if (n < 1)
        return Failure{fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "N: the roughing surface needs at least 1 piece, not {}"), n)};
    if (m <= n)
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "M: the finishing surface's pieces (M = {}) must be more "
                                                           "than the roughing surface's (N = {})"),
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
        return Failure{TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the ruled surface needs two curves of the same number of points, at least two")};
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
        if (!planar.IsPlanar())
            return Failure{fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "the ruled surface is not a plane within {} mm"), tolerance)};
        const gp_Pln pln = planar.Plan();
        gp_Dir d = pln.Axis().Direction();
        if (d.Z() < 0 || (d.Z() == 0 && (d.Y() < 0 || (d.Y() == 0 && d.X() < 0)))) d.Reverse();
        const gp_Pnt o = pln.Location();
        return Plane3{{o.X(), o.Y(), o.Z()}, {d.X(), d.Y(), d.Z()}};
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the ruled surface: OpenCASCADE refused it ({})"),
                                   e.GetMessageString())};
    }
}

}  // namespace taiwa::surface
