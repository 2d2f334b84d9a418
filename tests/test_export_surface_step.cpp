// The finished surface of a SURFACE unit written to STEP by `taiwa export`
// (docs/command-line.md, docs/surfaces.md): the shipped sample
// resources/samples/surface-cover.taiwa exports STEM.u1.surface.step beside
// its tape; read back with OpenCASCADE's STEPControl_Reader, its one face is
// the unit's finishing surface as the unit defines it (the bilinear patches
// between the rulings of its two curves divided into M pieces, rebuilt here
// from the curves by the core): every sampled point of the unit's surface
// lies within 1 µm of the face, and every sampled point of the face within
// 1 µm (in Z) of the unit's surface. Negative controls: the face moved 2 µm
// is caught, and so is the smooth B-spline through the same points
// (exportSurfaceStep's other fit), which bulges between them.
#include "modules/surface/surface.h"
#include "occt/surface_mesh.h"
#include "occt/surface_step.h"
#include "support/support.h"
#include "support/surface_oracle.h"

#include "job/job_file.h"
#include "modules/registry.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Surface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace taiwa;
using namespace taiwa::test;

namespace {

const QString kSample = QStringLiteral("resources/samples/surface-cover.taiwa");

// The STEP file's faces' surfaces (each face of it on its whole surface).
std::vector<Handle(Geom_Surface)> facesOf(const QString& file)
{
    STEPControl_Reader reader;
    if (reader.ReadFile(file.toStdString().c_str()) != IFSelect_RetDone) return {};
    reader.TransferRoots();
    std::vector<Handle(Geom_Surface)> faces;
    for (TopExp_Explorer ex(reader.OneShape(), TopAbs_FACE); ex.More(); ex.Next())
        faces.push_back(BRep_Tool::Surface(TopoDS::Face(ex.Current())));
    return faces;
}

struct Misses {
    double unitToFace = 0.0;  // the farthest a point of the unit's surface is from the face
    double faceToUnit = 0.0;  // the farthest a point of the face is (in Z) from the unit's surface
};

// Both ways at seeded random points: the unit's surface at (u, v) projected
// on the face; the face at random parameters against the unit's surface
// under it (its triangles, within 0.2 µm of its bilinear patches).
Misses compare(const Handle(Geom_Surface)& face, const surface::RuledSurface& unit, const std::vector<std::vector<Point3>>& paths)
{
    std::mt19937 rng(36);
    std::uniform_real_distribution<double> unitU(0.0, unit.pieces()), unitV(0.0, 1.0), unit01(0.0, 1.0);
    Misses m;
    GeomAPI_ProjectPointOnSurf project;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    face->Bounds(u0, u1, v0, v1);
    project.Init(face, u0, u1, v0, v1);
    for (int i = 0; i < 400; ++i) {
        const Point3 p = unit.point(unitU(rng), unitV(rng));
        project.Perform(gp_Pnt(p.x, p.y, p.z));
        m.unitToFace = std::max(m.unitToFace, project.NbPoints() > 0 ? project.LowerDistance() : 1e9);
    }
    const surface::MeshIndex index(surface::meshFromPaths(paths));
    surface::DropCutter drop(index, surface::Cutter{});
    for (int i = 0; i < 400; ++i) {
        const gp_Pnt q = face->Value(u0 + (u1 - u0) * unit01(rng), v0 + (v1 - v0) * unit01(rng));
        const auto z = drop.surfaceZ(q.X(), q.Y());
        m.faceToUnit = std::max(m.faceToUnit, z ? std::abs(q.Z() - *z) : 1e9);
    }
    return m;
}

}  // namespace

class TestExportSurfaceStep : public QObject {
    Q_OBJECT

    surface::RuledSurface unit_;
    std::vector<std::vector<Point3>> paths_;  // the finishing step's surface, as the module gives it

private slots:
    void initTestCase()
    {
        const auto read = readJobFile(sourcePath(kSample).toStdString());
        QVERIFY(read.job);
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok());
        const SurfaceUnit& u = plan.mmJob.units.front().module.as<SurfaceUnit>();
        QVERIFY(u.m);
        unit_ = finishingSurface(u, *u.m);
        for (const Step& s : plan.steps)
            if (auto p = findModuleKind(s.module)->machinedSurface(s); !p.empty()) paths_ = p;
        QVERIFY(!paths_.empty());
    }

    void exportWritesTheUnitsFinishedSurface()
    {
        QTemporaryDir out;
        const auto r = runTaiwa({"export", sourcePath(kSample), "--out", out.path(), "--resolution", "0.25", "--no-pictures"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString file = QDir(out.path()).filePath("surface-cover.u1.surface.step");
        QVERIFY2(QFileInfo::exists(file), qPrintable(QDir(out.path()).entryList().join(", ")));
        QVERIFY(readFile(file).starts_with("ISO-10303-21;"));
        const auto faces = facesOf(file);
        QCOMPARE(faces.size(), std::size_t(1));
        const Misses m = compare(faces.front(), unit_, paths_);
        qInfo("the unit's surface is at most %.2e mm from the face, the face %.2e mm (in Z) from the unit's surface",
              m.unitToFace, m.faceToUnit);
        QVERIFY2(m.unitToFace <= 1e-3, qPrintable(QString::number(m.unitToFace)));
        QVERIFY2(m.faceToUnit <= 1e-3, qPrintable(QString::number(m.faceToUnit)));

        // Negative controls: the face 2 µm higher, and the smooth fit through
        // the same points.
        const Handle(Geom_Surface) moved = Handle(Geom_Surface)::DownCast(faces.front()->Translated(gp_Vec(0, 0, 0.002)));
        const Misses off = compare(moved, unit_, paths_);
        qInfo("moved 2 µm: %.2e mm and %.2e mm", off.unitToFace, off.faceToUnit);
        QVERIFY(off.unitToFace > 1e-3 && off.faceToUnit > 1e-3);
        const QString smoothFile = QDir(out.path()).filePath("smooth.step");
        QVERIFY(surface::exportSurfaceStep(paths_, smoothFile.toStdString(), surface::SurfaceFit::Smooth));
        const auto smooth = facesOf(smoothFile);
        QCOMPARE(smooth.size(), std::size_t(1));
        const Misses bulge = compare(smooth.front(), unit_, paths_);
        qInfo("the smooth fit: %.2e mm and %.2e mm", bulge.unitToFace, bulge.faceToUnit);
        QVERIFY(std::max(bulge.unitToFace, bulge.faceToUnit) > 1e-3);
    }

    void aJobWithoutASurfaceWritesNone()
    {
        QTemporaryDir out;
        const auto r = runTaiwa({"export", sourcePath("resources/samples/face-top.taiwa"), "--out", out.path(),
                                 "--resolution", "0.25", "--no-pictures"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QDir(out.path()).entryList({"*.step"}, QDir::Files).isEmpty());
    }
};

QTEST_APPLESS_MAIN(TestExportSurfaceStep)
#include "test_export_surface_step.moc"
