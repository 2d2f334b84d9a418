// The verification's order of cutting (core/verify/milling_cut.cpp): a run
// of pieces going down is cut from its end, and must leave the very heights
// and findings that cutting every piece in the path's order leaves
// (Options::inPathOrder). Held on generated paths: ramps in zigzag, along
// many short chords and in helices, each into layers cut after them, with
// flat, bull-nose and ball end mills, some gouging the floor (the run is
// then cut in order after all), some with the shank in the stock, on two
// grids; and the order must pay (fewer cells visited on the ramps). The
// rows a sweep looks at are held to an exact oracle of the heights.
#include "modules/m4/m4.h"
#include "verify/verify.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace taiwa;

namespace {

Tool mill(int id, ToolType type, double d, double corner, double flute)
{
    Tool t;
    t.id = id;
    t.type = type;
    t.diameter = d;
    t.cornerRadius = corner;
    t.fluteLength = flute;
    t.stickout = flute + 10;
    t.holder = "HSK63 shrink-fit";
    return t;
}

// One M4 pocket [10, 90] x [10, 70], corner radius 5, `depth` deep, in a
// block 100 x 80 x 30; a step a tool and its path.
Plan pocketPlan(double depth, const std::vector<std::pair<Tool, ToolPath>>& steps)
{
    Plan plan;
    plan.mmJob.stock = {0, 0, 100, 80, 30};
    M4Pocket p;
    p.corners = {Point2{10, 10}, Point2{90, 10}, Point2{90, 70}, Point2{10, 70}};
    p.cornerRadius = 5;
    p.depth = depth;
    p.toolUse = 1;
    plan.mmJob.units.push_back({"pocket", p, {}});
    plan.job = plan.mmJob;
    for (const auto& [tool, path] : steps) {
        plan.tools.push_back(tool);
        Step s;
        s.module = "M4";
        s.kind = StepKind::Roughing;
        editMilling(s).cutDepth = depth;
        s.tool = ToolChoice{tool.id, "test"};
        s.path = path;
        plan.steps.push_back(s);
    }
    return plan;
}

// Layers about `step` apart down to `bottom`, each entered by a ramp of
// `slope` (dz per mm) the generator draws, then cleared by rectangles
// shrinking about the pocket's centre, then up to clear height.
enum class Entry { Zigzag, Chords, Helix };

ToolPath layers(std::mt19937& rng, Entry entry, double step, double bottom, double reach, double slope)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Point2 c{50 + 10 * (u(rng) - 0.5), 40 + 8 * (u(rng) - 0.5)};
    ToolPath p{{c.x, c.y, 5}, {}};
    const auto to = [&](MoveKind k, Point3 e, Point2 centre = {}) { p.moves.push_back({k, e, centre}); };
    double z = 0.5;
    const int n = static_cast<int>(std::ceil(-bottom / step - 1e-9));
    for (int layer = 1; layer <= n; ++layer) {
        const double level = bottom * layer / n;
        to(MoveKind::Rapid, {c.x, c.y, z});
        switch (entry) {
        case Entry::Zigzag: {  // back and forth along a drawn direction
            const double a = u(rng) * std::numbers::pi, half = 4 + 4 * u(rng);
            const Point2 d{half * std::cos(a), half * std::sin(a)};
            for (int side = 1; z > level; side = -side) {
                z = std::max(level, z - slope * 2 * half);
                to(MoveKind::Feed, {c.x + side * d.x, c.y + side * d.y, z});
            }
            to(MoveKind::Feed, {c.x, c.y, z});
            break;
        }
        case Entry::Chords: {  // down a circle of many short chords, then once round at the level
            const double r = 3 + 3 * u(rng), chord = 0.2 + 0.4 * u(rng);
            const int sides = std::max(8, static_cast<int>(2 * std::numbers::pi * r / chord));
            to(MoveKind::Feed, {c.x + r, c.y, z});
            for (int i = 1; z > level || i % sides != 1; ++i) {
                const double a = 2 * std::numbers::pi * i / sides;
                z = std::max(level, z - slope * chord);
                to(MoveKind::Feed, {c.x + r * std::cos(a), c.y + r * std::sin(a), z});
            }
            break;
        }
        case Entry::Helix: {  // half turns of a helix, then a full circle at the level
            const double r = 2 + 4 * u(rng);
            to(MoveKind::Feed, {c.x + r, c.y, z});
            for (int i = 1; z > level; ++i) {
                z = std::max(level, z - slope * std::numbers::pi * r);
                to(MoveKind::ArcCCW, {c.x + (i % 2 ? -r : r), c.y, z}, c);
            }
            const Point3 at = p.moves.back().end;
            to(MoveKind::ArcCCW, at, c);
            break;
        }
        }
        // Rectangles about the centre, out to the walls less the reach
        // (and clear of the pocket's corners, of radius 5).
        const double m = std::max(reach, 5.0) + 0.3;
        for (double w = reach; w < 30; w += 1.2 * reach) {
            const double x0 = std::max(10 + m, c.x - 1.4 * w), x1 = std::min(90 - m, c.x + 1.4 * w);
            const double y0 = std::max(10 + m, c.y - w), y1 = std::min(70 - m, c.y + w);
            for (Point2 q : {Point2{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}) to(MoveKind::Feed, {q.x, q.y, level});
        }
        z = level + 0.5;
        to(MoveKind::Feed, {p.moves.back().end.x, p.moves.back().end.y, z});
        to(MoveKind::Rapid, {p.moves.back().end.x, p.moves.back().end.y, 5});
    }
    return p;
}

}  // namespace

class TestVerifyOrder : public QObject {
    Q_OBJECT

private slots:
    void aRunCutFromItsEndLeavesWhatThePathsOrderLeaves_data();
    void aRunCutFromItsEndLeavesWhatThePathsOrderLeaves();
    void theOrderPaysOnRamps();
    void aRowIsSkippedOnlyWhereNoSweepCanLowerIt();
};

void TestVerifyOrder::aRunCutFromItsEndLeavesWhatThePathsOrderLeaves_data()
{
    QTest::addColumn<int>("seed");
    QTest::addColumn<int>("entry");
    QTest::addColumn<int>("tool");
    QTest::addColumn<bool>("gouges");
    QTest::addColumn<double>("resolution");
    int seed = 1;
    for (int entry = 0; entry < 3; ++entry)
        for (int tool = 0; tool < 4; ++tool)
            for (const bool gouges : {false, true})
                for (const double res : {0.15, 0.08})
                    QTest::addRow("entry %d tool %d%s at %g", entry, tool, gouges ? " gouging" : "", res)
                        << seed++ << entry << tool << gouges << res;
}

// Flat D10, bull-nose D12 r2, ball D8, and a flat D6 whose 8 mm flutes
// leave the shank in the stock below 8 mm (its runs are cut in order).
Tool toolOf(int k)
{
    switch (k) {
    case 0: return mill(1, ToolType::FlatEndMill, 10, 0, 25);
    case 1: return mill(1, ToolType::FlatEndMill, 12, 2, 25);
    case 2: return mill(1, ToolType::BallEndMill, 8, 4, 25);
    default: return mill(1, ToolType::FlatEndMill, 6, 0, 8);
    }
}

void TestVerifyOrder::aRunCutFromItsEndLeavesWhatThePathsOrderLeaves()
{
    QFETCH(int, seed);
    QFETCH(int, entry);
    QFETCH(int, tool);
    QFETCH(bool, gouges);
    QFETCH(double, resolution);
    std::mt19937 rng(static_cast<unsigned>(seed));
    const Tool t = toolOf(tool);
    const double depth = 10;
    // A gouging path goes 0.3 mm below the floor on its last layer.
    const double bottom = gouges ? -(depth + 0.3) : -depth + 0.2;
    const ToolPath path = layers(rng, static_cast<Entry>(entry), 2.5, bottom, t.diameter / 2, 0.05 + 0.1 * (seed % 3));
    // A second step finishes with another tool over what the first left.
    const ToolPath second = layers(rng, static_cast<Entry>((entry + 1) % 3), 5, -depth + 0.1, 3, 0.08);
    const Plan plan = pocketPlan(depth, {{t, path}, {mill(2, ToolType::BallEndMill, 6, 3, 25), second}});

    verify::Options inOrder;
    inOrder.resolution = resolution;
    inOrder.threads = 2;
    inOrder.inPathOrder = true;
    verify::Options fast = inOrder;
    fast.inPathOrder = false;
    const verify::Report a = verify::verifyPlan(plan, inOrder);
    const verify::Report b = verify::verifyPlan(plan, fast);

    QCOMPARE(b.columns, a.columns);
    QCOMPARE(b.rows, a.rows);
    const auto show = [](const verify::Report& r) {
        QString text;
        for (const verify::Finding& f : r.findings)
            text += QString("[k%1 s%2 m%3 %4 size %5 area %6 at %7 %8 %9] ").arg(int(f.kind)).arg(f.step).arg(f.move).arg(QString::fromStdString(f.part)).arg(f.size).arg(f.area).arg(f.position.x).arg(f.position.y).arg(f.position.z);
        return text;
    };
    if (b.findings.size() != a.findings.size()) qInfo("in order: %s\nfast: %s", qPrintable(show(a)), qPrintable(show(b)));
    QCOMPARE(b.findings.size(), a.findings.size());
    for (std::size_t i = 0; i < a.findings.size(); ++i) QVERIFY2(b.findings[i] == a.findings[i], qPrintable(QString::number(i)));
    const bool gouged = std::any_of(a.findings.begin(), a.findings.end(),
                                    [](const verify::Finding& f) { return f.kind == verify::FindingKind::Gouge; });
    QCOMPARE(gouged, gouges);  // the generator gouges where it says it does, and only there
    const std::vector<float>& ha = a.stock.heights();
    const std::vector<float>& hb = b.stock.heights();
    QCOMPARE(hb.size(), ha.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < ha.size(); ++i) differ += ha[i] != hb[i];
    QCOMPARE(differ, std::size_t{0});
    QCOMPARE(b.removed.size(), a.removed.size());
    for (std::size_t k = 0; k < a.removed.size(); ++k) QVERIFY(std::abs(b.removed[k] - a.removed[k]) <= 1e-9 * (1 + a.removed[k]));
    QVERIFY(b.cellVisits <= a.cellVisits);
}

// Ramps into layers: cut from their ends they visit far fewer cells.
void TestVerifyOrder::theOrderPaysOnRamps()
{
    double inOrder = 0, fast = 0;
    for (int entry = 0; entry < 3; ++entry) {
        std::mt19937 rng(static_cast<unsigned>(100 + entry));
        const Tool t = toolOf(0);
        const Plan plan = pocketPlan(10, {{t, layers(rng, static_cast<Entry>(entry), 2.5, -9.8, 5, 0.05)}});
        verify::Options o;
        o.resolution = 0.05;
        o.threads = 2;
        o.inPathOrder = true;
        inOrder += verify::verifyPlan(plan, o).cellVisits;
        o.inPathOrder = false;
        fast += verify::verifyPlan(plan, o).cellVisits;
    }
    qInfo("cells visited: %.3g in the path's order, %.3g with runs cut from their ends", inOrder, fast);
    QVERIFY(fast < 0.6 * inOrder);
}

// A row of cells is handed on only above the cutting surface's lowest over
// it (milling_cut.cpp). Against an oracle that knows nothing of rows, tiles
// or order: random walks of short level lines and arcs with a ball and a
// bull-nose, each cell's height the least of its stock top and, for every
// move within reach, the move's Z plus the cutter's height at the cell's
// exact distance (model/contour.h). Every cell must agree to the grid's
// float rounding; skipping a row a sweep lowers leaves cells higher by up
// to the cutter's height there.
void TestVerifyOrder::aRowIsSkippedOnlyWhereNoSweepCanLowerIt()
{
    for (const int tool : {1, 2}) {
        const Tool t = toolOf(tool);
        const double R = t.diameter / 2, corner = t.cornerRadius, flat = R - corner;
        const auto height = [&](double d) { return d <= flat ? 0.0 : corner - std::sqrt(std::max(0.0, corner * corner - (d - flat) * (d - flat))); };
        std::mt19937 rng(static_cast<unsigned>(7 + tool));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        ToolPath path{{50, 40, 5}, {}};
        std::vector<std::pair<ContourSegment, double>> level;  // every feed move as a plane segment at its Z
        Point2 at{50, 40};
        for (const double z : {-1.0, -2.5, -4.0}) {
            path.moves.push_back({MoveKind::Rapid, {at.x, at.y, 5}});
            path.moves.push_back({MoveKind::Feed, {at.x, at.y, z}});
            for (int k = 0; k < 120; ++k) {
                const double a = 2 * std::numbers::pi * u(rng), len = 0.1 + 1.9 * u(rng);
                Point2 to{std::clamp(at.x + len * std::cos(a), 25.0, 75.0), std::clamp(at.y + len * std::sin(a), 22.0, 58.0)};
                if (k % 10 == 9) {  // now and then a half circle about a point beside the walk
                    const Point2 c{at.x + 1.5 * std::cos(a), at.y + 1.5 * std::sin(a)};
                    to = c + (c - at);
                    if (to.x < 25 || to.x > 75 || to.y < 22 || to.y > 58) continue;
                    path.moves.push_back({MoveKind::ArcCCW, {to.x, to.y, z}, c});
                    level.push_back({ContourSegment::arc(at, to, c, true), z});
                } else {
                    path.moves.push_back({MoveKind::Feed, {to.x, to.y, z}});
                    level.push_back({ContourSegment::line(at, to), z});
                }
                at = to;
            }
        }
        path.moves.push_back({MoveKind::Rapid, {at.x, at.y, 5}});
        const Plan plan = pocketPlan(10, {{t, path}});
        verify::Options o;
        o.resolution = 0.1;
        o.threads = 2;
        const verify::Report r = verify::verifyPlan(plan, o);
        for (const verify::Finding& f : r.findings)  // (material is left: the walk clears no pocket)
            QVERIFY(f.kind != verify::FindingKind::Gouge && f.kind != verify::FindingKind::Collision);
        std::size_t differ = 0, lowered = 0;
        for (int j = 0; j < r.rows; ++j)
            for (int i = 0; i < r.columns; ++i) {
                const Point2 p = r.stock.centre(i, j);
                double h = 0.0;
                for (const auto& [seg, z] : level) {
                    const double d = distance(p, seg.nearest(p));
                    if (d <= R) h = std::min(h, z + height(d));
                }
                lowered += h < 0.0;
                differ += std::abs(r.stock.heights()[r.stock.indexOf(i, j)] - h) > 1e-4;
            }
        QVERIFY(lowered > 10000);
        QCOMPARE(differ, std::size_t{0});
    }
}

QTEST_GUILESS_MAIN(TestVerifyOrder)
#include "test_verify_order.moc"
