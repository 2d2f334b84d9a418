// The surface unit's geometric checks (surface_checks.h): undercuts by the
// paths' quads' normals, the smallest concave radius by circles through
// three neighbouring points, the boundary by crossing the paths' segments.
#include "occt/surface_checks.h"

#include "model/translate_noop.h"
#include "occt/surface_paths.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace taiwa::surface {

namespace {

// Z of the (unnormalised) normal of the quad paths[i][j] … paths[i+1][j+1]:
// twice its signed area in XY.
double quadNormalZ(const std::vector<std::vector<Point3>>& p, std::size_t i, std::size_t j)
{
    const Point3 &a = p[i][j], &b = p[i][j + 1], &c = p[i + 1][j + 1], &d = p[i + 1][j];
    return (c.x - a.x) * (d.y - b.y) - (c.y - a.y) * (d.x - b.x);
}

// The circle through a, b, c: its radius when b lies below the chord a–c
// (a concave bend), nothing otherwise.
std::optional<double> concaveRadius(const Point3& a, const Point3& b, const Point3& c)
{
    const double abx = b.x - a.x, aby = b.y - a.y, abz = b.z - a.z;
    const double acx = c.x - a.x, acy = c.y - a.y, acz = c.z - a.z;
    const double lab = std::hypot(abx, aby, abz), lac = std::hypot(acx, acy, acz);
    const double bcx = c.x - b.x, bcy = c.y - b.y, bcz = c.z - b.z;
    const double lbc = std::hypot(bcx, bcy, bcz);
    if (lab < 1e-9 || lac < 1e-9 || lbc < 1e-9) return std::nullopt;
    // b below the chord: its height under the chord's point at the same
    // share of the way.
    const double t = lab / (lab + lbc);
    if (b.z >= a.z + t * acz - 1e-9) return std::nullopt;
    const double cx = aby * acz - abz * acy, cy = abz * acx - abx * acz, cz = abx * acy - aby * acx;
    const double area2 = std::hypot(cx, cy, cz);
    if (area2 < 1e-15) return std::nullopt;
    return lab * lbc * lac / (2 * area2);
}

}  // namespace

std::optional<std::string> findUndercut(const std::vector<std::vector<Point3>>& p)
{
    if (p.size() < 2) return std::nullopt;
    // The surface's own side: the sign of the whole grid's area in XY.
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        for (std::size_t j = 0; j + 1 < p[i].size() && j + 1 < p[i + 1].size(); ++j) total += quadNormalZ(p, i, j);
    const double up = total >= 0 ? 1.0 : -1.0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        for (std::size_t j = 0; j + 1 < p[i].size() && j + 1 < p[i + 1].size(); ++j) {
            const Point3 &a = p[i][j], &c = p[i + 1][j + 1];
            const double diag = std::hypot(c.x - a.x, c.y - a.y, c.z - a.z);
            // A quad folded back by more than 1 µm over its diagonal.
            if (up * quadNormalZ(p, i, j) < -1e-3 * diag)
                return fmt::format(
                    TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                         "paths {} and {}, points {} to {} (X {:.3f} Y {:.3f} Z {:.3f}): the surface "
                                         "turns under itself; the verifying simulation is a height "
                                         "field and cannot see undercuts"),
                    i + 1, i + 2, j + 1, j + 2, a.x, a.y, a.z);
        }
    return std::nullopt;
}

ConcaveRadius smallestConcaveRadius(const std::vector<std::vector<Point3>>& p)
{
    ConcaveRadius out{std::numeric_limits<double>::infinity(), {}};
    const auto consider = [&](const Point3& a, const Point3& b, const Point3& c, std::size_t i, std::size_t j) {
        if (const auto r = concaveRadius(a, b, c); r && *r < out.radius) {
            out.radius = *r;
            out.where =
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "path {}, point {} (X {:.3f} Y {:.3f} Z {:.3f})"), i + 1,
                            j + 1, b.x, b.y, b.z);
        }
    };
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 1; j + 1 < p[i].size(); ++j) consider(p[i][j - 1], p[i][j], p[i][j + 1], i, j);
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
        for (std::size_t j = 0; j < p[i].size() && j < p[i - 1].size() && j < p[i + 1].size(); ++j)
            consider(p[i - 1][j], p[i][j], p[i + 1][j], i, j);
    return out;
}

bool boundaryMeetsSurface(const std::vector<std::vector<Point3>>& p, const MeshIndex& boundary)
{
    for (const auto& path : p)
        if (stopAtBoundary(path, boundary).stopped) return true;
    if (p.empty()) return false;
    for (std::size_t j = 0; j < p.front().size(); ++j) {
        std::vector<Point3> across;
        for (const auto& path : p)
            if (j < path.size()) across.push_back(path[j]);
        if (stopAtBoundary(across, boundary).stopped) return true;
    }
    return false;
}

}  // namespace taiwa::surface
