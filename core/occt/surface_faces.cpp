// A STEP face set sampled into the point-sequence paths of the SURFACE
// unit (surface_step.h sampleStepFaces): the faces tessellated once, a
// point dropped on them at every grid point, the holes and undercuts
// refused, the paths' own error measured.
#include "occt/surface_step.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::surface {

namespace {

constexpr double kDeflection = 1e-4;  // mm: the faces' triangles (a tenth of the micrometre the surface is held to)
constexpr double kUnder = 1e-3;       // mm: a triangle this far under the top is hidden by another
constexpr std::size_t kMaxPoints = 1'000'000;

std::string at(double x, double y) { return fmt::format("X {:.3f} Y {:.3f}", x, y); }

}  // namespace

Result<SampledFaces> sampleStepFaces(const std::string& file, double spacing)
{
    if (!(spacing > 0.0) || !std::isfinite(spacing))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the spacing {} must be above 0"), spacing)};
    auto mesh = importStepFaces(file, kDeflection);
    if (!mesh) return mesh.failure();
    const MeshIndex index(std::move(*mesh));
    DropCutter drop(index, Cutter{});
    // Undercuts: a triangle whose middle lies below the top seen from above
    // (a face under another, or a face turned over).
    const TriangleMesh& m = index.mesh();
    for (const auto& t : m.triangles) {
        const Point3 a = m.vertices[static_cast<std::size_t>(t[0])], b = m.vertices[static_cast<std::size_t>(t[1])],
                     c = m.vertices[static_cast<std::size_t>(t[2])];
        const double area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        if (area < 1e-12) continue;  // standing on edge: a vertical wall, not a face under another
        const double x = (a.x + b.x + c.x) / 3, y = (a.y + b.y + c.y) / 3, z = (a.z + b.z + c.z) / 3;
        if (const auto top = drop.surfaceZ(x, y); top && *top > z + kUnder)
            return Failure{fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: a face lies under another at {} (Z {:.3f} under Z {:.3f}); "
                                                   "a surface machined from above has none (the verifying "
                                                   "simulation is a height field)"),
                file, at(x, y), z, *top)};
    }
    const double x0 = index.minX(), x1 = index.maxX(), y0 = index.minY(), y1 = index.maxY();
    const int nx = std::max(1, static_cast<int>(std::ceil((x1 - x0) / spacing - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil((y1 - y0) / spacing - 1e-9)));
    if (static_cast<double>(nx + 1) * (ny + 1) > kMaxPoints)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                        "{}: {} × {} points at a spacing of {} mm; a surface holds at "
                                                        "most {} (give a larger spacing)"),
                                   file, nx + 1, ny + 1, spacing, kMaxPoints)};
    // The grid spans the rectangle exactly: its steps are at most `spacing`.
    const double dx = (x1 - x0) / nx, dy = (y1 - y0) / ny;
    SampledFaces out;
    for (int j = 0; j <= ny; ++j) {
        const double y = j == ny ? y1 : y0 + j * dy;
        std::vector<Point3> path;
        for (int i = 0; i <= nx; ++i) {
            const double x = i == nx ? x1 : x0 + i * dx;
            // On the rectangle's edge the faces' own edge: look a hair inside.
            const double xi = std::clamp(x, x0 + 1e-7, x1 - 1e-7), yi = std::clamp(y, y0 + 1e-7, y1 - 1e-7);
            const auto z = drop.surfaceZ(xi, yi);
            if (!z)
                return Failure{fmt::format(
                    TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: no face lies under {}: the faces seen from above leave a "
                                                       "hole or are not a rectangle; the surface must cover "
                                                       "its X-Y rectangle"),
                    file, at(x, y))};
            path.push_back({x, y, *z});
        }
        out.paths.push_back(std::move(path));
    }
    // The paths' own error: the faces at each cell's middle against the
    // mean of its four corners (what the cell's two triangles give there,
    // near enough whichever diagonal splits it).
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const auto J = static_cast<std::size_t>(j), I = static_cast<std::size_t>(i);
            const auto& p = out.paths;
            const Point3 a = p[J][I], b = p[J][I + 1], c = p[J + 1][I], d = p[J + 1][I + 1];
            const double x = (a.x + b.x + c.x + d.x) / 4, y = (a.y + b.y + c.y + d.y) / 4;
            if (const auto z = drop.surfaceZ(x, y))
                out.deviation = std::max(out.deviation, std::abs(*z - (a.z + b.z + c.z + d.z) / 4));
        }
    return out;
}

}  // namespace taiwa::surface
