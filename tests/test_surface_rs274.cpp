// A surface finishing program through LinuxCNC's interpreter: the finishing
// paths of a ball end mill (D8, 0.01 mm scallop) over a free-form B-spline
// surface built with OpenCASCADE, linked into one tool path
// (core/occt/surface_paths.h linkPaths), posted for linuxcnc, run by
// `rs274`; every feed move it reads back, sampled along its length, keeps
// (every 0.1 mm) the ball's centre at least r − 1 µm from the exact surface
// (GeomAPI_ProjectPointOnSurf, signed by the upward normal), and the
// rapids stay above the surface. Until the SURFACE module makes such steps
// itself, the step is made here by hand. Negative control: the same tape
// read with the ball 5 µm larger gouges.
#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"
#include "post/post.h"
#include "support/rs274.h"

#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Vec.hxx>

#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::surface;

namespace {

double height(double x, double y) { return 6 * std::sin(x / 15) * std::cos(y / 12) + 0.002 * x * y - 10; }

double signedDistance(const Handle(Geom_BSplineSurface)& s, const Point3& p)
{
    GeomAPI_ProjectPointOnSurf proj(gp_Pnt(p.x, p.y, p.z), s);
    if (proj.NbPoints() == 0) return -1e9;
    double u = 0, v = 0;
    proj.LowerDistanceParameters(u, v);
    gp_Pnt q;
    gp_Vec du, dv;
    s->D1(u, v, q, du, dv);
    gp_Vec n = du.Crossed(dv);
    if (n.Z() < 0) n.Reverse();
    const double d = proj.LowerDistance();
    return gp_Vec(q, gp_Pnt(p.x, p.y, p.z)).Dot(n) >= 0 ? d : -d;
}

}  // namespace

class TestSurfaceRs274 : public QObject {
    Q_OBJECT

private slots:
    void finishingTapeThroughRs274()
    {
        TColgp_Array2OfPnt pts(1, 16, 1, 11);
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 11; ++j) pts.SetValue(i + 1, j + 1, gp_Pnt(4.0 * i, 4.0 * j, height(4.0 * i, 4.0 * j)));
        const Handle(Geom_BSplineSurface) exact = GeomAPI_PointsToBSplineSurface(pts).Surface();
        double u0, u1, v0, v1;
        exact->Bounds(u0, u1, v0, v1);
        std::vector<std::vector<Point3>> paths;
        for (int j = 0; j <= 160; ++j) {
            std::vector<Point3> path;
            for (int i = 0; i <= 240; ++i) {
                const gp_Pnt p = exact->Value(u0 + (u1 - u0) * i / 240, v0 + (v1 - v0) * j / 160);
                path.push_back({p.X(), p.Y(), p.Z()});
            }
            paths.push_back(std::move(path));
        }
        const MeshIndex mesh(meshFromPaths(paths));
        DropCutter drop(mesh, Cutter{8, 4});
        const FinishingPaths f = finishingPaths(drop, Area{20, 12, 40, 24}, 0.25, 0.01);
        QVERIFY(f.paths.size() > 10);

        Tool ball;
        ball.id = 12;  // 8 mm in tests/data/rs274/tools.tbl
        ball.type = ToolType::BallEndMill;
        ball.diameter = 8;
        ball.fluteLength = 20;
        Step step;
        step.kind = StepKind::FloorFinishing;  // the SURFACE module's own kinds are not there yet
        step.tool = ToolChoice{12, "ball for the surface"};
        step.speeds = SpeedsFeeds{6000, 1200, 300};
        step.path = linkPaths(f.paths, 5.0, 1.0);
        PostOptions o;
        o.dialect = "linuxcnc";
        o.programName = "surface";
        const std::string nc = postProcess({step}, {ball}, o).nc;
        const test::Rs274Result r = test::runRs274(nc);
        QVERIFY2(r.ok, qPrintable(r.errors));

        // Every feed move sampled `every` mm along it (0: its ends only);
        // the rapids' ends at least 0.5 mm above the surface.
        int rapidsLow = 0;
        const auto deepest = [&](double radius, double every) {
            double below = 1e9;
            for (const test::CanonMove& m : r.moves) {
                if (m.kind == test::CanonMove::Traverse) {
                    if (signedDistance(exact, {m.end.x, m.end.y, m.end.z + 4}) - radius < 0.5) ++rapidsLow;
                    continue;
                }
                const double len = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y, m.end.z - m.start.z);
                const int n = every > 0 ? std::max(1, static_cast<int>(std::ceil(len / every))) : 1;
                for (int k = every > 0 ? 0 : 1; k <= n; ++k) {
                    const double t = static_cast<double>(k) / n;
                    const Point3 c{m.start.x + t * (m.end.x - m.start.x), m.start.y + t * (m.end.y - m.start.y),
                                   m.start.z + t * (m.end.z - m.start.z) + 4};
                    below = std::min(below, signedDistance(exact, c) - radius);
                }
            }
            return below;
        };
        int feeds = 0;
        for (const test::CanonMove& m : r.moves) feeds += m.kind == test::CanonMove::Feed;
        const double below = deepest(4.0, 0.1);
        qInfo("rs274: %zu moves, %d feeds, deepest %.4f µm into the surface", r.moves.size(), feeds, -below * 1e3);
        QVERIFY(feeds > 500);
        QCOMPARE(rapidsLow, 0);
        QVERIFY2(below >= -1e-3, qPrintable(QString::number(below)));
        QVERIFY(deepest(4.005, 0.0) < -1e-3);  // negative control: a ball 5 µm larger gouges
    }
};

QTEST_GUILESS_MAIN(TestSurfaceRs274)
#include "test_surface_rs274.moc"
