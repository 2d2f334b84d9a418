// STEP import of turned parts (core/occt/step_import.h): a stepped shaft with
// a front chamfer, a relief groove, a fillet and (once) a bore is built here
// with OpenCASCADE from its half-section, revolved, written as STEP and
// imported back to exactly the profile it was built from (ends, kinds, arc
// centres and radii to 1 nm as written); a box, a cylinder with a cross
// hole, a text file and a STEP without a solid are refused saying which.
#include "job/job_file.h"
#include "model/turned_geometry.h"
#include "support/support.h"
#include "occt/step_import.h"
#include "turning/profile_resolve.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <STEPControl_Writer.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::turning;

namespace {

gp_Pnt at(ZR p) { return gp_Pnt(p.r, 0.0, p.z); }  // the half-section in the model's XZ plane, axis Z

// A closed outline of lines and arcs in (z, r), revolved about Z.
TopoDS_Shape revolved(const std::vector<Segment>& loop)
{
    BRepBuilderAPI_MakeWire wire;
    for (const Segment& s : loop) {
        if (!s.arc) {
            wire.Add(BRepBuilderAPI_MakeEdge(at(s.a), at(s.b)).Edge());
        } else {
            const ZR mid = midpoint(s);
            wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(at(s.a), at(mid), at(s.b)).Value()).Edge());
        }
    }
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
    return BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2 * M_PI).Shape();
}

QString writeStep(const TopoDS_Shape& shape, const QTemporaryDir& dir, const QString& name)
{
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    STEPControl_Writer w;
    w.Transfer(shape, STEPControl_AsIs);
    const QString path = dir.filePath(name);
    if (w.Write(path.toStdString().c_str()) != IFSelect_RetDone) qFatal("cannot write %s", qPrintable(path));
    return path;
}

// The outer profile of the shaft, front to back, from `bore` (0: the axis):
// Ø28 front face, chamfer 1 to Ø30, Ø30 to Z-28, relief groove 3 x 0.5 into
// the shoulder's foot, shoulder to Ø40, Ø40 to Z-60, fillet R2 into the
// shoulder to Ø50, Ø50 to Z-90, back face.
std::vector<Segment> outerProfile(double bore)
{
    return {lineSegment({0, bore}, {0, 14}),         lineSegment({0, 14}, {-1, 15}),
            lineSegment({-1, 15}, {-28, 15}),        lineSegment({-28, 15}, {-28, 14.5}),
            lineSegment({-28, 14.5}, {-31, 14.5}),   lineSegment({-31, 14.5}, {-31, 20}),
            lineSegment({-31, 20}, {-60, 20}),       arcSegment({-60, 20}, {-62, 22}, {-60, 22}, false),
            lineSegment({-62, 22}, {-62, 25}),       lineSegment({-62, 25}, {-90, 25}),
            lineSegment({-90, 25}, {-90, bore})};
}

void compareRows(const TurnedProfile& got, const std::vector<Segment>& want)
{
    QCOMPARE(got.rows.size(), want.size());
    QCOMPARE(got.startX, 2 * want.front().a.r);
    QCOMPARE(got.startZ, want.front().a.z);
    for (std::size_t i = 0; i < want.size(); ++i) {
        const ProfileRow& r = got.rows[i];
        const Segment& s = want[i];
        const QString where = QString("row %1").arg(i + 1);
        QVERIFY2(r.id == int(i) + 1, qPrintable(where));
        QVERIFY2(std::abs(r.x - 2 * s.b.r) < 1e-6 && std::abs(r.z - s.b.z) < 1e-6, qPrintable(where + " end"));
        QCOMPARE(r.kind, s.arc ? (s.ccw ? ElementKind::ArcCCW : ElementKind::ArcCW) : ElementKind::Line);
        if (s.arc) {
            QVERIFY2(std::abs(*r.centreX - 2 * s.centre.r) < 1e-6 && std::abs(*r.centreZ - s.centre.z) < 1e-6,
                     qPrintable(where + " centre"));
            QVERIFY2(std::abs(*r.radius - s.radius) < 1e-6, qPrintable(where + " radius"));
        }
    }
}

}  // namespace

class TestStepImport : public QObject {
    Q_OBJECT

private slots:
    void solidShaftComesBackAsItsProfile()
    {
        QTemporaryDir dir;
        std::vector<Segment> loop = outerProfile(0);
        loop.push_back(lineSegment({-90, 0}, {0, 0}));  // the axis
        const auto imported = importStepProfiles(writeStep(revolved(loop), dir, "shaft.step").toStdString());
        QVERIFY2(imported, imported.ok() ? "" : imported.error().c_str());
        QVERIFY(imported->outer && !imported->inner);
        QCOMPARE(imported->outer->side, ProfileSide::Outer);
        compareRows(*imported->outer, outerProfile(0));
        QCOMPARE(imported->axisDirection, (std::array<double, 3>{0, 0, 1}));
        QCOMPARE(imported->frontZ, 0.0);
        // The profile resolves: every edge with its id, the fillet an arc.
        const Resolution resolved = resolveProfile(*imported->outer);
        QVERIFY(resolved.ok());
        QCOMPARE(resolved.profile.edges[7].id, std::string("E8"));
        QVERIFY(resolved.profile.edges[7].geometry.arc);
    }

    void hollowShaftGivesOuterAndBore()
    {
        QTemporaryDir dir;
        std::vector<Segment> loop = outerProfile(5);
        loop.push_back(lineSegment({-90, 5}, {0, 5}));  // the Ø10 bore, back to front
        const auto imported = importStepProfiles(writeStep(revolved(loop), dir, "hollow.stp").toStdString());
        QVERIFY2(imported, imported.ok() ? "" : imported.error().c_str());
        QVERIFY(imported->outer && imported->inner);
        compareRows(*imported->outer, outerProfile(5));
        QCOMPARE(imported->inner->side, ProfileSide::Inner);
        compareRows(*imported->inner, {lineSegment({0, 5}, {-90, 5})});
    }

    // A shaft modelled from Z0 up to Z90 (its front at the top) comes in with
    // its front face at Z0 and the part toward -Z.
    void frontFaceBecomesZeroWhereverItWasModelled()
    {
        QTemporaryDir dir;
        std::vector<Segment> loop;
        for (const Segment& s : outerProfile(0)) {
            Segment t = s;
            for (ZR* p : {&t.a, &t.b, &t.centre}) p->z += 90;
            loop.push_back(t);
        }
        loop.push_back(lineSegment({0, 0}, {90, 0}));
        const auto imported = importStepProfiles(writeStep(revolved(loop), dir, "up.step").toStdString());
        QVERIFY2(imported, imported.ok() ? "" : imported.error().c_str());
        QCOMPARE(imported->frontZ, 90.0);
        compareRows(*imported->outer, outerProfile(0));
    }

    // `taiwa import`: a lathe job that passes input processing, on a bar
    // that holds the part; an existing file is never overwritten, a broken
    // STEP is an input error.
    void importMakesALatheJob()
    {
        QTemporaryDir dir;
        std::vector<Segment> loop = outerProfile(5);
        loop.push_back(lineSegment({-90, 5}, {0, 5}));
        const QString step = writeStep(revolved(loop), dir, "hollow.step");
        const QString job = dir.filePath("hollow.taiwa");
        auto r = test::runTaiwa({"import", step, "--out", job});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out, QString("taiwa: wrote %1: 2 turned profiles on a bar D52 x 116 mm\n").arg(job));
        const JobReadResult read = readJobFile(job.toStdString());
        QVERIFY(read.job);
        QCOMPARE(read.job->machine, std::string("lathe"));
        QCOMPARE(read.job->bar, (std::optional<BarStock>{BarStock{52, 116, 1, 0}}));
        QCOMPARE(read.job->units.size(), std::size_t(2));
        QCOMPARE(read.job->units[1].name, std::string("Bore"));
        // It plans (its Ø10 bore drilled to size); the one word is that the
        // library's blade does not part off its Ø52 bar.
        r = test::runTaiwa({"check", job, "--tools", dir.filePath("tools.sqlite")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.err.trimmed().split('\n').size(), 1);
        QVERIFY2(r.err.contains("warning: no parting off"), qPrintable(r.err));
        // Again onto the same file: refused, the job unchanged.
        const std::string before = test::readFile(job);
        r = test::runTaiwa({"import", step, "--out", job});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QString("taiwa: import: %1 exists; give a new file name (nothing was written)\n").arg(job));
        QCOMPARE(test::readFile(job), before);
        const QString text = dir.filePath("notes.step");
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not STEP\n");
        f.close();
        r = test::runTaiwa({"import", text, "--out", dir.filePath("x.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QString("taiwa: import: %1: not a STEP file, or a broken one\n").arg(text));
        QVERIFY(!QFileInfo::exists(dir.filePath("x.taiwa")));
    }

    void whatIsNotATurnedPartIsRefused()
    {
        QTemporaryDir dir;
        const QString box = writeStep(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), dir, "box.step");
        auto r = importStepProfiles(box.toStdString());
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()),
                 box + ": not a body of revolution: no face of it is turned about an axis (cylinder, cone, torus, sphere)");

        // A Ø40 cylinder with a Ø8 cross hole.
        const TopoDS_Shape shaft = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -50), gp_Dir(0, 0, 1)), 20, 50).Shape();
        const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-30, 0, -25), gp_Dir(1, 0, 0)), 4, 60).Shape();
        const QString crossed = writeStep(BRepAlgoAPI_Cut(shaft, hole).Shape(), dir, "crossed.step");
        r = importStepProfiles(crossed.toStdString());
        QVERIFY(!r);
        QVERIFY2(QString::fromStdString(r.error()).contains(QRegularExpression(
                     ": not a body of revolution: face \\d+ \\(a cylinder\\) is not turned about the axis of face \\d+ \\(a cylinder\\)$")),
                 r.error().c_str());

        const QString text = dir.filePath("notes.step");
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("this is a text file, not ISO 10303-21\n");
        f.close();
        r = importStepProfiles(text.toStdString());
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()), text + ": not a STEP file, or a broken one");

        // A STEP with only a face in it.
        std::vector<Segment> square{lineSegment({0, 0}, {0, 10}), lineSegment({0, 10}, {-10, 10}),
                                    lineSegment({-10, 10}, {-10, 0}), lineSegment({-10, 0}, {0, 0})};
        BRepBuilderAPI_MakeWire wire;
        for (const auto& s : square) wire.Add(BRepBuilderAPI_MakeEdge(at(s.a), at(s.b)).Edge());
        const QString faceOnly = writeStep(BRepBuilderAPI_MakeFace(wire.Wire(), true).Face(), dir, "face.step");
        r = importStepProfiles(faceOnly.toStdString());
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()),
                 faceOnly + ": the file holds no solid: a turned part is imported from its solid model");

        r = importStepProfiles(dir.filePath("missing.step").toStdString());
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()), dir.filePath("missing.step") + ": cannot open it (no such file)");
    }
};

QTEST_APPLESS_MAIN(TestStepImport)
#include "test_step_import.moc"
