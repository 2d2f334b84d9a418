// Module SURFACE's scallops as `taiwa verify` sees them (issue 36, "its
// colour map shows the scallops within the set height"): the sample
// tests/data/surface-ruled.taiwa is verified (verifyPlan, 0.05 mm cells) and
// at every cell over the surface's inside (the ball's axis over the surface
// all around it, X 14 to 106, Y 20 to 66) the simulated stock's height above
// the finishing surface (the unit's cavity, the surface's own height) is
// measured: the residual, the scallops' height as the verification sees it.
// It must stay within the unit's scallop setting (plus the verification's
// Z step, 0.01 mm, and its 1 µm tolerance), and the colour map
// (deviationMap) must show every such cell at size, none with material
// left, none gouged; and the scallops must be there to see (above the
// grid's own terms). Negative control: the unit planned for 0.3 mm scallops
// and judged against its 0.05 shows scallops above it, and the colour map
// marks them as material left.
#include "modules/registry.h"
#include "modules/surface/surface.h"
#include "support/support.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "verify/deviation.h"
#include "verify/verify.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace taiwa;
using namespace taiwa::test;
using json = nlohmann::json;

namespace {

constexpr double kResolution = 0.05;

struct Measured {
    double highest = -1e9;  // the largest residual over the inside [mm]
    double lowest = 1e9;    // the smallest (below 0: cut into the surface)
    int cells = 0;
    int atSize = 0, left = 0, gouged = 0;  // the colour map's cells over the inside
};

// The verification of `p` measured over the surface's inside against the
// finishing surface; the colour map made with the cavity's tolerance
// `scallop` (the unit's setting when it is the one planned).
Measured measure(const Plan& planned, double scallop)
{
    Plan p = planned;
    p.mmJob.units[0].module.as<SurfaceUnit>().scallop = scallop;
    verify::Options vo;
    vo.resolution = kResolution;
    const verify::Report report = verify::verifyPlan(p, vo);
    const verify::DeviationMap map = verify::deviationMap(p, report, std::size_t(1) << 40);
    const auto cavity = moduleKind(p.mmJob.units[0].module).cavity(p.mmJob.units[0].module, p.technology);
    if (!cavity || map.factor != 1) qFatal("no cavity, or a coarse map");
    Measured m;
    const sim::HeightField& field = report.stock;
    for (int j = 0; j < field.rows(); ++j)
        for (int i = 0; i < field.columns(); ++i) {
            const Point2 c = field.centre(i, j);
            if (c.x < 14 || c.x > 106 || c.y < 20 || c.y > 66) continue;
            const double surface = -cavity->depthAt(c, 0.0);
            const double residual = field.at(i, j) - surface;
            m.highest = std::max(m.highest, residual);
            m.lowest = std::min(m.lowest, residual);
            ++m.cells;
            const verify::DeviationBand b = map.band[map.stock.indexOf(i, j)];
            m.atSize += b == verify::DeviationBand::AtSize ? 1 : 0;
            m.gouged += b == verify::DeviationBand::Gouge ? 1 : 0;
            m.left += b == verify::DeviationBand::RestThin || b == verify::DeviationBand::RestMedium ||
                              b == verify::DeviationBand::RestThick
                          ? 1
                          : 0;
        }
    return m;
}

}  // namespace

class TestSurfaceScallopMap : public QObject {
    Q_OBJECT
private slots:
    void scallopsOnTheColourMapStayWithinTheSetHeight()
    {
        const json j = json::parse(readFile(dataPath("surface-ruled.taiwa")));
        const JobReadResult r = readJob(j.dump());
        QVERIFY(r.job);
        const Plan p = planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(p.ok());
        const double h = p.mmJob.units[0].module.as<SurfaceUnit>().scallop;
        QCOMPARE(h, 0.05);
        const double zStep = std::min(0.02, kResolution / 5.0);
        const Measured m = measure(p, h);
        qInfo("scallop %g mm: %d cells over the inside, residual %.4f to %.4f mm; colour map: %d at size, %d with "
              "material left, %d gouged",
              h, m.cells, m.lowest, m.highest, m.atSize, m.left, m.gouged);
        QVERIFY(m.cells > 1'000'000);
        QVERIFY2(m.highest <= h + zStep + 0.001, qPrintable(QString::number(m.highest)));
        // The scallops are there to see: higher than the grid's own terms.
        QVERIFY2(m.highest > zStep + 0.001, qPrintable(QString::number(m.highest)));
        QVERIFY2(m.lowest > -0.001, qPrintable(QString::number(m.lowest)));
        QCOMPARE(m.left, 0);
        QCOMPARE(m.gouged, 0);
        QCOMPARE(m.atSize, m.cells);

        // Negative control: the unit planned for scallops of 0.3 mm (its
        // paths farther apart) and judged against 0.05: the scallops rise
        // above it, and the colour map marks them as material left.
        Job coarse = *r.job;
        coarse.units[0].module.as<SurfaceUnit>().scallop = 0.3;
        const Plan pc = planJob(coarse, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(pc.ok());
        const Measured wide = measure(pc, h);
        qInfo("planned for 0.3 mm, judged against %g: residual up to %.4f mm, %d of %d cells with material left", h,
              wide.highest, wide.left, wide.cells);
        QVERIFY(wide.highest > h + zStep + 0.001);
        QVERIFY2(wide.left > wide.cells / 100, qPrintable(QString::number(wide.left)));
    }
};

QTEST_GUILESS_MAIN(TestSurfaceScallopMap)
#include "test_surface_scallop_map.moc"
