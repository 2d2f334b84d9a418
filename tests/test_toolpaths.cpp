// CL creation on hand-made steps: every step kind's path starts and ends at
// safe height, never takes the tool centre outside the outline shrunk by the
// tool radius, clears every roughing layer completely (Clipper), mills
// climb, keeps arcs as arcs, and estimates time as a hand computation does.
#include "paths/cl.h"
#include "paths/contour.h"
#include "paths/coverage.h"
#include "support/pocket_geometry.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;

namespace {

Tool endMill(double d)
{
    Tool t;
    t.id = 1;
    t.type = ToolType::FlatEndMill;
    t.diameter = d;
    t.fluteLength = 3 * d;
    return t;
}

Step pocketStep(StepKind kind, Quad outline, double start, double cut)
{
    Step s;
    s.kind = kind;
    s.outline = outline;
    s.startDepth = start;
    s.cutDepth = cut;
    s.position = centroid(outline.corners);
    return s;
}

Quad rectangle(double w, double h, double r) { return {{{{0, 0}, {w, 0}, {w, h}, {0, h}}}, r}; }

// All XY points the tool centre passes through while feeding (arcs sampled).
std::vector<Point3> feedPoints(const ToolPath& p)
{
    std::vector<Point3> pts;
    Point3 at = p.start;
    for (const auto& m : p.moves) {
        if (m.kind == MoveKind::Feed) pts.push_back(m.end);
        if (m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW) {
            const Point2 a{at.x - m.centre.x, at.y - m.centre.y}, e{m.end.x - m.centre.x, m.end.y - m.centre.y};
            double sweep = std::atan2(cross(a, e), dot(a, e));
            if (m.kind == MoveKind::ArcCCW && sweep <= 0) sweep += 2 * std::numbers::pi;
            if (m.kind == MoveKind::ArcCW && sweep >= 0) sweep -= 2 * std::numbers::pi;
            for (int i = 1; i <= 32; ++i) {
                const double ang = std::atan2(a.y, a.x) + sweep * i / 32;
                pts.push_back({m.centre.x + length(a) * std::cos(ang), m.centre.y + length(a) * std::sin(ang),
                               at.z + (m.end.z - at.z) * i / 32});
            }
        }
        if (m.kind != MoveKind::DrillCycle) at = m.end;
    }
    return pts;
}

double worstOutside(const Quad& outline, double radius, const ToolPath& p)
{
    double worst = -1e9;
    for (const auto& q : feedPoints(p)) worst = std::max(worst, test::signedDistance(outline, {q.x, q.y}) + radius);
    return worst;
}

}  // namespace

class TestToolpaths : public QObject {
    Q_OBJECT
private slots:
    void roughingStaysInsideAndClearsEveryLayer_data()
    {
        QTest::addColumn<Quad>("outline");
        QTest::addColumn<double>("diameter");
        QTest::newRow("rectangle") << rectangle(100, 60, 5.7) << 10.0;
        QTest::newRow("thin slot") << rectangle(100, 12, 3) << 6.0;
        QTest::newRow("tight corners r = R") << rectangle(40, 30, 3) << 6.0;
        QTest::newRow("parallelogram 60 deg")
            << Quad{{{{0, 0}, {80, 0}, {80 + 40 * std::cos(std::numbers::pi / 3), 40 * std::sin(std::numbers::pi / 3)},
                      {40 * std::cos(std::numbers::pi / 3), 40 * std::sin(std::numbers::pi / 3)}}}, 4.0}
            << 8.0;
    }
    void roughingStaysInsideAndClearsEveryLayer()
    {
        QFETCH(Quad, outline);
        QFETCH(double, diameter);
        const Tool tool = endMill(diameter);
        TechnologyData tech;
        tech.gamma = 0.5;
        const Step s = pocketStep(StepKind::Roughing, outline, 0, 11.8);
        const ToolPath p = makeToolPath(s, tool, tech, {});
        QCOMPARE(p.start.z, 5.0);
        QCOMPARE(p.moves.back().end.z, 5.0);
        QVERIFY(worstOutside(outline, tool.radius(), p) <= 1e-6);
        // Layers: equal, at most gamma x D, the last one at the cut depth.
        std::vector<double> zs;
        for (const auto& q : feedPoints(p))
            if (std::none_of(zs.begin(), zs.end(), [&](double z) { return std::abs(z - q.z) < 1e-9; }) && q.z < 0) zs.push_back(q.z);
        const double lowest = *std::min_element(zs.begin(), zs.end());
        QVERIFY(std::abs(lowest + 11.8) < 1e-9);
        const int layers = static_cast<int>(std::ceil(11.8 / (0.5 * diameter) - 1e-9));
        for (int k = 1; k <= layers; ++k) {
            const double z = -11.8 * k / layers;
            QVERIFY2(std::any_of(zs.begin(), zs.end(), [&](double v) { return std::abs(v - z) < 1e-9; }), "layer missing");
            // The part of the path at this layer's height clears the whole outline.
            ToolPath layer{p.start, {}};
            for (const auto& m : p.moves)
                if (m.kind != MoveKind::Rapid && std::abs(m.end.z - z) < 1e-9) layer.moves.push_back(m);
            QVERIFY2(paths::uncutArea(outline, layer, tool.radius()) < 1e-3,
                     qPrintable(QString("layer %1 leaves %2 mm2").arg(k).arg(paths::uncutArea(outline, layer, tool.radius()))));
        }
    }

    void outermostRingIsExactlyTheOffsetWithCornerArcs()
    {
        const Quad outline = rectangle(100, 60, 5.7);
        const ToolPath p = makeToolPath(pocketStep(StepKind::Roughing, outline, 0, 3), endMill(10), TechnologyData{}, {});
        QVERIFY(std::abs(worstOutside(outline, 5, p)) < 1e-9);  // it touches the outline shrunk by R
        int cornerArcs = 0;
        Point3 at = p.start;
        for (const auto& m : p.moves) {
            if (m.kind == MoveKind::ArcCCW && std::abs(distance({at.x, at.y}, m.centre) - 0.7) < 1e-9) ++cornerArcs;
            if (m.kind != MoveKind::DrillCycle) at = m.end;
        }
        QVERIFY(cornerArcs >= 4);  // corner radius r - R = 0.7 as arcs, not chords
    }

    void contoursAreClimbMilledCounterClockwise()
    {
        paths::PathBuilder b({0, 0, 0});
        const Quad c = rectangle(50, 30, 2);
        b.feed({paths::contourStart(c, true).point.x, paths::contourStart(c, true).point.y, -1});
        paths::appendContour(b, c, -1, true);
        const ToolPath p = b.take();
        double area = 0;
        Point3 at = p.moves.front().end;
        for (const auto& m : p.moves) {
            area += cross({at.x, at.y}, {m.end.x, m.end.y});
            at = m.end;
        }
        QVERIFY(area > 0);  // counter-clockwise: the wall on the tool's right, climb with M3
    }

    void wallFinishingLeadsInTangentiallyAndIncises()
    {
        const Quad outline = rectangle(80, 50, 6);
        const Tool tool = endMill(12);
        TechnologyData tech;
        tech.gamma = 0.5;
        Step s = pocketStep(StepKind::WallFinishing, outline, 0, 14);
        ToolPath p = makeToolPath(s, tool, tech, {});
        QVERIFY(worstOutside(outline, 6, p) <= 1e-9);
        int arcs = 0;
        for (const auto& m : p.moves) arcs += m.kind == MoveKind::ArcCCW;
        QCOMPARE(arcs, 2);  // sharp centre corners (r = R): only the two lead arcs
        s.multiIncision = true;
        p = makeToolPath(s, tool, tech, {});
        int levels = 0;
        for (const auto& m : p.moves) levels += m.feed == FeedKind::Plunge;
        QCOMPARE(levels, static_cast<int>(std::ceil(14.0 / 6.0)));
    }

    void taperWallRunsTheTipOnTheFloorOffset()
    {
        const Quad top = rectangle(80, 50, 6);
        Tool t = endMill(4);
        t.type = ToolType::TaperEndMill;
        t.taperAngle = 5;
        Step s = pocketStep(StepKind::WallFinishing, top, 0, 10);
        s.wallTaper = 5;
        const ToolPath p = makeToolPath(s, t, TechnologyData{}, {});
        const double offset = 2 + 10 * std::tan(5 * std::numbers::pi / 180);
        QVERIFY(std::abs(worstOutside(top, offset, p)) < 1e-9);
    }

    void pilotHolePecksWhenDeep()
    {
        Step s;
        s.kind = StepKind::PilotHole;
        s.position = {30, 20};
        s.cutDepth = 11;
        Tool drill = endMill(10);
        drill.type = ToolType::Drill;
        ToolPath p = makeToolPath(s, drill, TechnologyData{}, {});
        QCOMPARE(p.moves.size(), std::size_t(1));
        QCOMPARE(p.moves[0].end.z, -11.0);
        QCOMPARE(p.moves[0].peck, 0.0);
        s.cutDepth = 40;
        p = makeToolPath(s, drill, TechnologyData{}, {});
        QCOMPARE(p.moves[0].peck, 10.0);
    }

    void inclinedFaceStepsOverForTheScallop()
    {
        Step s;
        s.kind = StepKind::InclinedFaceFinishing;
        s.cutDepth = 10;
        s.scallop = 0.01;
        const double tan10 = std::tan(10 * std::numbers::pi / 180);
        s.face = InclinedFace{{{{0, 0}, {0, 40}}}, {{{10 * tan10, 0}, {10 * tan10, 40}}}, 10};
        s.outline = Quad{{{{10 * tan10, 0}, {60, 0}, {60, 40}, {10 * tan10, 40}}}, 4};
        Tool ball = endMill(6);
        ball.type = ToolType::BallEndMill;
        const ToolPath p = makeToolPath(s, ball, TechnologyData{}, {});
        // Passes along Y; consecutive passes one scallop step-over apart along the face.
        std::vector<Point3> starts;
        for (const auto& m : p.moves)
            if (m.kind == MoveKind::Feed && std::abs(m.end.y - 4) < 1e-9) starts.push_back(m.end);
        QVERIFY(starts.size() > 10);
        const double expected = 2 * std::sqrt(2 * 3 * 0.01 - 0.01 * 0.01);
        const double along = std::hypot(starts[1].x - starts[0].x, starts[1].z - starts[0].z);
        QVERIFY(along <= expected + 1e-9);
        QVERIFY(along > 0.8 * expected);
        // The tip never goes below the floor, and the last pass reaches it.
        double lowest = 0;
        for (const auto& m : p.moves) lowest = std::min(lowest, m.end.z);
        QVERIFY(std::abs(lowest + 10) < 1e-9);
    }

    void timeEstimateIsTheHandComputation()
    {
        ToolPath p{{0, 0, 5}, {}};
        p.moves.push_back({MoveKind::Rapid, {0, 0, 1}});
        Move plunge{MoveKind::Feed, {0, 0, -2}};
        plunge.feed = FeedKind::Plunge;
        p.moves.push_back(plunge);
        p.moves.push_back({MoveKind::Feed, {100, 0, -2}});
        SpeedsFeeds sf{1000, 500, 100};
        const double expected = 4.0 / 15000 + 3.0 / 100 + 100.0 / 500;
        QVERIFY(std::abs(estimateMinutes(p, sf) - expected) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestToolpaths)
#include "test_toolpaths.moc"
