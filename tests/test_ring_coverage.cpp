// The geometric rule that lets planning skip a rectangular pocket's coverage
// proof (paths::ringsClearRectangle): rings of a rounded rectangle no more
// than (1 + 1/sqrt 2) R apart clear it. Judged by Clipper's uncut area on
// rings alone, on both sides of the bound, and on the planner's own paths
// for rectangles the rule accepts and shapes it refuses.
#include "paths/contour.h"
#include "paths/coverage.h"
#include "test_toolpaths_support.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// A w x h rectangle with corner radius r, turned by `degrees` about the origin.
Quad turnedRectangle(double w, double h, double r, double degrees)
{
    Quad q = rectangle(w, h, r);
    const double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
    for (auto& p : q.corners) p = {c * p.x - s * p.y, s * p.x + c * p.y};
    return q;
}

// Offsets from R to the deepest (1e-4 short of collapse) at most `gap` apart.
std::vector<double> evenOffsets(const Quad& q, double R, double gap)
{
    const double deepest = std::max(R, paths::maxOffset(q) - 1e-4);
    const int n = std::max(1, static_cast<int>(std::ceil((deepest - R) / gap - 1e-9)));
    std::vector<double> d;
    for (int k = 0; k <= n; ++k) d.push_back(R + (deepest - R) * k / n);
    return d;
}

// The rings alone, at Z 0, linked by straight feeds.
ToolPath ringsOnly(const Quad& q, const std::vector<double>& offsets)
{
    const Quad first = paths::centreQuad(q, offsets.front());
    paths::PathBuilder b({paths::contourStart(first, true).point.x, paths::contourStart(first, true).point.y, 0});
    for (const double d : offsets) {
        const Quad c = paths::centreQuad(q, d);
        const Point2 s = paths::contourStart(c, true).point;
        b.feed({s.x, s.y, 0});
        paths::appendContour(b, c, 0, true);
    }
    return b.take();
}

}  // namespace

class TestRingCoverage : public QObject {
    Q_OBJECT

private slots:
    // Either side of the bound, on rings alone: at 0.99 of it nothing is
    // left (the rule holds, so it may skip the proof), at 1.1 of it the
    // corners' bisectors are left uncut (so the bound is where coverage
    // really ends, and a looser rule would let stock through).
    void theBoundIsWhereRingsStopClearing()
    {
        const double R = 5, bound = (1 + std::numbers::sqrt2 / 2) * R;
        for (const double degrees : {0.0, 17.0, 90.0, 133.0}) {
            const Quad q = turnedRectangle(80, 50, R, degrees);
            const auto tight = evenOffsets(q, R, 0.99 * bound);
            QVERIFY(paths::ringsClearRectangle(q, R, tight));
            const double left = paths::uncutArea(q, ringsOnly(q, tight), R);
            QVERIFY2(left < 1e-3, qPrintable(QString("%1 deg: %2 mm2 left at 0.99 of the bound").arg(degrees).arg(left)));

            // Rings 1.1 x the bound apart, the last 1e-4 short of collapse.
            std::vector<double> wide;
            for (double d = R; d < paths::maxOffset(q) - 1e-4; d += 1.1 * bound) wide.push_back(d);
            wide.push_back(paths::maxOffset(q) - 1e-4);
            QVERIFY(!paths::ringsClearRectangle(q, R, wide));
            const double leftWide = paths::uncutArea(q, ringsOnly(q, wide), R);
            QVERIFY2(leftWide > 0.01, qPrintable(QString("%1 deg: only %2 mm2 left at 1.1 x the bound").arg(degrees).arg(leftWide)));
        }
    }

    // Shapes the rule does not speak for: not rectangles, corners tighter
    // than the tool, a last ring short of the deepest, offsets not from R.
    void theRuleRefusesWhatItCannotProve()
    {
        const double R = 4;
        const Quad parallelogram{{{{0, 0}, {90, 0}, {141.96, 30}, {51.96, 30}}}, 4.0};
        QVERIFY(!paths::ringsClearRectangle(parallelogram, R, evenOffsets(parallelogram, R, R)));
        const Quad kite{{{{0, 0}, {40, -10}, {60, 20}, {10, 30}}}, 5.0};
        QVERIFY(!paths::ringsClearRectangle(kite, R, evenOffsets(kite, R, R)));
        const Quad tight = rectangle(60, 40, 3.9);
        QVERIFY(!paths::ringsClearRectangle(tight, R, evenOffsets(tight, R, R)));
        const Quad ok = rectangle(60, 40, 4);
        auto offsets = evenOffsets(ok, R, R);
        QVERIFY(paths::ringsClearRectangle(ok, R, offsets));
        offsets.pop_back();
        QVERIFY(!paths::ringsClearRectangle(ok, R, offsets));  // the middle is left
        QVERIFY(!paths::ringsClearRectangle(ok, R, {4.5, 10, 19.9999}));
        QVERIFY(!paths::ringsClearRectangle(ok, R, {}));
    }

    // The planner's paths: rectangles at step-overs the rule accepts (no
    // proof made) and one it refuses (0.95 D: proved by Clipper, with
    // cleanup visits if needed) each clear their layer, judged by Clipper
    // within 1 µm of the outline.
    void plannedRectanglesClearTheirLayer()
    {
        for (const double stepOver : {0.3, 0.45, 0.6, 0.85, 0.95})
            for (const double degrees : {0.0, 30.0, 200.0})
                for (const double d : {6.0, 10.0}) {
                    const double R = d / 2;
                    // As high as makes the rings 0.98 of the step-over apart: 1.67 R
                    // at 0.85 (within the bound), 1.86 R at 0.95 (beyond it).
                    const Quad q = turnedRectangle(47.3, 2 * (R + 0.98 * stepOver * d), R + 0.5, degrees);
                    TechnologyData tech;
                    tech.stepOver = stepOver;
                    forgetProvedLayers();
                    const ToolPath p = makeToolPath(makePocketStep(StepKind::Roughing, q, 0, 2), makeTool(ToolType::FlatEndMill, d), tech,
                                                    PathParameters{});
                    ToolPath layer{p.start, {}};
                    Point3 at = p.start;
                    for (const Move& m : p.moves) {
                        if (std::abs(m.end.z + 2) < 1e-9 && std::abs(at.z + 2) < 1e-9) {
                            if (layer.moves.empty() || !(layer.moves.back().end == at)) layer.moves.push_back({MoveKind::Rapid, at});
                            layer.moves.push_back(m);
                        }
                        at = m.end;
                    }
                    const double left = paths::uncutArea(q, layer, R);
                    QVERIFY2(left < 1e-3, qPrintable(QString("step-over %1, %2 deg, D%3: %4 mm2 left").arg(stepOver).arg(degrees).arg(d).arg(left)));
                }
    }
};

QTEST_APPLESS_MAIN(TestRingCoverage)
#include "test_ring_coverage.moc"
