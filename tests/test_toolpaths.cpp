// Pocket tool paths on hand-made steps: roughing and floor finishing start
// and end at safe height, keep the tool centre inside the outline shrunk by
// the tool radius (1 µm, arcs sampled), cut equal layers of at most gamma x D
// ending exactly at the cut depth, clear every layer completely (Clipper),
// mill climb, enter through the pilot hole or on a ramp, and keep the
// outermost ring exactly on the offset with its corner arcs.
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/m4/m4.h"
#include "paths/coverage.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "test_toolpaths_support.h"
#include "model/turn_path.h"

#include <QDir>
#include <QtTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace taiwa;
using namespace taiwa::test;

Q_DECLARE_METATYPE(taiwa::Quad)

namespace {

const PathParameters kParams{};

// The distinct depths (negative Z) at which the path cuts in the plane:
// the ends of horizontal cutting moves.
std::vector<double> layerZs(const ToolPath& p)
{
    std::set<double> zs;
    for (const auto& q : cuttingPieces(p))
        if (q.move.feed == FeedKind::Cut && std::abs(q.from.z - q.move.end.z) < 1e-12) zs.insert(q.move.end.z);
    return {zs.begin(), zs.end()};
}

// The part of the path that cuts at height z.
ToolPath atHeight(const ToolPath& p, double z)
{
    ToolPath layer{p.start, {}};
    for (const auto& q : cuttingPieces(p)) {
        if (std::abs(q.move.end.z - z) > 1e-9 || std::abs(q.from.z - z) > 1e-9) continue;
        if (layer.moves.empty() || !(layer.moves.back().end == q.from)) layer.moves.push_back({MoveKind::Rapid, q.from});
        layer.moves.push_back(q.move);
    }
    return layer;
}

// No rapid ends below the height where the step's material begins.
bool rapidsStayInAir(const ToolPath& p, const Step& s)
{
    return std::all_of(p.moves.begin(), p.moves.end(), [&](const Move& m) {
        return m.kind != MoveKind::Rapid || m.end.z >= -millingOf(s).startDepth + kParams.clearance - 1e-12;
    });
}

Quad parallelogram60() { return {{{{0, 0}, {80, 0}, {100, 20 * std::sqrt(3.0)}, {20, 20 * std::sqrt(3.0)}}}, 4.0}; }

}  // namespace

class TestToolpaths : public QObject {
    Q_OBJECT
private slots:
    void moveEstimatesFollowThePaths()
    {
        // The budget's estimate of every sample step is of the order of the
        // moves the path really has: never below a quarter, at most 20 times.
        for (const QString& f : QDir(test::sourcePath("resources/samples")).entryList({"*.taiwa"})) {
            const Job job = *readJobFile(test::sourcePath("resources/samples/" + f).toStdString()).job;
            const Plan plan = planJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY2(plan.ok(), qPrintable(f));
            for (const Step& s : plan.steps) {
                const double estimate = estimateMoves(s, *plan.tool(s.tool->toolId), plan.technology, {});
                const double real = static_cast<double>(turnOf(s) ? turnOf(s)->path.moves.size() : s.path->moves.size());
                QVERIFY2(estimate >= real / 4 && estimate <= real * 20 + 50,
                         qPrintable(QString("%1 %2: %3 estimated, %4 real").arg(f, QString::fromStdString(s.label())).arg(estimate).arg(real)));
            }
        }
    }

    void aJobBeyondTheMoveBudgetIsRefusedBeforeAnyPath()
    {
        // Sixteen 2 m pockets whose 1.4 mm corners take a 2 mm end mill, at
        // γ 0.05: 50 layers of 1,100 rings each, about 11 million moves.
        Job j;
        j.stock = {0, 0, 10000, 10000, 30};
        j.technology.gamma = 0.05;
        for (int i = 0; i < 16; ++i) {
            M4Pocket p;
            const double x = 400 + (i % 4) * 2400, y = 400 + (i / 4) * 2400;
            p.corners = {Point2{x, y}, Point2{x + 2000, y}, Point2{x + 2000, y + 2000}, Point2{x, y + 2000}};
            p.cornerRadius = 1.4;
            p.depth = 5;
            p.toolUse = 9;
            j.units.push_back({"big", p});
        }
        QVERIFY(!hasErrors(checkJob(j, TechnologyTable::builtIn(), defaultToolLibrary())));
        const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(!plan.ok());
        QVERIFY(std::all_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return !s.path; }));
        const auto& d = plan.diagnostics.back();
        QVERIFY2(d.message.find("more than the 1e+07 a job may have") != std::string::npos, d.message.c_str());
    }

    void roughingStaysInsideAndClearsEveryLayer_data()
    {
        QTest::addColumn<Quad>("outline");
        QTest::addColumn<double>("diameter");
        QTest::addColumn<double>("start");
        QTest::newRow("rectangle") << rectangle(100, 60, 5.7) << 10.0 << 0.0;
        QTest::newRow("thin 12 x 100") << rectangle(12, 100, 3) << 6.0 << 0.0;
        QTest::newRow("slot a hair wider than the tool") << rectangle(100, 10.2, 5) << 10.0 << 0.0;
        QTest::newRow("square, tight corners r = R") << rectangle(40, 40, 3) << 6.0 << 0.0;
        QTest::newRow("parallelogram 60 deg") << parallelogram60() << 8.0 << 0.0;
        QTest::newRow("irregular convex quad") << Quad{{{{0, 0}, {70, 8}, {62, 50}, {9, 41}}}, 3.5} << 6.0 << 0.0;
        QTest::newRow("M2D layer below air") << rectangle(90, 50, 4) << 8.0 << 4.2;
    }
    void roughingStaysInsideAndClearsEveryLayer()
    {
        QFETCH(Quad, outline);
        QFETCH(double, diameter);
        QFETCH(double, start);
        const Tool tool = makeTool(ToolType::FlatEndMill, diameter);
        TechnologyData tech;
        tech.gamma = 0.5;
        const double cut = 11.8;
        const Step s = makePocketStep(StepKind::Roughing, outline, start, cut);
        const ToolPath p = makeToolPath(s, tool, tech, kParams);
        QCOMPARE(p.start.z, kParams.safeZ);
        QCOMPARE(endOf(p).z, kParams.safeZ);
        QCOMPARE(p.moves.front().kind, MoveKind::Rapid);
        QCOMPARE(p.moves.front().end.z, -start + kParams.clearance);  // air above the start depth
        QVERIFY(rapidsStayInAir(p, s));
        QVERIFY2(worstOutside(outline, tool.radius(), p) <= 1e-6, qPrintable(QString::number(worstOutside(outline, tool.radius(), p))));
        // Feeds never start above the clearance plane of the step's material.
        for (const auto& q : feedPoints(p)) QVERIFY(q.z <= -start + kParams.clearance + 1e-12);

        // Equal layers of at most gamma x D from the start depth, the last
        // exactly at the cut depth.
        const auto zs = layerZs(p);
        const int n = static_cast<int>(std::ceil((cut - start) / (tech.gamma * diameter) - 1e-9));
        QCOMPARE(static_cast<int>(zs.size()), n);
        QCOMPARE(zs.front(), -cut);
        double above = -start;
        for (auto it = zs.rbegin(); it != zs.rend(); ++it) {
            QVERIFY(above - *it <= tech.gamma * diameter + 1e-9);
            QVERIFY(std::abs((above - *it) - (cut - start) / n) < 1e-9);
            above = *it;
            // Every layer clears the whole outline (within 1 µm of it).
            const double left = paths::uncutArea(outline, atHeight(p, *it), tool.radius());
            QVERIFY2(left < 1e-3, qPrintable(QString("layer at %1 leaves %2 mm2").arg(*it).arg(left)));
        }
    }

    // A pocket's layer is proved once per shape and the answer moved to the
    // other places the shape is used. A 30° parallelogram at a wide step-over
    // needs cleanup visits in its acute corners: the moved pocket's path is
    // the original's moved (to rounding), its visits land in its own corners
    // (the layer is cleared), and it is the path a fresh proof gives.
    void aRepeatedPocketGetsTheSamePathAsAFreshOne()
    {
        TechnologyData wide;
        wide.stepOver = 0.9;
        const Quad parallelogram{{{{0, 0}, {90, 0}, {141.96, 30}, {51.96, 30}}}, 4.0};
        const Point2 shift{137.25, -61.5};
        Quad moved = parallelogram;
        for (auto& c : moved.corners) c = c + shift;
        const Tool tool = makeTool(ToolType::FlatEndMill, 8);
        const auto path = [&](const Quad& q) { return makeToolPath(makePocketStep(StepKind::Roughing, q, 0, 2), tool, wide, kParams); };

        forgetProvedLayers();
        const ToolPath fresh = path(moved);
        forgetProvedLayers();
        const ToolPath original = path(parallelogram);  // proves the shape
        const ToolPath remembered = path(moved);         // and this one reuses it
        QVERIFY(fresh == remembered);
        QVERIFY(paths::uncutArea(moved, atHeight(remembered, -2), 4) < 1e-3);
        QCOMPARE(remembered.moves.size(), original.moves.size());
        for (std::size_t i = 0; i < original.moves.size(); ++i) {
            const Point3 a = original.moves[i].end, b = remembered.moves[i].end;
            QVERIFY2(std::abs(b.x - a.x - shift.x) < 1e-9 && std::abs(b.y - a.y - shift.y) < 1e-9 && std::abs(b.z - a.z) < 1e-12,
                     qPrintable(QString("move %1").arg(i)));
        }
    }

    // The proof is not vacuous: leaving out the last ring leaves stock.
    void coverageProofDetectsUncutStock()
    {
        const Quad outline = rectangle(60, 40, 4);
        const ToolPath p = makeToolPath(makePocketStep(StepKind::Roughing, outline, 0, 2), makeTool(ToolType::FlatEndMill, 8),
                                        TechnologyData{}, kParams);
        ToolPath layer = atHeight(p, -2);
        QVERIFY(paths::uncutArea(outline, layer, 4) < 1e-3);
        QVERIFY(paths::uncutArea(outline, layer, 3.5) > 1.0);  // a smaller tool on the same path leaves the walls
        layer.moves.resize(layer.moves.size() / 2);
        QVERIFY(paths::uncutArea(outline, layer, 4) > 1.0);
    }

    void outermostRingIsExactlyTheOffsetWithCornerArcs()
    {
        const Quad outline = rectangle(100, 60, 5.7);
        const ToolPath p = makeToolPath(makePocketStep(StepKind::Roughing, outline, 0, 3), makeTool(ToolType::FlatEndMill, 10),
                                        TechnologyData{}, kParams);
        QVERIFY(std::abs(worstOutside(outline, 5, p)) < 1e-9);  // touches the outline shrunk by R
        int cornerArcs = 0;
        for (const auto& q : cuttingPieces(p))
            if (q.move.kind == MoveKind::ArcCCW && std::abs(distance({q.from.x, q.from.y}, q.move.centre) - 0.7) < 1e-9 &&
                std::abs(arcSweep(q.from, q.move) - std::numbers::pi / 2) < 1e-9)
                ++cornerArcs;
        QCOMPARE(cornerArcs, 4);  // r - R = 0.7, quarter arcs, not chords
    }

    // With an M3 spindle the wall must be on the tool's right: the ring
    // along the wall runs counter-clockwise; conventional milling reverses it.
    void roughingIsClimbMilled()
    {
        const Quad outline = parallelogram60();
        const Step s = makePocketStep(StepKind::Roughing, outline, 0, 4);
        const Tool tool = makeTool(ToolType::FlatEndMill, 8);
        const WallSides climb = wallSides(makeToolPath(s, tool, TechnologyData{}, kParams), outline, 4);
        QVERIFY(climb.right >= 4);  // four sides (r = R: sharp centre corners)
        QCOMPARE(climb.left, 0);
        PathParameters conventional;
        conventional.climb = false;
        const WallSides up = wallSides(makeToolPath(s, tool, TechnologyData{}, conventional), outline, 4);
        QVERIFY(up.left >= 4);
        QCOMPARE(up.right, 0);
    }

    void roughingPlungesIntoThePilotHoleOtherwiseRamps()
    {
        const Quad outline = rectangle(80, 50, 4);
        const Tool tool = makeTool(ToolType::FlatEndMill, 8);
        Step s = makePocketStep(StepKind::Roughing, outline, 0, 9);
        editMilling(s).holeDiameter = 8;
        const auto count = [](const ToolPath& p, FeedKind k) {
            return std::count_if(p.moves.begin(), p.moves.end(), [&](const Move& m) { return isCut(m) && m.feed == k; });
        };
        ToolPath p = makeToolPath(s, tool, TechnologyData{}, kParams);
        QCOMPARE(count(p, FeedKind::Ramp), 0);
        for (const auto& q : cuttingPieces(p))
            if (q.move.feed == FeedKind::Plunge) {
                QCOMPARE(q.move.end.x, millingOf(s).position.x);
                QCOMPARE(q.move.end.y, millingOf(s).position.y);
            }
        QCOMPARE(count(p, FeedKind::Plunge), 3);  // one per layer (9 mm, 4 mm layers)

        // A hole narrower than the tool, or none: a helix at the ramp angle.
        for (const double hole : {6.0, 0.0}) {
            editMilling(s).holeDiameter = hole;
            p = makeToolPath(s, tool, TechnologyData{}, kParams);
            QCOMPARE(count(p, FeedKind::Plunge), 0);
            QVERIFY(count(p, FeedKind::Ramp) > 3);
            for (const auto& q : cuttingPieces(p)) {
                if (q.move.feed != FeedKind::Ramp || q.move.kind == MoveKind::Feed) continue;
                const double run = std::abs(arcSweep(q.from, q.move)) * distance({q.from.x, q.from.y}, q.move.centre);
                QVERIFY(q.from.z - q.move.end.z <= run * std::tan(3 * std::numbers::pi / 180) + 1e-9);
            }
        }
        // Floor finishing never uses the hole (roughing removed it).
        s.kind = StepKind::FloorFinishing;
        editMilling(s).holeDiameter = 8;
        QVERIFY(count(makeToolPath(s, tool, TechnologyData{}, kParams), FeedKind::Ramp) > 0);
    }

    // A slot too narrow for a helix: ramp along its centre line.
    void narrowSlotRampsAlongItsLine()
    {
        const Quad outline = rectangle(100, 10.2, 5);
        const ToolPath p = makeToolPath(makePocketStep(StepKind::Roughing, outline, 0, 5), makeTool(ToolType::FlatEndMill, 10),
                                        TechnologyData{}, kParams);
        int ramps = 0;
        for (const auto& q : cuttingPieces(p)) {
            if (q.move.feed != FeedKind::Ramp) continue;
            ++ramps;
            QCOMPARE(q.move.kind, MoveKind::Feed);
            QVERIFY(std::abs(q.move.end.y - 5.1) < 1e-3);
            const double run = std::hypot(q.move.end.x - q.from.x, q.move.end.y - q.from.y);
            QVERIFY(q.from.z - q.move.end.z <= run * std::tan(3 * std::numbers::pi / 180) + 1e-9);
        }
        QVERIFY(ramps >= 2);
        QVERIFY(worstOutside(outline, 5, p) <= 1e-6);
    }

    void floorFinishingReachesTheFloorAndCoversIt()
    {
        const Quad outline = rectangle(70, 45, 4.7);
        const Tool tool = makeTool(ToolType::FlatEndMill, 8);
        const Step s = makePocketStep(StepKind::FloorFinishing, outline, 9.8, 10);
        const ToolPath p = makeToolPath(s, tool, TechnologyData{}, kParams);
        QCOMPARE(p.start.z, kParams.safeZ);
        QCOMPARE(endOf(p).z, kParams.safeZ);
        QCOMPARE(p.moves.front().end.z, -9.8 + kParams.clearance);  // rapid through the roughed air
        QVERIFY(rapidsStayInAir(p, s));
        const auto zs = layerZs(p);
        QCOMPARE(static_cast<int>(zs.size()), 1);
        QCOMPARE(zs.front(), -10.0);
        double lowest = 0;
        for (const auto& q : feedPoints(p)) lowest = std::min(lowest, q.z);
        QCOMPARE(lowest, -10.0);
        QVERIFY(worstOutside(outline, 4, p) <= 1e-6);
        QVERIFY(paths::uncutArea(outline, atHeight(p, -10), 4) < 1e-3);
        // Finer than roughing: more (and shorter-spaced) rings on the same outline.
        const Step rough = makePocketStep(StepKind::Roughing, outline, 9.8, 10);
        QVERIFY(cuttingPieces(p).size() > cuttingPieces(makeToolPath(rough, tool, TechnologyData{}, kParams)).size());
    }

    // A slot whose corner radius is half its width: its innermost ring
    // collapses to the centre line, where the corner arcs once shrank to
    // 0.1 µm and came out as "G3 X92 Y30 I0 J0" (a zero-radius full circle
    // to the controller). No arc of any step may have a radius or a length
    // below 1 µm: such an arc is a line, or nothing.
    void slotArcsAreNeverDegenerate_data()
    {
        QTest::addColumn<Quad>("outline");
        QTest::addColumn<double>("diameter");
        const Quad slot{{{{20, 22}, {100, 22}, {100, 38}, {20, 38}}}, 8.0};
        // 80 x 16 turned by atan(3/4): the corners are exact decimals.
        const Quad turned{{{{30, 20}, {94, 68}, {84.4, 80.8}, {20.4, 32.8}}}, 8.0};
        for (const double d : {6.0, 8.0, 10.0, 12.0}) {
            QTest::newRow(qPrintable(QString("slot 80 x 16 r 8, D%1").arg(d))) << slot << d;
            QTest::newRow(qPrintable(QString("turned slot, D%1").arg(d))) << turned << d;
        }
        QTest::newRow("slot 12 x 100 r 6, D6") << rectangle(12, 100, 6) << 6.0;
        QTest::newRow("slot 100 x 10.2 r 5.1, D10") << rectangle(100, 10.2, 5.1) << 10.0;
    }
    void slotArcsAreNeverDegenerate()
    {
        QFETCH(Quad, outline);
        QFETCH(double, diameter);
        const Tool tool = makeTool(ToolType::FlatEndMill, diameter);
        TechnologyData tech;
        tech.gamma = 0.5;
        std::vector<std::pair<QString, Step>> steps;
        Step rough = makePocketStep(StepKind::Roughing, outline, 0, 9.8);
        steps.push_back({"roughing, helix or ramp", rough});
        editMilling(rough).holeDiameter = diameter;
        steps.push_back({"roughing, pilot hole", rough});
        steps.push_back({"floor finishing", makePocketStep(StepKind::FloorFinishing, outline, 9.8, 10)});
        Step wall = makePocketStep(StepKind::WallFinishing, outline, 0, 10);
        steps.push_back({"wall finishing", wall});
        editMilling(wall).multiIncision = true;
        steps.push_back({"wall finishing, F = 2", wall});
        for (const auto& [name, step] : steps) {
            const ToolPath p = makeToolPath(step, tool, tech, kParams);
            int arcs = 0;
            for (const auto& q : cuttingPieces(p)) {
                if (q.move.kind == MoveKind::Feed) continue;
                ++arcs;
                const double r = distance({q.from.x, q.from.y}, q.move.centre);
                const double run = std::abs(arcSweep(q.from, q.move)) * r;
                // No arc turns more than half a turn either (a corner turns
                // less, a helix runs in halves): a collapsed side must not send
                // a corner arc the long way round.
                QVERIFY2(r >= 1e-3 && run >= 1e-3 && std::abs(arcSweep(q.from, q.move)) <= std::numbers::pi + 1e-9,
                         qPrintable(QString("%1: arc to (%2, %3) of radius %4 mm and length %5 mm")
                                        .arg(name).arg(q.move.end.x).arg(q.move.end.y).arg(r).arg(run)));
            }
            QVERIFY2(arcs > 0, qPrintable(name + ": no arcs at all"));
            QVERIFY2(worstOutside(outline, tool.radius(), p) <= 1e-6, qPrintable(name));
        }
    }

    void refusesWhatTheChecksRefuse()
    {
        const Tool tool = makeTool(ToolType::FlatEndMill, 10);
        QVERIFY_THROWS_EXCEPTION(std::logic_error,
            makeToolPath(makePocketStep(StepKind::Roughing, rectangle(50, 40, 4), 0, 5), tool, TechnologyData{}, kParams));
        QVERIFY_THROWS_EXCEPTION(std::logic_error,
            makeToolPath(makePocketStep(StepKind::Roughing, rectangle(50, 9, 4.5), 0, 5), tool, TechnologyData{}, kParams));
    }
};

QTEST_APPLESS_MAIN(TestToolpaths)
#include "test_toolpaths.moc"
