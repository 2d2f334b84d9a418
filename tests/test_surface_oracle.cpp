// The oracle of the surface paths (core/occt/surface_mesh.h,
// surface_paths.h) against OpenCASCADE's exact surface: a free-form
// B-spline surface is built here with OpenCASCADE, sampled into
// point-sequence paths 0.25 mm apart and tessellated by the program; then,
// with GeomAPI_ProjectPointOnSurf (the distance from a point to the exact
// surface), no finishing or roughing move of a ball end mill goes into the
// surface by more than 1 µm (its centre, at the points and along the moves
// between them, at least r from the surface and on its upper side), the
// finishing nose points touch it (the centre at most r + 1 µm from it),
// roughing keeps its allowance, and a bull-nose's ring stays r off it.
// The oracle lives here, not in the product. A negative control: the same
// check catches a ball lowered by 5 µm. A trimmed face (a square plate with
// a round hole, written to STEP here) is read back as triangles that stay
// off the hole and cover the rest but for a band one grid cell wide.
#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"
#include "occt/surface_step.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Vec.hxx>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::surface;

namespace {

double height(double x, double y) { return 6 * std::sin(x / 15) * std::cos(y / 12) + 0.002 * x * y; }

// The signed distance of p from the exact surface: positive above it (on
// the side its upward normal points to).
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

class TestSurfaceOracle : public QObject {
    Q_OBJECT

    Handle(Geom_BSplineSurface) exact_;
    std::unique_ptr<MeshIndex> mesh_;

    // The worst (smallest) distance of the ball's centre (r above the nose)
    // from the surface less `clearance` (r, or r + an allowance), at every
    // `every`-th path's points and at the quarter points of their moves;
    // the largest at the points themselves.
    struct Worst {
        double below = 1e9;  // min(distance − r): negative is a gouge
        double above = -1e9; // max(distance − r) at the points
        int checked = 0;
    };
    Worst check(const std::vector<std::vector<Point3>>& paths, double r, double clearance, std::size_t every,
                double lowered = 0.0)
    {
        Worst w;
        for (std::size_t i = 0; i < paths.size(); i += every) {
            const auto& path = paths[i];
            for (std::size_t j = 0; j < path.size(); ++j) {
                const Point3 c{path[j].x, path[j].y, path[j].z + r - lowered};
                const double d = signedDistance(exact_, c) - clearance;
                w.below = std::min(w.below, d);
                w.above = std::max(w.above, d);
                ++w.checked;
                if (j + 1 < path.size())
                    for (double t : {0.25, 0.5, 0.75}) {
                        const Point3& q = path[j + 1];
                        const Point3 m{c.x + t * (q.x - path[j].x), c.y + t * (q.y - path[j].y),
                                       c.z + t * (q.z - path[j].z)};
                        w.below = std::min(w.below, signedDistance(exact_, m) - clearance);
                        ++w.checked;
                    }
            }
        }
        return w;
    }

private slots:
    void initTestCase()
    {
        // The exact surface: a B-spline through 16 × 11 points 4 mm apart.
        TColgp_Array2OfPnt pts(1, 16, 1, 11);
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 11; ++j) pts.SetValue(i + 1, j + 1, gp_Pnt(4.0 * i, 4.0 * j, height(4.0 * i, 4.0 * j)));
        exact_ = GeomAPI_PointsToBSplineSurface(pts).Surface();
        QVERIFY(!exact_.IsNull());
        // Its paths: the surface at 241 × 161 parameters (about 0.25 mm).
        double u0, u1, v0, v1;
        exact_->Bounds(u0, u1, v0, v1);
        std::vector<std::vector<Point3>> paths;
        for (int j = 0; j <= 160; ++j) {
            std::vector<Point3> path;
            for (int i = 0; i <= 240; ++i) {
                const gp_Pnt p = exact_->Value(u0 + (u1 - u0) * i / 240, v0 + (v1 - v0) * j / 160);
                path.push_back({p.X(), p.Y(), p.Z()});
            }
            paths.push_back(std::move(path));
        }
        mesh_ = std::make_unique<MeshIndex>(meshFromPaths(paths));
    }

    void finishingNeitherGougesNorHovers()
    {
        DropCutter drop(*mesh_, Cutter{8, 4});
        // At 0.25 mm a move's chord sags about 0.2 µm into the offset
        // surface here, the mesh's chords as much: together within 1 µm (at
        // 0.5 mm the moves reach 0.9 µm: the step follows the tolerance).
        const FinishingPaths f = finishingPaths(drop, Area{12, 10, 48, 30}, 0.25, 0.005);
        QVERIFY(f.paths.size() > 20);
        const Worst w = check(f.paths, 4, 4, 9);
        qInfo("finishing: %d points and move points checked, deepest %.4f µm, highest %.4f µm", w.checked,
              -w.below * 1e3, w.above * 1e3);
        QVERIFY2(w.below >= -1e-3, qPrintable(QString::number(w.below)));
        QVERIFY2(w.above <= 1e-3, qPrintable(QString::number(w.above)));
        // Negative control: the same paths 5 µm lower gouge.
        QVERIFY(check(f.paths, 4, 4, 9, 0.005).below < -1e-3);
    }

    void roughingKeepsItsAllowance()
    {
        ZLevelOptions o;
        o.top = 12;
        o.depth = 3;
        o.stepOver = 5;
        o.step = 0.35;  // at 0.5 the moves' chords sag 0.9 µm into the allowance
        o.allowance = 0.4;
        const auto passes = zLevelRoughing(*mesh_, Cutter{8, 4}, Area{12, 10, 48, 30}, o);
        std::vector<std::vector<Point3>> paths;
        for (const auto& p : passes) paths.push_back(p.points);
        QVERIFY(paths.size() > 10);
        const Worst w = check(paths, 4, 4 + 0.4, 2);
        qInfo("roughing: %d checked, the nearest %.4f µm inside the allowance", w.checked, -w.below * 1e3);
        QVERIFY2(w.below >= -1e-3, qPrintable(QString::number(w.below)));
        QVERIFY(w.below < 1e-3);  // it rides on the allowance somewhere
    }

    void bullNoseRingStaysOff()
    {
        // A bull-nose D10 r2: at each nose point, 36 points of its ring (the
        // corner's centre circle, 3 mm from the axis, r above the nose) are
        // at least r from the surface.
        DropCutter drop(*mesh_, Cutter{10, 2});
        double worst = 1e9;
        int n = 0;
        for (const auto& path : dropLine(drop, 20, 14, 46, 1.0))
            for (const Point3& p : path)
                for (int k = 0; k < 36; ++k) {
                    const double a = k * std::numbers::pi / 18;
                    const Point3 ring{p.x + 3 * std::cos(a), p.y + 3 * std::sin(a), p.z + 2};
                    worst = std::min(worst, signedDistance(exact_, ring) - 2);
                    ++n;
                }
        qInfo("bull-nose: %d ring points, nearest %.4f µm inside", n, -worst * 1e3);
        QVERIFY(n > 1000);
        QVERIFY2(worst >= -1e-3, qPrintable(QString::number(worst)));
        QVERIFY(worst < 0.02);  // and touches somewhere (to the ring samples' 10°)
    }

    void trimmedFaceImport()
    {
        // The plane z = 2 over [0, 40]², a hole of radius 8 at (20, 20).
        const gp_Pnt c[4] = {{0, 0, 2}, {40, 0, 2}, {40, 40, 2}, {0, 40, 2}};
        BRepBuilderAPI_MakeWire outer;
        for (int i = 0; i < 4; ++i) outer.Add(BRepBuilderAPI_MakeEdge(c[i], c[(i + 1) % 4]));
        const gp_Circ circle(gp_Ax2(gp_Pnt(20, 20, 2), gp_Dir(0, 0, 1)), 8);
        TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle));
        hole.Reverse();
        BRepBuilderAPI_MakeFace face(outer.Wire());
        face.Add(hole);
        QVERIFY(face.IsDone());
        QTemporaryDir dir;
        const std::string file = dir.filePath("plate.step").toStdString();
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        STEPControl_Writer writer;
        QCOMPARE(writer.Transfer(face.Face(), STEPControl_AsIs), IFSelect_RetDone);
        QCOMPARE(writer.Write(file.c_str()), IFSelect_RetDone);

        const auto mesh = importStepFaces(file, 1e-3);
        QVERIFY2(mesh.ok(), mesh.ok() ? "" : mesh.error().c_str());
        double area = 0.0;
        for (const auto& t : mesh->triangles) {
            const Point3 &a = mesh->vertices[static_cast<std::size_t>(t[0])],
                         &b = mesh->vertices[static_cast<std::size_t>(t[1])],
                         &d = mesh->vertices[static_cast<std::size_t>(t[2])];
            QVERIFY(std::abs(a.z - 2) < 1e-9);
            for (const Point3* p : {&a, &b, &d}) QVERIFY(std::hypot(p->x - 20, p->y - 20) >= 8 - 1e-6);
            area += 0.5 * std::abs((b.x - a.x) * (d.y - a.y) - (d.x - a.x) * (b.y - a.y));
        }
        const double full = 1600 - std::numbers::pi * 64;
        qInfo("trimmed face: %zu triangles, %.1f of %.1f mm² covered", mesh->triangles.size(), area, full);
        QVERIFY(area <= full + 1e-6);
        QVERIFY(area > 0.9 * full);
        // The drop-cutter on it: a ball rests on the plate, not in the hole.
        const MeshIndex index(std::move(*mesh));
        DropCutter drop(index, Cutter{4, 2});
        QVERIFY(std::abs(*drop.noseZ(5, 5) - 2) < 1e-9);
        QVERIFY(!drop.surfaceZ(20, 20));
    }
};

QTEST_GUILESS_MAIN(TestSurfaceOracle)
#include "test_surface_oracle.moc"
