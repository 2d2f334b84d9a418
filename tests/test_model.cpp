// Model value types: geometry of outlines, code tables, unit conversion.
#include "model/codes.h"
#include "model/geometry.h"
#include "model/job.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "model/step.h"
#include "model/technology.h"

#include <QtTest>

using namespace taiwa;

class TestModel : public QObject {
    Q_OBJECT
private slots:
    void offsetOfRectangleIsExact()
    {
        const Quad q{{{{0, 0}, {100, 0}, {100, 50}, {0, 50}}}, 5.0};
        const Quad o = offsetInward(q, 0.3);
        QVERIFY(distance(o.corners[0], {0.3, 0.3}) < 1e-12);
        QVERIFY(distance(o.corners[2], {99.7, 49.7}) < 1e-12);
        QVERIFY(std::abs(o.cornerRadius - 4.7) < 1e-12);
    }
    void offsetOfClockwiseOutlineStillGoesInward()
    {
        const Quad q{{{{0, 0}, {0, 50}, {100, 50}, {100, 0}}}, 5.0};
        const Quad o = offsetInward(q, 1.0);
        QVERIFY(signedArea(o.corners) > 0);
        QVERIFY(std::abs(signedArea(o.corners) - 98.0 * 48.0) < 1e-9);
    }
    void offsetOfParallelogramMovesSidesByTheDistance()
    {
        const std::array<Point2, 4> p{{{0, 0}, {100, 0}, {130, 40}, {30, 40}}};
        const Quad o = offsetInward(Quad{p, 0}, 2.0);
        // Bottom side moved up by 2, slanted side moved inward by 2 along its normal.
        QVERIFY(std::abs(o.corners[0].y - 2.0) < 1e-12);
        const Point2 t = p[2] - p[1];
        const Point2 n{-t.y / length(t), t.x / length(t)};
        QVERIFY(std::abs(dot(o.corners[1] - p[1], n) - 2.0) < 1e-12);
    }
    void convexityAndSelfIntersection()
    {
        QVERIFY(isStrictlyConvex({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}));
        QVERIFY(!isStrictlyConvex({{{0, 0}, {10, 0}, {2, 2}, {0, 10}}}));
        QVERIFY(isSelfIntersecting({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}));
        QVERIFY(!isSelfIntersecting({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}));
    }
    void inscribedRadiusOfRectangleIsHalfTheShortSide()
    {
        QVERIFY(std::abs(inscribedRadius({{{0, 0}, {100, 0}, {100, 40}, {0, 40}}}) - 20.0) < 1e-6);
    }
    void codeTablesRejectUndefinedCodes()
    {
        for (int u : {1, 6, 7, 8, 9}) QVERIFY(toolUseFromCode(u).has_value());
        for (int u : {0, 2, 3, 4, 5, 10, -1}) QVERIFY(!toolUseFromCode(u).has_value());
        QVERIFY(!wallFinishFromCode(4).has_value());
        QVERIFY(!pilotHoleFromCode(1).has_value());
        QVERIFY(hasRoughing(ToolUse::RoughOnly) && !hasFloorFinishing(ToolUse::RoughOnly));
        QVERIFY(!hasRoughing(ToolUse::Cored) && hasWallFinishing(ToolUse::WallOnly));
        QVERIFY(!meaning(ToolUse::Standard).empty());
    }
    void inchJobConvertsLengthsButNotAngles()
    {
        Job job;
        job.lengthUnit = LengthUnit::Inch;
        job.stock = {0, 0, 4, 3, 1};
        M4Pocket m;
        m.corners = {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
        m.depth = 0.5;
        m.taper = 5;
        job.units.push_back({"a", m});
        const Job mm = toMillimetres(job);
        const auto& p = (mm.units[0].module).as<M4Pocket>();
        QCOMPARE(p.depth, 12.7);
        QCOMPARE(p.taper, 5.0);
        QCOMPARE(mm.stock.width, 101.6);
    }
    void builtInTechnologyTableHasTheDefaultMaterial()
    {
        const auto* m = TechnologyTable::builtIn().find("aluminium-6061");
        QVERIFY(m != nullptr);
        QVERIFY(m->data.gamma > 0);
    }
    void stepLabelsUseRomanNumbers()
    {
        Step s;
        s.kind = StepKind::Roughing;
        s.number = 4;
        QCOMPARE(QString::fromStdString(s.label()), QStringLiteral("Roughing IV"));
        s.kind = StepKind::PilotHole;
        QCOMPARE(QString::fromStdString(s.label()), QStringLiteral("Pilot hole"));
    }
};

QTEST_APPLESS_MAIN(TestModel)
#include "test_model.moc"
