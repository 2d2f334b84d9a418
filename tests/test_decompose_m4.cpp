// Decomposition of module M4: every combination of U, F, H and taper (0 or
// 5 degrees) on a rectangle and on a non-rectangular convex quad entered
// clockwise, pinned to the step list the spec's formulas give. Expected
// outlines are computed here from the side lines (each side moved along its
// own normal by the total inward distance), not by calling the implementation.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;

namespace {

constexpr double kTol = 1e-6;  // mm: well inside the 1 µm the brief asks for

const TechnologyData kTech{1.0, 0.3, 0.1, 0.2, 0.5};  // alpha1, alpha2, alpha3, beta2, gamma

struct Shape {
    const char* name;
    std::array<Point2, 4> typed;  // as the operator entered them
    std::array<Point2, 4> ccw;    // the same corners counter-clockwise, starting at P1
    double r1, depth;
};

const Shape kShapes[] = {
    {"rectangle", {{{10, 20}, {110, 20}, {110, 80}, {10, 80}}}, {{{10, 20}, {110, 20}, {110, 80}, {10, 80}}}, 8.0, 12.0},
    // Entered clockwise: P1, P4, P3, P2 is the counter-clockwise order.
    {"quad", {{{0, 0}, {-5, 50}, {110, 60}, {90, -10}}}, {{{0, 0}, {90, -10}, {110, 60}, {-5, 50}}}, 6.0, 15.0},
};

// Corners of the polygon whose sides are the given sides moved inward by d:
// side i is the line n_i . x = n_i . p_i + d with n_i its inward unit normal;
// corner i is where side i-1 meets side i.
std::array<Point2, 4> movedSides(const std::array<Point2, 4>& p, double d)
{
    std::array<double, 4> nx{}, ny{}, c{};
    for (int i = 0; i < 4; ++i) {
        const double dx = p[(i + 1) % 4].x - p[i].x, dy = p[(i + 1) % 4].y - p[i].y;
        const double len = std::sqrt(dx * dx + dy * dy);
        nx[i] = -dy / len;
        ny[i] = dx / len;
        c[i] = nx[i] * p[i].x + ny[i] * p[i].y + d;
    }
    std::array<Point2, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 3) % 4;
        const double det = nx[j] * ny[i] - ny[j] * nx[i];
        out[i] = {(c[j] * ny[i] - ny[j] * c[i]) / det, (nx[j] * c[i] - c[j] * nx[i]) / det};
    }
    return out;
}

struct Expected {
    StepKind kind;
    int number;
    MachiningType type;
    bool hasOutline;
    double inward;  // total inward distance of the outline from the typed outline
    double radius;
    double start, cut, taper, wallLeft, floorLeft;
    bool multi;
};

std::vector<Expected> expectedSteps(const Shape& s, int U, int F, int H, double S)
{
    const double T = s.depth, r1 = s.r1, t = std::tan(S * std::numbers::pi / 180.0);
    const TechnologyData& k = kTech;
    std::vector<Expected> e;
    if (H == 0) e.push_back({StepKind::PilotHole, 1, MachiningType::PilotHole, false, 0, 0, 0, T - k.alpha1, 0, 0, k.alpha1, false});
    // Roughing outline: section at depth T - beta2 (moved in by (T - beta2) tan S), then alpha2.
    const double roughIn = (T - k.beta2) * t + k.alpha2;
    if (U == 1 || U == 6 || U == 9)
        e.push_back({StepKind::Roughing, 1, MachiningType::Roughing, true, roughIn, r1 - roughIn, 0, T - k.beta2, 0, k.alpha2, k.beta2, false});
    if (U == 1 || U == 6 || U == 7)
        e.push_back({StepKind::FloorFinishing, 1, MachiningType::FloorFinishing, true, roughIn, r1 - roughIn, T - k.beta2, T, 0, k.alpha2, 0, false});
    if (U == 1 || U == 7 || U == 8) {
        std::vector<std::pair<double, MachiningType>> passes;
        if (F == 3) passes.push_back({k.alpha3, MachiningType::WallSemiFinishing});
        if (F == 3 && S > 0) passes.push_back({k.alpha3 / 2, MachiningType::WallMiddlePass});
        passes.push_back({0.0, MachiningType::WallFinishing});
        int n = 0;
        for (const auto& [left, type] : passes)
            e.push_back({StepKind::WallFinishing, ++n, type, true, left, r1 - left, 0, T, S, left, 0, F == 2});
    }
    return e;
}

}  // namespace

class TestDecomposeM4 : public QObject {
    Q_OBJECT
private slots:
    void everyCombination_data()
    {
        QTest::addColumn<int>("shape");
        QTest::addColumn<int>("U");
        QTest::addColumn<int>("F");
        QTest::addColumn<int>("H");
        QTest::addColumn<double>("taper");
        for (int shape = 0; shape < 2; ++shape)
            for (int U : {1, 6, 7, 8, 9})
                for (int F : {1, 2, 3})
                    for (int H : {0, 9})
                        for (double S : {0.0, 5.0})
                            QTest::addRow("%s U%d F%d H%d S%g", kShapes[shape].name, U, F, H, S) << shape << U << F << H << S;
    }
    void everyCombination()
    {
        QFETCH(int, shape);
        QFETCH(int, U);
        QFETCH(int, F);
        QFETCH(int, H);
        QFETCH(double, taper);
        const Shape& s = kShapes[shape];
        M4Pocket p;
        p.corners = s.typed;
        p.cornerRadius = s.r1;
        p.depth = s.depth;
        p.taper = taper;
        p.toolUse = U;
        p.wallFinish = F;
        p.pilotHole = H;

        const auto steps = decomposeM4(p, kTech, 4);
        const auto expected = expectedSteps(s, U, F, H, taper);
        QCOMPARE(steps.size(), expected.size());
        for (std::size_t i = 0; i < steps.size(); ++i) {
            const Step& a = steps[i];
            const Expected& e = expected[i];
            const QByteArray where = QByteArray("step ") + QByteArray::number(int(i)) + " " + a.label().c_str();
            QVERIFY2(a.kind == e.kind, where);
            QCOMPARE(a.number, e.number);
            QVERIFY2(a.machiningType == e.type, where);
            QCOMPARE(a.unit, 4);
            QCOMPARE(a.module, std::string("M4"));
            QVERIFY2(std::abs(millingOf(a).startDepth - e.start) < kTol, where);
            QVERIFY2(std::abs(millingOf(a).cutDepth - e.cut) < kTol, where);
            QVERIFY2(std::abs(millingOf(a).wallTaper - e.taper) < kTol, where);
            QVERIFY2(std::abs(millingOf(a).wallAllowance - e.wallLeft) < kTol, where);
            QVERIFY2(std::abs(millingOf(a).floorAllowance - e.floorLeft) < kTol, where);
            QCOMPARE(millingOf(a).multiIncision, e.multi);
            QVERIFY(!a.tool && !a.path && !a.minutes);
            QVERIFY(a.payload.getIf<MillingGeometry>());  // an M4 step holds its geometry alone
            QCOMPARE(millingOf(a).outline.has_value(), e.hasOutline);
            if (!e.hasOutline) {
                // Pilot hole at the mean of the four typed corners.
                const double cx = (s.typed[0].x + s.typed[1].x + s.typed[2].x + s.typed[3].x) / 4;
                const double cy = (s.typed[0].y + s.typed[1].y + s.typed[2].y + s.typed[3].y) / 4;
                QVERIFY2(std::abs(millingOf(a).position.x - cx) < kTol && std::abs(millingOf(a).position.y - cy) < kTol, where);
                continue;
            }
            const auto corners = movedSides(s.ccw, e.inward);
            for (std::size_t c = 0; c < 4; ++c)
                QVERIFY2(distance(millingOf(a).outline->corners[c], corners[c]) < kTol, where + " corner " + QByteArray::number(int(c)));
            QVERIFY2(std::abs(millingOf(a).outline->cornerRadius - e.radius) < kTol, where);
            const Point2 mean = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
            QVERIFY2(distance(millingOf(a).position, mean) < kTol, where);
        }
    }

    // The same pins with numbers worked out by hand for the rectangle, so
    // that the test's own offset routine is checked as well.
    void rectangleByHand()
    {
        M4Pocket p;
        p.corners = kShapes[0].typed;
        p.cornerRadius = 8;
        p.depth = 12;
        p.wallFinish = 3;
        const auto steps = decomposeM4(p, kTech, 0);
        QCOMPARE(steps.size(), std::size_t(5));  // pilot, roughing, floor, semi-finish, final
        QCOMPARE(millingOf(steps[0]).position, (Point2{60, 50}));
        QVERIFY(std::abs(millingOf(steps[0]).cutDepth - 11.0) < kTol);
        const Quad& rough = *millingOf(steps[1]).outline;
        QVERIFY(distance(rough.corners[0], {10.3, 20.3}) < kTol && distance(rough.corners[2], {109.7, 79.7}) < kTol);
        QVERIFY(std::abs(rough.cornerRadius - 7.7) < kTol && std::abs(millingOf(steps[1]).cutDepth - 11.8) < kTol);
        QVERIFY(std::abs(millingOf(steps[2]).startDepth - 11.8) < kTol && std::abs(millingOf(steps[2]).cutDepth - 12.0) < kTol);
        QVERIFY(distance(millingOf(steps[3]).outline->corners[1], {109.9, 20.1}) < kTol);
        QVERIFY(std::abs(millingOf(steps[3]).outline->cornerRadius - 7.9) < kTol);
        QCOMPARE(millingOf(steps[4]).outline->corners, kShapes[0].ccw);  // the final pass runs exactly on the typed corners
        QCOMPARE(millingOf(steps[4]).outline->cornerRadius, 8.0);
        QCOMPARE(steps[4].label(), std::string("Wall finishing II"));
    }

    // With a 5 degree taper the roughing outline is the section at the
    // roughing depth less alpha2: 11.8 * tan 5° + 0.3 inward of the top.
    void taperedRoughingClearsTheWallAtItsDeepestPoint()
    {
        M4Pocket p;
        p.corners = kShapes[0].typed;
        p.cornerRadius = 8;
        p.depth = 12;
        p.taper = 5;
        const auto steps = decomposeM4(p, kTech, 0);
        const double inward = 11.8 * 0.087488663525924 + 0.3;
        QVERIFY(distance(millingOf(steps[1]).outline->corners[0], {10 + inward, 20 + inward}) < kTol);
        // Its wall at the roughing depth is alpha2 away from the finished wall there.
        const double wallAtRoughDepth = 10 + 11.8 * std::tan(5 * std::numbers::pi / 180);
        QVERIFY(std::abs(millingOf(steps[1]).outline->corners[0].x - wallAtRoughDepth - 0.3) < kTol);
        QCOMPARE(millingOf(steps.back()).wallTaper, 5.0);
        QCOMPARE(millingOf(steps.back()).outline->corners, kShapes[0].ccw);  // tapered steps carry the top outline
    }
};

QTEST_APPLESS_MAIN(TestDecomposeM4)
#include "test_decompose_m4.moc"
