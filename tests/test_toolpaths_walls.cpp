// Wall, inclined-face and drilling tool paths on hand-made steps, and the
// time estimate: wall finishing keeps the tool inside, leads in and out on
// arcs tangent to the contour, keeps corner arcs of radius r - R, mills
// climb, incises ceil(T / (gamma D)) times for F = 2 and follows a tapered
// wall's floor section; the ball end mill steps over by the scallop formula
// and never gouges the pocket; drilling pecks when deep.
#include "test_toolpaths_support.h"

#include "modules/inclined_face.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "model/job.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace taiwa;
using namespace taiwa::test;

namespace {

const PathParameters kParams{};

// Unit tangent of a cutting move at its start (atEnd = false) or its end.
Point2 tangent(const Piece& q, bool atEnd)
{
    const Move& m = q.move;
    if (m.kind == MoveKind::Feed) {
        const Point2 d{m.end.x - q.from.x, m.end.y - q.from.y};
        return (1.0 / length(d)) * d;
    }
    const Point3 p = atEnd ? m.end : q.from;
    const Point2 r{p.x - m.centre.x, p.y - m.centre.y};
    const Point2 t = m.kind == MoveKind::ArcCCW ? Point2{-r.y, r.x} : Point2{r.y, -r.x};
    return (1.0 / length(t)) * t;
}

std::vector<double> incisionDepths(const ToolPath& p)
{
    std::vector<double> z;
    for (const auto& m : p.moves)
        if (m.feed == FeedKind::Plunge) z.push_back(m.end.z);
    return z;
}

}  // namespace

class TestToolpathsWalls : public QObject {
    Q_OBJECT
private slots:
    void wallFinishingLeadsInTangentiallyOnTheContour()
    {
        const Quad outline{{{{0, 0}, {80, 0}, {90, 50}, {5, 45}}}, 7.5};
        const Tool tool = makeTool(ToolType::FlatEndMill, 10);
        const Step s = makePocketStep(StepKind::WallFinishing, outline, 0, 14);
        const ToolPath p = makeToolPath(s, tool, TechnologyData{}, kParams);
        QCOMPARE(p.start.z, kParams.safeZ);
        QCOMPARE(endOf(p).z, kParams.safeZ);
        QVERIFY(worstOutside(outline, 5, p) <= 1e-6);
        QVERIFY(std::abs(worstOutside(outline, 5, p)) < 1e-9);  // it runs on the wall
        QCOMPARE(incisionDepths(p), std::vector<double>{-14.0});  // F = 1: one incision at full depth

        const auto pieces = cuttingPieces(p);
        // Lead-in: the arc after the plunge; lead-out: the last cutting move.
        std::size_t in = 0;
        while (pieces[in].move.feed == FeedKind::Plunge || pieces[in].move.kind == MoveKind::Feed) ++in;
        const Piece& leadIn = pieces[in];
        const Piece& leadOut = pieces.back();
        for (const Piece* lead : {&leadIn, &leadOut}) {
            QCOMPARE(lead->move.kind, MoveKind::ArcCCW);
            QVERIFY(std::abs(std::abs(arcSweep(lead->from, lead->move)) - std::numbers::pi / 2) < 1e-9);  // quarter circle
        }
        QVERIFY(signedDistance(outline, {leadIn.from.x, leadIn.from.y}) < -5 - 1.0);  // starts inside the pocket
        // Tangent where the lead-in meets the contour and where the lead-out leaves it.
        const Point2 a = tangent(leadIn, true), b = tangent(pieces[in + 1], false);
        QVERIFY(distance(a, b) < 1e-9);
        const Point2 c = tangent(pieces[pieces.size() - 2], true), d = tangent(leadOut, false);
        QVERIFY(distance(c, d) < 1e-9);
        // The contour's corner arcs: radius r - R = 2.5, about the outline's arc centres.
        int corners = 0;
        for (std::size_t i = in + 1; i + 1 < pieces.size(); ++i)
            if (pieces[i].move.kind != MoveKind::Feed) {
                QVERIFY(std::abs(distance({pieces[i].from.x, pieces[i].from.y}, pieces[i].move.centre) - 2.5) < 1e-9);
                ++corners;
            }
        QCOMPARE(corners, 4);
        // Climb: the wall on the tool's right all the way round.
        const WallSides w = wallSides(p, outline, 5);
        QVERIFY(w.right >= 8);
        QCOMPARE(w.left, 0);
    }

    void multiIncisionCutsEqualStepsOfAtMostGammaD_data()
    {
        QTest::addColumn<double>("depth");
        QTest::addColumn<double>("gamma");
        QTest::newRow("14 mm, gamma 0.5, D 12") << 14.0 << 0.5;
        QTest::newRow("12 mm, exactly two") << 12.0 << 0.5;
        QTest::newRow("20 mm, gamma 0.3") << 20.0 << 0.3;
    }
    void multiIncisionCutsEqualStepsOfAtMostGammaD()
    {
        QFETCH(double, depth);
        QFETCH(double, gamma);
        const Quad outline = rectangle(80, 50, 6);
        const Tool tool = makeTool(ToolType::FlatEndMill, 12);
        TechnologyData tech;
        tech.gamma = gamma;
        Step s = makePocketStep(StepKind::WallFinishing, outline, 0, depth);
        editMilling(s).multiIncision = true;
        const ToolPath p = makeToolPath(s, tool, tech, kParams);
        const auto z = incisionDepths(p);
        QCOMPARE(static_cast<int>(z.size()), static_cast<int>(std::ceil(depth / (gamma * 12) - 1e-9)));
        QCOMPARE(z.back(), -depth);
        double above = 0;
        for (const double d : z) {
            QVERIFY(above - d <= gamma * 12 + 1e-9);
            QVERIFY(std::abs(above - d - depth / static_cast<double>(z.size())) < 1e-9);
            above = d;
        }
        QVERIFY(worstOutside(outline, 6, p) <= 1e-6);
        // Each incision has its lead-in and lead-out (r = R: no corner arcs).
        const auto arcs = std::count_if(p.moves.begin(), p.moves.end(), [](const Move& m) { return m.kind == MoveKind::ArcCCW; });
        QCOMPARE(static_cast<std::size_t>(arcs), 2 * z.size());
        QCOMPARE(endOf(p).z, kParams.safeZ);
    }

    // The taper end mill's tip runs on the floor section moved in by its tip
    // radius; its flank then touches the wall at every depth, never beyond.
    void taperWallFollowsTheFloorSection()
    {
        M4Pocket pocket;
        pocket.corners = {{{0, 0}, {80, 0}, {80, 50}, {0, 50}}};
        pocket.cornerRadius = 6;
        pocket.depth = 10;
        pocket.taper = 5;
        Tool t = makeTool(ToolType::TaperEndMill, 4);
        t.taperAngle = 5;
        Step s = makePocketStep(StepKind::WallFinishing, Quad{pocket.corners, 6}, 0, 10);
        editMilling(s).wallTaper = 5;
        for (const bool multi : {false, true}) {
            editMilling(s).multiIncision = multi;
            const ToolPath p = makeToolPath(s, t, TechnologyData{}, kParams);
            double worst = -1e9;
            for (const auto& q : feedPoints(p)) {
                const double offset = 2 + (-q.z) * tanDeg(5);
                QVERIFY(signedDistance(millingOf(s).outline.value(), {q.x, q.y}) + offset <= 1e-6);
                if (q.z < -1e-9) worst = std::max(worst, gouge(ModuleInput{pocket}, t, q));
            }
            QVERIFY2(worst <= 1e-3 && worst > -1e-3, qPrintable(QString::number(worst)));  // touches, no gouge
        }
        // A flank steeper than the wall would gouge it: refused.
        t.taperAngle = 7;
        QVERIFY_THROWS_EXCEPTION(std::logic_error, makeToolPath(s, t, TechnologyData{}, kParams));
    }

    void pilotHoleDrillsToDepthAndPecksWhenDeep()
    {
        Step s;
        s.module = "M4";
        s.kind = StepKind::PilotHole;
        editMilling(s).position = {30, 20};
        editMilling(s).cutDepth = 11;
        const Tool drill = makeTool(ToolType::Drill, 10);
        ToolPath p = makeToolPath(s, drill, TechnologyData{}, kParams);
        QCOMPARE(p.moves.size(), std::size_t(1));
        QCOMPARE(p.start, (Point3{30, 20, kParams.safeZ}));
        QCOMPARE(p.moves[0].kind, MoveKind::DrillCycle);
        QCOMPARE(p.moves[0].end, (Point3{30, 20, -11}));
        QCOMPARE(p.moves[0].retractZ, kParams.clearance);
        QCOMPARE(p.moves[0].peck, 0.0);
        QCOMPARE(endOf(p).z, kParams.safeZ);  // G98: back to the start level
        editMilling(s).cutDepth = 30;                      // exactly 3 x D: still straight
        QCOMPARE(makeToolPath(s, drill, TechnologyData{}, kParams).moves[0].peck, 0.0);
        editMilling(s).cutDepth = 40;
        QCOMPARE(makeToolPath(s, drill, TechnologyData{}, kParams).moves[0].peck, 10.0);
    }

    void inclinedFaceStepsOverForTheScallopWithoutGouging()
    {
        M2DPocket pocket;
        pocket.corner = {0, 0};
        pocket.lengthX = 80;
        pocket.lengthY = 40;
        pocket.depth = 10;
        pocket.theta1 = 20;
        pocket.cornerRadius = 4;
        const double run = 10 * tanDeg(20);
        Step s;
        s.module = "M2D";
        s.kind = StepKind::InclinedFaceFinishing;
        s.payload = InclinedFace{{{{0, 0}, {0, 40}}}, {{{run, 0}, {run, 40}}}, 20, 0.01};
        editMilling(s).cutDepth = 10;
        editMilling(s).outline = m2dCrossSection(pocket, 10);
        const Tool ball = makeTool(ToolType::BallEndMill, 6);
        const ToolPath p = makeToolPath(s, ball, TechnologyData{}, kParams);
        QCOMPARE(p.start.z, kParams.safeZ);
        QCOMPARE(endOf(p).z, kParams.safeZ);

        // Passes along Y (zig-zag), consecutive passes at most the scallop
        // step-over apart along the face, and not much less.
        std::vector<Piece> passes;
        for (const auto& q : cuttingPieces(p))
            if (std::abs(q.move.end.x - q.from.x) < 1e-12 && std::abs(q.move.end.z - q.from.z) < 1e-12) passes.push_back(q);
        QVERIFY(passes.size() > 10);
        const double expected = 2 * std::sqrt(2 * 3 * 0.01 - 0.01 * 0.01);
        for (std::size_t i = 1; i < passes.size(); ++i) {
            QVERIFY((passes[i].move.end.y - passes[i].from.y) * (passes[i - 1].move.end.y - passes[i - 1].from.y) < 0);
            const double along = std::hypot(passes[i].from.x - passes[i - 1].from.x, passes[i].from.z - passes[i - 1].from.z);
            QVERIFY(along <= expected + 1e-9);
            QVERIFY(along > 0.95 * expected);
        }
        // The ball touches the face (1 µm), never cuts beyond the pocket, and
        // the last pass's tip is on the floor.
        double worst = -1e9, lowest = 0;
        for (const auto& q : feedPoints(p)) {
            lowest = std::min(lowest, q.z);
            if (q.z < -1e-9) worst = std::max(worst, gouge(ModuleInput{pocket}, ball, q));
        }
        QVERIFY2(worst <= 1e-3, qPrintable(QString::number(worst)));
        QVERIFY(worst > -1e-3);
        QCOMPARE(lowest, -10.0);
    }

    void timeEstimateIsTheHandComputation()
    {
        ToolPath p{{0, 0, 5}, {}};
        p.moves.push_back({MoveKind::Rapid, {0, 0, 1}});
        Move plunge{MoveKind::Feed, {0, 0, -2}};
        plunge.feed = FeedKind::Plunge;
        p.moves.push_back(plunge);
        p.moves.push_back({MoveKind::Feed, {100, 0, -2}});
        p.moves.push_back({MoveKind::ArcCCW, {110, 10, -2}, {100, 10}});  // quarter circle R10
        p.moves.push_back({MoveKind::Rapid, {110, 10, 5}});
        const SpeedsFeeds sf{1000, 500, 100};
        const double expected = (4.0 + 7.0) / 15000 + 3.0 / 100 + (100.0 + 5 * std::numbers::pi) / 500;
        QVERIFY(std::abs(estimateMinutes(p, sf) - expected) < 1e-12);

        // Drilling 40 deep from R = +1 with 10 mm pecks: 41 mm at the feed;
        // rapids 5 -> 1 and back, out of the hole (41), and out and back in
        // for the pecks at 10, 20, 30 and 40 mm below R (2 x 100).
        ToolPath d{{0, 0, 5}, {}};
        Move cycle{MoveKind::DrillCycle, {30, 40, -40}};
        cycle.retractZ = 1;
        cycle.peck = 10;
        d.moves.push_back(cycle);
        const double rapid = 50 + 2 * 4 + 41 + 2 * (10 + 20 + 30 + 40);
        QVERIFY(std::abs(estimateMinutes(d, sf) - (41.0 / 500 + rapid / 15000)) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestToolpathsWalls)
#include "test_toolpaths_walls.moc"
