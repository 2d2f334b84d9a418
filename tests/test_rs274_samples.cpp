// Every sample exported as a `linuxcnc` tape through the real command line
// must pass LinuxCNC's own interpreter (rs274) with no error, and its
// canonical moves are the geometry judged here, step by step:
// - no feed position of the tool cuts beyond the finished pocket (1 µm),
// - no rapid below the top of the stock except into air already cut,
// - roughing reaches exactly -(T - beta2) and leaves exactly alpha2 on the walls,
// - the finishing steps reach the floor at exactly -T,
// - the inch tape describes the same moves as the mm tape;
// a SURFACE sample's moves against its finishing surface instead (no rapid
// below the stock top, finishing off the surface, roughing the allowance
// off it: support/surface_oracle.h).
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "modules/surface/surface.h"
#include "support/pocket_geometry.h"
#include "support/rs274.h"
#include "support/support.h"
#include "support/surface_oracle.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

using namespace taiwa;
using namespace taiwa::test;

namespace {

constexpr double kTol = 1e-3;  // 1 µm in mm

struct Exported {
    std::string nc;
    Plan plan;
};

Exported exportSample(const QString& job, const QString& units)
{
    QTemporaryDir out;
    // The tape is what is judged here: the verification on a coarse grid and
    // no step pictures (both have tests of their own, and at the default
    // 0.05 mm the contour samples take seconds each).
    const auto r = runTaiwa({"export", job, "--out", out.path(), "--dialect", "linuxcnc", "--units", units, "--resolution",
                             "0.25", "--no-pictures"});
    if (r.exitCode != 0) qFatal("export failed: %s", qPrintable(r.err));
    Exported e;
    e.nc = readFile(QDir(out.path()).filePath(QFileInfo(job).completeBaseName() + ".nc"));
    const auto read = readJobFile(job.toStdString());
    e.plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
    return e;
}

// Every position a move passes through that must be checked: line end points
// suffice (the set of safe tip positions is convex), arcs are sampled.
std::vector<Point3> checkPoints(const CanonMove& m)
{
    if (m.kind == CanonMove::Arc) return sampleArc(m, 0.05);
    return {m.start, m.end};
}

QString where(const CanonMove& m, const Step& s)
{
    return QString("step %1 (unit %2 %3, T%4) at X%5 Y%6 Z%7")
        .arg(m.step).arg(s.unit + 1).arg(QString::fromStdString(s.label())).arg(m.tool)
        .arg(m.end.x, 0, 'f', 4).arg(m.end.y, 0, 'f', 4).arg(m.end.z, 0, 'f', 4);
}

// A SURFACE sample (docs/surfaces.md): its pockets are no walls and floor
// but the unit's finishing surface. Every step cuts with its own tool;
// finishing keeps the ball off the surface (1 µm, the tape's rounding in
// it), roughing keeps it the allowance off; no rapid goes below the stock
// top other than down to the clearance over it.
void judgeSurfaceTape(const Plan& plan, const Rs274Result& r)
{
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& s = plan.steps[i];
        const SurfacePaths& sp = s.payload.as<SurfacePaths>();
        // Roughing carries the finishing surface too, and leaves the allowance on it.
        const bool roughing = !sp.finished.empty();
        const double grow = roughing ? sp.allowance : 0.0;
        const SurfaceDepth d = intoSurface(r.moves, static_cast<int>(i) + 1, roughing ? sp.finished : sp.surface,
                                           *plan.tool(s.tool->toolId), grow);
        qInfo("step %zu %s: %d feed moves, deepest %.4f mm into the surface (grown by %.2f)", i + 1, s.label().c_str(),
              d.feeds, d.deepest, grow);
        QVERIFY2(d.feeds > 0, qPrintable(QString::fromStdString(s.label()) + " cuts nothing"));
        QVERIFY2(d.deepest <= kTol, qPrintable(QString::fromStdString(s.label()) + QString(" goes %1 mm into the surface").arg(d.deepest)));
    }
    for (const CanonMove& m : r.moves) {
        if (m.step == 0) continue;
        if (m.kind != CanonMove::Traverse)  // every cut with the step's own tool
            QCOMPARE(m.tool, plan.steps[static_cast<std::size_t>(m.step - 1)].tool->toolId);
        else
            QVERIFY2(m.end.z >= -kTol, qPrintable(QString("a rapid below the stock top at Z%1, step %2").arg(m.end.z).arg(m.step)));
    }
}

}  // namespace

class TestRs274Samples : public QObject {
    Q_OBJECT
private slots:
    void oracleKnowsAGougeWhenItSeesOne()
    {
        // The judge itself: a 10 mm flat end mill in a 100 x 60 pocket, r1 8, T 10.
        M4Pocket p;
        p.corners = {{{0, 0}, {100, 0}, {100, 60}, {0, 60}}};
        p.cornerRadius = 8;
        p.depth = 10;
        Tool t;
        t.diameter = 10;
        QVERIFY(gouge(p, t, {5, 30, -5}) <= kTol);             // touching the wall
        QVERIFY(std::abs(gouge(p, t, {5, 30, -5})) < 1e-9);
        QVERIFY(gouge(p, t, {4.99, 30, -5}) > 0.009);          // 10 µm into it
        QVERIFY(gouge(p, t, {50, 30, -10.002}) > 0.0015);      // below the floor
        QVERIFY(gouge(p, t, {3, 3, -1}) > 0);                   // rounded corner
        QVERIFY(gouge(p, t, {-50, -50, 1}) < 0);                // above the stock: air
        p.taper = 5;  // the wall leans in: at depth 10 it is 0.875 mm further in
        QVERIFY(gouge(p, t, {5.5, 30, -10}) > 0.3);
        t.type = ToolType::TaperEndMill;
        t.taperAngle = 5;
        t.diameter = 4;
        QVERIFY(std::abs(gouge(p, t, {2 + 10 * std::tan(5 * M_PI / 180), 30, -10})) < 1e-6);
    }

    void linuxcncTapesPassRs274AndStayInside_data()
    {
        QTest::addColumn<QString>("job");
        for (const auto& f : QDir(sourcePath("resources/samples")).entryInfoList({"*.taiwa"}, QDir::Files, QDir::Name))
            if (readFile(f.absoluteFilePath()).find("\"shape\": \"bar\"") == std::string::npos)  // lathe jobs have no tape yet
                QTest::newRow(qPrintable(f.completeBaseName())) << f.absoluteFilePath();
    }
    void linuxcncTapesPassRs274AndStayInside()
    {
        QFETCH(QString, job);
        const Exported e = exportSample(job, "mm");
        QVERIFY(e.plan.ok());
        const Rs274Result r = runRs274(e.nc);
        QVERIFY2(r.ok, qPrintable(r.errors));
        QVERIFY(!r.moves.empty());

        const Plan& plan = e.plan;
        if (std::all_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return s.module == "SURFACE"; })) {
            judgeSurfaceTape(plan, r);
            return;
        }
        std::map<int, double> deepest;  // step (1-based) -> lowest feed z
        std::map<int, double> reach;    // roughing step -> closest approach to the wall (signed)
        std::vector<std::vector<Point3>> fed(plan.steps.size() + 1);
        int seenSteps = 0;
        for (const auto& m : r.moves) {
            if (m.step == 0) {
                QVERIFY2(m.kind == CanonMove::Traverse && m.end.z >= 0, "a cut before the first step");
                continue;
            }
            QVERIFY(m.step <= static_cast<int>(plan.steps.size()));
            seenSteps = std::max(seenSteps, m.step);
            const Step& s = plan.steps[static_cast<std::size_t>(m.step - 1)];
            const Tool& tool = *plan.tool(s.tool->toolId);
            const ModuleInput& module = plan.mmJob.units[static_cast<std::size_t>(s.unit)].module;
            if (m.kind == CanonMove::Traverse) {
                // Rapids below the stock top only straight down into air: above
                // the step's start depth, or into a hole this step already fed.
                if (m.end.z < -kTol) {
                    const bool aboveStart = m.end.z >= -millingOf(s).startDepth - kTol && gouge(module, tool, m.end) <= kTol;
                    const auto& pts = fed[static_cast<std::size_t>(m.step)];
                    const bool intoCut = std::any_of(pts.begin(), pts.end(), [&](const Point3& p) {
                        return std::abs(p.x - m.end.x) < kTol && std::abs(p.y - m.end.y) < kTol && p.z <= m.end.z + kTol;
                    });
                    const bool vertical = std::abs(m.start.x - m.end.x) < kTol && std::abs(m.start.y - m.end.y) < kTol;
                    QVERIFY2(aboveStart || (intoCut && vertical), qPrintable("rapid into material: " + where(m, s)));
                }
                continue;
            }
            QCOMPARE(m.tool, s.tool->toolId);  // every cut with the step's own tool
            for (const auto& p : checkPoints(m)) {
                const double g = gouge(module, tool, p);
                QVERIFY2(g <= kTol, qPrintable(QString("gouge of %1 mm: ").arg(g) + where(m, s)));
                deepest[m.step] = std::min(deepest.count(m.step) ? deepest[m.step] : 0.0, p.z);
                if (s.kind == StepKind::Roughing && p.z < 0) {
                    const double d = wallDistance(module, p) + tool.radius();
                    reach[m.step] = std::max(reach.count(m.step) ? reach[m.step] : -1e9, d);
                }
            }
            fed[static_cast<std::size_t>(m.step)].push_back(m.end);
        }
        QCOMPARE(seenSteps, static_cast<int>(plan.steps.size()));

        // Depths and allowances, step by step.
        for (std::size_t i = 0; i < plan.steps.size(); ++i) {
            const Step& s = plan.steps[i];
            const int k = static_cast<int>(i) + 1;
            const ModuleInput& module = plan.mmJob.units[static_cast<std::size_t>(s.unit)].module;
            const double T = pocketDepth(module);
            const QString name = QString("step %1 %2").arg(k).arg(QString::fromStdString(s.label()));
            QVERIFY2(deepest.count(k), qPrintable(name + " cuts nothing"));
            QVERIFY2(std::abs(deepest[k] + millingOf(s).cutDepth) < kTol,
                     qPrintable(name + QString(" reaches %1, not %2").arg(deepest[k]).arg(-millingOf(s).cutDepth)));
            if (s.kind == StepKind::FloorFinishing || s.kind == StepKind::WallFinishing ||
                s.kind == StepKind::InclinedFaceFinishing)
                QVERIFY2(std::abs(deepest[k] + T) < kTol, qPrintable(name + " does not reach the floor at -T"));
            if (s.kind == StepKind::Roughing) {
                const bool lastLayer = std::none_of(plan.steps.begin(), plan.steps.end(), [&](const Step& o) {
                    return o.unit == s.unit && o.kind == StepKind::Roughing && o.number > s.number;
                });
                if (lastLayer)
                    QVERIFY2(std::abs(deepest[k] + (T - plan.technology.beta2)) < kTol,
                             qPrintable(name + " does not stop at -(T - beta2)"));
                QVERIFY2(std::abs(reach[k] + plan.technology.alpha2) < kTol,
                         qPrintable(name + QString(" leaves %1 mm on the walls, not alpha2 = %2")
                                               .arg(-reach[k]).arg(plan.technology.alpha2)));
            }
        }
    }

    void inchTapeIsTheMmTapeScaled()
    {
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const Rs274Result mm = runRs274(exportSample(job, "mm").nc);
        const Rs274Result in = runRs274(exportSample(job, "inch").nc);
        QVERIFY2(mm.ok && in.ok, qPrintable(mm.errors + in.errors));
        QVERIFY(!in.canon.filter("USE_LENGTH_UNITS(CANON_UNITS_INCHES)").isEmpty());
        QCOMPARE(in.moves.size(), mm.moves.size());
        for (std::size_t i = 0; i < mm.moves.size(); ++i) {
            const auto& a = mm.moves[i];
            const auto& b = in.moves[i];
            QCOMPARE(a.kind, b.kind);
            // The inch tape rounds to 0.0001 in = 2.54 µm.
            QVERIFY2(std::abs(a.end.x - b.end.x * 25.4) < 2e-3 && std::abs(a.end.y - b.end.y * 25.4) < 2e-3 &&
                         std::abs(a.end.z - b.end.z * 25.4) < 2e-3,
                     qPrintable(QString("move %1 differs").arg(i)));
        }
    }
};

QTEST_APPLESS_MAIN(TestRs274Samples)
#include "test_rs274_samples.moc"
