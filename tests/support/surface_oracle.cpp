// The SURFACE tapes' moves against the finishing surface, and the unit's
// finishing surface rebuilt from its curves (surface_oracle.h).
#include "support/surface_oracle.h"

#include "occt/surface_mesh.h"

#include <algorithm>
#include <cmath>

namespace taiwa::test {

SurfaceDepth intoSurface(const std::vector<CanonMove>& moves, int step, const std::vector<std::vector<Point3>>& surface,
                         const Tool& tool, double grow)
{
    const surface::MeshIndex index(surface::meshFromPaths(surface));
    const double corner = tool.cornerRadius > 0.0 ? tool.cornerRadius : tool.radius();
    surface::DropCutter drop(index, surface::Cutter{tool.diameter + 2 * grow, corner + grow});
    SurfaceDepth d;
    for (const CanonMove& m : moves) {
        if (m.kind != CanonMove::Feed || m.step != step) continue;
        ++d.feeds;
        const double len = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y, m.end.z - m.start.z);
        const int n = std::max(1, static_cast<int>(std::ceil(len / 0.1)));
        for (int k = 0; k <= n; ++k) {
            const double t = static_cast<double>(k) / n;
            const double x = m.start.x + t * (m.end.x - m.start.x), y = m.start.y + t * (m.end.y - m.start.y),
                         z = m.start.z + t * (m.end.z - m.start.z);
            // The grown tool's nose is `grow` below the tape's.
            if (const auto floor = drop.noseZ(x, y)) d.deepest = std::max(d.deepest, *floor - (z - grow));
        }
    }
    return d;
}

surface::RuledSurface finishingSurface(const SurfaceUnit& u, int m)
{
    const auto curve = [](const SurfaceCurve& c) {
        if (!c.points.empty()) return surface::SpaceCurve{c.points, c.smooth};
        surface::Projection p[2];
        for (int i = 0; i < 2; ++i) {
            const std::string& pl = c.projections[static_cast<std::size_t>(i)].plane;
            p[i].plane = pl == "XY" ? surface::ProjectionPlane::XY
                                    : pl == "YZ" ? surface::ProjectionPlane::YZ : surface::ProjectionPlane::ZX;
            p[i].points = c.projections[static_cast<std::size_t>(i)].points;
            p[i].smooth = c.smooth;
        }
        return *surface::spaceCurveFromProjections(p[0], p[1], 0.5);
    };
    return surface::roughAndFinishSurfaces(curve(u.curve1), curve(u.curve2), u.n, m)->finishing;
}

}  // namespace taiwa::test
