// Decomposition of module M2D: the roughing layer count with round-half-up
// at the .5 boundary (both sides, and a ratio that lands just below .5 in
// floating point), the reset layer depth, every layer's outline following the
// wall slope with alpha2 left, theta2 defaulting to theta1, and the pilot,
// floor, wall and inclined-face steps. Expectations come from the spec's
// formulas written out here.
#include "modules/inclined_face.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;

namespace {

constexpr double kTol = 1e-6;  // mm


M2DPocket pocket(double depth, double theta1, std::optional<double> theta2 = std::nullopt)
{
    M2DPocket p;
    p.corner = {30, 40};
    p.lengthX = 80;
    p.lengthY = 50;
    p.depth = depth;
    p.theta1 = theta1;
    p.theta2 = theta2;
    p.cornerRadius = 5;
    p.scallop = 0.02;
    return p;
}

TechnologyData tech(double beta2, double gamma) { return {1.0, 0.3, 0.1, beta2, gamma}; }

std::vector<Step> ofKind(const std::vector<Step>& steps, StepKind k)
{
    std::vector<Step> out;
    for (const auto& s : steps)
        if (s.kind == k) out.push_back(s);
    return out;
}

}  // namespace

class TestDecomposeM2D : public QObject {
    Q_OBJECT
private slots:
    void layerCountRoundsHalfUp_data()
    {
        QTest::addColumn<double>("depth");
        QTest::addColumn<double>("beta2");
        QTest::addColumn<double>("gamma");
        QTest::addColumn<double>("diameter");
        QTest::addColumn<int>("layers");
        // (T - beta2) / (gamma D):
        QTest::newRow("exactly 2.5") << 2.7 << 0.2 << 0.5 << 2.0 << 3;
        QTest::newRow("just above 2.5") << 2.701 << 0.2 << 0.5 << 2.0 << 3;
        QTest::newRow("just below 2.5") << 2.699 << 0.2 << 0.5 << 2.0 << 2;
        // 2.05 - 0.3 = 1.7499999999999998 in doubles: the ratio is 3.4999999999999996.
        QTest::newRow("3.5 landing below in doubles") << 2.05 << 0.3 << 0.5 << 1.0 << 4;
        QTest::newRow("2.4 rounds down") << 2.6 << 0.2 << 0.5 << 2.0 << 2;
        QTest::newRow("at least one layer") << 0.5 << 0.2 << 0.5 << 10.0 << 1;
        QTest::newRow("many layers") << 30.0 << 0.2 << 0.3 << 6.0 << 17;  // 29.8 / 1.8 = 16.56
    }
    void layerCountRoundsHalfUp()
    {
        QFETCH(double, depth);
        QFETCH(double, beta2);
        QFETCH(double, gamma);
        QFETCH(double, diameter);
        QFETCH(int, layers);
        M2DPocket p = pocket(depth, 10);
        p.pilotHole = 9;
        p.toolUse = 9;
        const auto steps = decomposeM2D(p, tech(beta2, gamma), diameter, 0);
        QCOMPARE(int(steps.size()), layers);
        // The layer depth is reset to (T - beta2) / n; layer k cuts (k-1)T'..kT'.
        const double layer = (depth - beta2) / layers;
        for (int k = 1; k <= layers; ++k) {
            const Step& s = steps[std::size_t(k - 1)];
            QVERIFY(s.kind == StepKind::Roughing && s.number == k);
            QVERIFY2(std::abs(millingOf(s).startDepth - (k - 1) * layer) < kTol, qPrintable(QString::number(k)));
            QVERIFY2(std::abs(millingOf(s).cutDepth - k * layer) < kTol, qPrintable(QString::number(k)));
        }
        QCOMPARE(millingOf(steps.back()).cutDepth, depth - beta2);  // the last layer ends exactly at T - beta2
    }

    void layersFollowTheWallSlopeLeavingAlpha2()
    {
        const M2DPocket p = pocket(12, 20, 35);
        const TechnologyData t = tech(0.2, 0.5);
        const auto rough = ofKind(decomposeM2D(p, t, 6.0, 2), StepKind::Roughing);
        QCOMPARE(rough.size(), std::size_t(4));  // 11.8 / 3 = 3.93 -> 4 layers of 2.95
        for (const auto& s : rough) {
            const double z = millingOf(s).cutDepth;
            const double left = 30 + z * tanDeg(20) + 0.3, right = 110 - z * tanDeg(35) - 0.3;
            const std::array<Point2, 4> want{{{left, 40.3}, {right, 40.3}, {right, 89.7}, {left, 89.7}}};
            for (std::size_t c = 0; c < 4; ++c) QVERIFY(distance(millingOf(s).outline->corners[c], want[c]) < kTol);
            QVERIFY(std::abs(millingOf(s).outline->cornerRadius - 4.7) < kTol);
            QVERIFY(std::abs(millingOf(s).wallAllowance - 0.3) < kTol);
            QVERIFY(std::abs(millingOf(s).floorAllowance - (12 - z)) < kTol);
            QCOMPARE(s.module, std::string("M2D"));
            QCOMPARE(s.unit, 2);
        }
        // Deeper layers are narrower: the stairs step inward with the walls.
        QVERIFY(millingOf(rough[3]).outline->corners[0].x > millingOf(rough[0]).outline->corners[0].x + 2.9 * 3 * tanDeg(20) - kTol);
    }

    void theta2DefaultsToTheta1()
    {
        const Quad q = m2dCrossSection(pocket(10, 15), 10);
        QVERIFY(std::abs(q.corners[0].x - (30 + 10 * tanDeg(15))) < kTol);
        QVERIFY(std::abs(q.corners[1].x - (110 - 10 * tanDeg(15))) < kTol);
        const Quad q2 = m2dCrossSection(pocket(10, 15, 30), 10);
        QVERIFY(std::abs(q2.corners[1].x - (110 - 10 * tanDeg(30))) < kTol);
        QVERIFY(std::abs(q2.corners[2].y - 90) < kTol && q2.cornerRadius == 5);
    }

    void standardStepsInOrder()
    {
        const M2DPocket p = pocket(12, 20, 35);
        const TechnologyData t = tech(0.2, 0.5);
        const auto steps = decomposeM2D(p, t, 6.0, 0);
        QCOMPARE(steps.size(), std::size_t(1 + 4 + 1 + 1 + 2));
        const double floorLeft = 30 + 12 * tanDeg(20), floorRight = 110 - 12 * tanDeg(35);

        const Step& pilot = steps[0];
        QVERIFY(pilot.kind == StepKind::PilotHole && pilot.machiningType == MachiningType::PilotHole);
        QVERIFY(distance(millingOf(pilot).position, {(floorLeft + floorRight) / 2, 65}) < kTol);
        QVERIFY(std::abs(millingOf(pilot).cutDepth - 11) < kTol && millingOf(pilot).startDepth == 0);

        const Step& floor = steps[5];
        QVERIFY(floor.kind == StepKind::FloorFinishing);
        QVERIFY(distance(millingOf(floor).outline->corners[0], {floorLeft + 0.3, 40.3}) < kTol);
        QVERIFY(distance(millingOf(floor).outline->corners[2], {floorRight - 0.3, 89.7}) < kTol);
        QVERIFY(std::abs(millingOf(floor).startDepth - 11.8) < kTol && std::abs(millingOf(floor).cutDepth - 12) < kTol);

        const Step& wall = steps[6];
        QVERIFY(wall.kind == StepKind::WallFinishing && wall.machiningType == MachiningType::WallFinishing);
        QVERIFY(distance(millingOf(wall).outline->corners[1], {floorRight, 40}) < kTol && millingOf(wall).outline->cornerRadius == 5);
        QVERIFY(millingOf(wall).startDepth == 0 && std::abs(millingOf(wall).cutDepth - 12) < kTol && millingOf(wall).wallAllowance == 0);

        const Step& one = steps[7];
        const Step& two = steps[8];
        QVERIFY(one.kind == StepKind::InclinedFaceFinishing && one.number == 1);
        QVERIFY(two.kind == StepKind::InclinedFaceFinishing && two.number == 2);
        const InclinedFace& oneFace = one.payload.as<InclinedFace>();
        const InclinedFace& twoFace = two.payload.as<InclinedFace>();
        QCOMPARE(one.label(), std::string("Inclined-face finishing I"));
        QCOMPARE(oneFace.angle, 20.0);
        QCOMPARE(twoFace.angle, 35.0);
        QVERIFY(distance(oneFace.topEdge[0], {30, 40}) < kTol && distance(oneFace.topEdge[1], {30, 90}) < kTol);
        QVERIFY(distance(oneFace.floorEdge[0], {floorLeft, 40}) < kTol);
        QVERIFY(distance(twoFace.topEdge[1], {110, 90}) < kTol && distance(twoFace.floorEdge[1], {floorRight, 90}) < kTol);
        QCOMPARE(oneFace.scallop, 0.02);
        QCOMPARE(twoFace.scallop, 0.02);
        for (const Step* s : {&one, &two}) {
            QVERIFY(millingOf(*s).startDepth == 0 && std::abs(millingOf(*s).cutDepth - 12) < kTol);
            QVERIFY(s->machiningType == MachiningType::InclinedFaceFinishing);
        }
    }

    void roughOnlyWithoutPilot()
    {
        M2DPocket p = pocket(12, 20);
        p.toolUse = 9;
        p.pilotHole = 9;
        const auto steps = decomposeM2D(p, tech(0.2, 0.5), 6.0, 0);
        QCOMPARE(steps.size(), std::size_t(4));
        for (const auto& s : steps) QVERIFY(s.kind == StepKind::Roughing);
    }

    // A face at 0 degrees is vertical: the wall step runs on it, and the one
    // inclined face left is numbered I.
    void verticalFaceHasNoInclinedStep()
    {
        const auto steps = decomposeM2D(pocket(12, 0, 25), tech(0.2, 0.5), 6.0, 0);
        const auto inclined = ofKind(steps, StepKind::InclinedFaceFinishing);
        QCOMPARE(inclined.size(), std::size_t(1));
        QCOMPARE(inclined[0].payload.as<InclinedFace>().angle, 25.0);
        QCOMPARE(inclined[0].number, 1);
        const auto wall = ofKind(steps, StepKind::WallFinishing);
        QVERIFY(std::abs(millingOf(wall[0]).outline->corners[0].x - 30) < kTol);
    }
};

QTEST_APPLESS_MAIN(TestDecomposeM2D)
#include "test_decompose_m2d.moc"
