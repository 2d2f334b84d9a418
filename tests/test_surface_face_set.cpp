// A STEP face set as the SURFACE unit's surface (issue 36 item 5;
// docs/surfaces.md "A STEP face set"): `taiwa import STEP --surface MM`
// samples the faces into the unit's point paths (occt/surface_step.h
// sampleStepFaces) and writes a milling job. The faces here are made with
// OpenCASCADE itself: a cylinder of R120 along Y, convex from above, cut to
// a 60 × 50 mm rectangle seen from above. The oracle is the cylinder's own
// formula: every sampled point lies on it within 1 µm; the job plans, its
// linuxcnc tape passes rs274, and no feed move of the finishing it reads
// back takes the ball into the cylinder by more than 1 µm (a ball 20 µm
// larger about the same centre does: negative control). Refused, naming the point: faces that
// leave a hole, and a face under another (an undercut).
// Runs rs274 and the taiwa executable: under the rs274 lock.
#include "job/step_job.h"
#include "modules/surface/surface.h"
#include "support/rs274.h"
#include "support/support.h"

#include "job/job_file.h"
#include "occt/surface_step.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <BRep_Builder.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax3.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::test;

namespace {

constexpr double kR = 120.0, kXc = 50.0, kZc = -100.0;  // the cylinder's axis: along Y through (50, y, -100)
const double kAlpha = std::asin(30.0 / kR);               // half the X span (60 mm) as seen from the axis

// The cylinder's top band: x in [20, 80], y in [10, 60], z = −100 + √(R² − (x − 50)²).
TopoDS_Face cylinderFace(double v0 = 10.0, double v1 = 60.0)
{
    // Axis along +Y, X-direction +X: P(u, v) = C + R(cos u·X + sin u·(Y × X)) + v·Y, Y × X = −Z.
    const gp_Ax3 axes(gp_Pnt(kXc, 0, kZc), gp_Dir(0, 1, 0), gp_Dir(1, 0, 0));
    const double top = -std::numbers::pi / 2;  // sin u = −1: the point straight above the axis
    return BRepBuilderAPI_MakeFace(gp_Cylinder(axes, kR), top - kAlpha, top + kAlpha, v0, v1).Face();
}

std::string writeStep(const TopoDS_Shape& shape, const QTemporaryDir& dir, const char* name)
{
    const std::string file = dir.filePath(name).toStdString();
    STEPControl_Writer w;
    w.Transfer(shape, STEPControl_AsIs);
    if (w.Write(file.c_str()) != IFSelect_RetDone) qFatal("cannot write %s", file.c_str());
    return file;
}

TopoDS_Shape both(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    builder.Add(c, a);
    builder.Add(c, b);
    return c;
}

// The cylinder after the import moved it down to put its top at Z 0.
double cylinderZ(double x, double lowered) { return kZc + std::sqrt(kR * kR - (x - kXc) * (x - kXc)) - lowered; }

}  // namespace

class TestSurfaceFaceSet : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        // The STEP writer's chatter off the test's output.
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    }

    void aFaceSetIsTheUnitsSurface()
    {
        QTemporaryDir dir;
        const std::string step = writeStep(cylinderFace(), dir, "cylinder.step");
        const auto imported = surfaceJobFromStep(step, "aluminium-6061", 0.5);
        QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error().c_str());
        const Job& job = imported->job;
        QCOMPARE(imported->lowered, kZc + kR);  // its top was at Z 20
        // The block is the faces' rectangle, its top their highest point.
        QVERIFY(std::abs(job.stock.x - 20.0) < 1e-6 && std::abs(job.stock.width - 60.0) < 1e-6);
        QVERIFY(std::abs(job.stock.y - 10.0) < 1e-6 && std::abs(job.stock.length - 50.0) < 1e-6);
        QCOMPARE(job.stock.height, std::ceil(kR - std::sqrt(kR * kR - 900.0) + 5.0));
        const SurfaceUnit& u = job.units.at(0).module.as<SurfaceUnit>();
        QCOMPARE(u.surface.size(), std::size_t(101));     // 50 mm at 0.5
        QCOMPARE(u.surface[0].size(), std::size_t(121));  // 60 mm at 0.5
        double worst = 0.0;
        for (const auto& path : u.surface)
            for (const Point3& p : path) worst = std::max(worst, std::abs(p.z - cylinderZ(p.x, imported->lowered)));
        qInfo("sampled points off the cylinder: %.2e mm at most; the paths' own deviation %.2e mm", worst, imported->deviation);
        QVERIFY(worst <= 1e-3);
        QVERIFY(imported->deviation < 1e-3);  // (0.5 mm)² / (8 R) = 0.26 µm

        // Through the file as written, planned, posted, read back by rs274.
        const JobReadResult again = readJob(writeJob(job));
        QVERIFY(again.job);
        QVERIFY(again.job->units[0].module.as<SurfaceUnit>().surface == u.surface);
        const std::vector<Tool> library = defaultToolLibrary();
        const Plan p = planJob(*again.job, TechnologyTable::builtIn(), library);
        QVERIFY2(p.ok(), p.diagnostics.empty() ? "" : p.diagnostics.front().message.c_str());
        QCOMPARE(p.steps.size(), std::size_t(2));
        const Rs274Result r = runRs274(postProcess(p.steps, library, postOptions(p, "linuxcnc")).nc);
        QVERIFY2(r.ok, qPrintable(r.errors));
        const double ball = p.tool(p.steps[1].tool->toolId)->radius();
        // How far the ball, `grow` larger about its centre, goes into the
        // cylinder along the finishing's feed moves (each sampled every 0.1 mm).
        const auto deepest = [&](double grow) {
            double into = -1e9;
            int feeds = 0;
            for (const CanonMove& m : r.moves) {
                if (m.step != 2 || m.kind != CanonMove::Feed) continue;
                ++feeds;
                const double len = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y, m.end.z - m.start.z);
                const int n = std::max(1, static_cast<int>(std::ceil(len / 0.1)));
                for (int k = 0; k <= n; ++k) {
                    const double t = static_cast<double>(k) / n;
                    const double x = m.start.x + t * (m.end.x - m.start.x), z = m.start.z + t * (m.end.z - m.start.z);
                    // The ball's centre (the nose + its radius) against the
                    // cylinder grown by the ball (and by `grow`).
                    const double d = std::hypot(x - kXc, z + ball - (kZc - imported->lowered));
                    into = std::max(into, kR + ball + grow - d);
                }
            }
            return std::pair{into, feeds};
        };
        const auto [into, feeds] = deepest(0.0);
        qInfo("%d finishing feed moves, the ball %.4f mm into the cylinder at the deepest", feeds, into);
        QVERIFY(feeds > 100);
        QVERIFY2(into <= 1e-3, qPrintable(QString::number(into)));
        QVERIFY(deepest(0.02).first > 0.01);  // a ball 20 µm larger gouges
    }

    void theCommandWritesTheJob()
    {
        QTemporaryDir dir;
        const std::string step = writeStep(cylinderFace(), dir, "cover.step");
        const QString out = dir.filePath("cover.taiwa");
        const RunResult r = runTaiwa({"import", QString::fromStdString(step), "--surface", "1", "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("a SURFACE unit on a block 60 x 50 x 9 mm") && r.out.contains("moved down 20 mm"), qPrintable(r.out));
        const RunResult check = runTaiwa({"check", out});
        QVERIFY2(check.exitCode == 0, qPrintable(check.err + check.out));
        const RunResult bad = runTaiwa({"import", QString::fromStdString(step), "--surface", "0", "--out", dir.filePath("x.taiwa")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--surface wants the paths' spacing in mm from 0.05 to 10"), qPrintable(bad.err));
    }

    // A hole between two strips, and a face under another: refused at a point.
    void holesAndUndercutsAreRefused()
    {
        QTemporaryDir dir;
        const std::string gap = writeStep(both(cylinderFace(10, 30), cylinderFace(40, 60)), dir, "gap.step");
        const auto holed = surface::sampleStepFaces(gap, 0.5);
        QVERIFY(!holed.ok());
        QVERIFY2(holed.error().find("no face lies under X") != std::string::npos &&
                     holed.error().find("gap.step") != std::string::npos,
                 holed.error().c_str());
        // A flat face 5 mm under the cylinder's band.
        const TopoDS_Face under =
            BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 10), gp_Dir(0, 0, 1)), 25, 75, 15, 55).Face();
        const std::string hidden = writeStep(both(cylinderFace(), under), dir, "under.step");
        const auto undercut = surface::sampleStepFaces(hidden, 0.5);
        QVERIFY(!undercut.ok());
        QVERIFY2(undercut.error().find("a face lies under another at X") != std::string::npos, undercut.error().c_str());
        // Control: the cylinder alone is taken.
        QVERIFY(surface::sampleStepFaces(writeStep(cylinderFace(), dir, "alone.step"), 0.5).ok());
    }
};

QTEST_GUILESS_MAIN(TestSurfaceFaceSet)
#include "test_surface_face_set.moc"
