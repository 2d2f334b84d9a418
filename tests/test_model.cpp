// Model value types: geometry of outlines (offsets, flattening), the sweep
// of an arc move, code tables, unit conversion, and how the values hold
// their parts (shared module inputs, optionals on the heap, shared texts).
#include "model/codes.h"
#include "model/geometry.h"
#include "model/job.h"
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/toolpath.h"

#include <QtTest>

#include <algorithm>
#include <random>
#include <utility>

#include <cmath>
#include <numbers>

using namespace taiwa;

Q_DECLARE_METATYPE(taiwa::Quad)

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
    // The closed form (first root of the sides' lengths and the area) against
    // the definition itself, bisected on offsetInward, for 20,000 random
    // quads: convex ones, skewed ones, needles and clockwise ones.
    void inscribedRadiusEqualsTheBisectedDefinition()
    {
        const auto byBisection = [](std::array<Point2, 4> q) {
            q = counterClockwise(q);
            double lo = 0, hi = 0;
            for (std::size_t i = 0; i < 4; ++i) hi = std::max(hi, distance(q[i], q[(i + 2) % 4]));
            for (int it = 0; it < 200; ++it) {
                const double mid = 0.5 * (lo + hi);
                const Quad o = offsetInward(Quad{q, 0.0}, mid);
                bool ok = signedArea(o.corners) > 0.0;
                for (std::size_t i = 0; ok && i < 4; ++i)
                    ok = dot(q[(i + 1) % 4] - q[i], o.corners[(i + 1) % 4] - o.corners[i]) > 0.0;
                (ok ? lo : hi) = mid;
            }
            return lo;
        };
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> coord(-50, 50), angle(0, 2 * std::numbers::pi), radius(0.1, 60);
        int tried = 0;
        for (int n = 0; n < 20'000; ++n) {
            // Corners at increasing angles around a centre: a convex quad (or,
            // with a swapped pair, a bow tie that is skipped).
            std::array<double, 4> a{};
            for (auto& v : a) v = angle(rng);
            std::sort(a.begin(), a.end());
            const Point2 c{coord(rng), coord(rng)};
            std::array<Point2, 4> q{};
            for (std::size_t i = 0; i < 4; ++i) {
                const double r = radius(rng);
                q[i] = {c.x + r * std::cos(a[i]), c.y + r * std::sin(a[i])};
            }
            if (n % 2) std::swap(q[1], q[3]);  // clockwise
            if (isSelfIntersecting(q) || std::abs(signedArea(q)) < 1e-3) continue;
            ++tried;
            const double expected = byBisection(q), got = inscribedRadius(q);
            if (std::abs(got - expected) > 1e-9 * std::max(1.0, expected))
                QFAIL(qPrintable(QString("quad (%1,%2) (%3,%4) (%5,%6) (%7,%8): %9 instead of %10")
                                     .arg(q[0].x).arg(q[0].y).arg(q[1].x).arg(q[1].y).arg(q[2].x).arg(q[2].y)
                                     .arg(q[3].x).arg(q[3].y).arg(got, 0, 'g', 17).arg(expected, 0, 'g', 17)));
        }
        QVERIFY(tried > 15'000);
    }
    // Counter-clockwise positive in (0, 2π], clockwise negative in [-2π, 0);
    // an arc that ends where it starts is a full circle, never 0.
    void arcSweepConvention()
    {
        const double pi = std::numbers::pi;
        const Point3 from{10, 0, 0};
        const auto arc = [](MoveKind k, Point3 end) { return Move{k, end, {0, 0}}; };
        QVERIFY(std::abs(arcSweep(from, arc(MoveKind::ArcCCW, {0, 10, -1})) - pi / 2) < 1e-12);
        QVERIFY(std::abs(arcSweep(from, arc(MoveKind::ArcCW, {0, 10, 0})) + 3 * pi / 2) < 1e-12);
        QVERIFY(std::abs(arcSweep(from, arc(MoveKind::ArcCCW, {-10, 0, 0})) - pi) < 1e-12);
        QVERIFY(std::abs(arcSweep(from, arc(MoveKind::ArcCW, {-10, 0, 0})) + pi) < 1e-12);
        QCOMPARE(arcSweep(from, arc(MoveKind::ArcCCW, from)), 2 * pi);
        QCOMPARE(arcSweep(from, arc(MoveKind::ArcCW, from)), -2 * pi);
    }

    // Chord ends on the arcs, chords within the tolerance, counter-clockwise
    // whatever the input's orientation; sharp corners are one point; a slot
    // whose radius is half its width (its core a segment) still flattens to
    // its two half discs and the rectangle between them.
    void flattenKeepsArcsWithinTheTolerance_data()
    {
        QTest::addColumn<Quad>("q");
        QTest::newRow("rectangle r 5") << Quad{{{{0, 0}, {100, 0}, {100, 50}, {0, 50}}}, 5.0};
        QTest::newRow("clockwise parallelogram r 3") << Quad{{{{0, 0}, {30, 40}, {130, 40}, {100, 0}}}, 3.0};
        QTest::newRow("slot 80 x 16 r 8") << Quad{{{{20, 22}, {100, 22}, {100, 38}, {20, 38}}}, 8.0};
        QTest::newRow("rotated slot r 8") << Quad{{{{30, 20}, {94, 68}, {84.4, 80.8}, {20.4, 32.8}}}, 8.0};
    }
    void flattenKeepsArcsWithinTheTolerance()
    {
        QFETCH(Quad, q);
        const double tol = 0.001, r = q.cornerRadius;
        const auto pts = flatten(q, tol);
        QVERIFY(pts.size() > 8);
        double area = 0;
        for (std::size_t i = 0; i < pts.size(); ++i) area += 0.5 * cross(pts[i], pts[(i + 1) % pts.size()]);
        // A corner that turns by φ loses r²(tan(φ/2) - φ/2) of the sharp area.
        const auto p = counterClockwise(q.corners);
        double exact = signedArea(p);
        for (std::size_t i = 0; i < 4; ++i) {
            const Point2 a = p[i] - p[(i + 3) % 4], b = p[(i + 1) % 4] - p[i];
            const double turn = std::atan2(cross(a, b), dot(a, b));
            exact -= r * r * (std::tan(turn / 2) - turn / 2);
        }
        QVERIFY2(area > 0 && area <= exact + 1e-9 && area > exact - tol * 2 * std::numbers::pi * r,
                 qPrintable(QString("area %1, exact %2").arg(area).arg(exact)));
        const Quad sharpQuad{q.corners, 0.0};
        QCOMPARE(flatten(sharpQuad, tol).size(), std::size_t(4));
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
        QCOMPARE(job.units[0].module.as<M4Pocket>().depth, 0.5);  // the job as typed keeps its inches
    }

    // Copies of a module input share it until one is changed (model/erased.h):
    // the copy changed has its own, the others keep what they had.
    void moduleInputCopiesShareUntilChanged()
    {
        M4Pocket m;
        m.corners = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
        m.depth = 5;
        const ModuleInput a = m;
        ModuleInput b = a;
        QCOMPARE(&std::as_const(b).as<M4Pocket>(), &a.as<M4Pocket>());  // reading: one struct
        b.as<M4Pocket>().depth = 7;                        // changing access: b's own
        QCOMPARE(a.as<M4Pocket>().depth, 5.0);
        QCOMPARE(std::as_const(b).as<M4Pocket>().depth, 7.0);
        QVERIFY(!(a == b));
        ModuleInput c = a;
        c.convertLengths([](double v) { return 2 * v; });
        QCOMPARE(a.as<M4Pocket>().depth, 5.0);
        QCOMPARE(c.as<M4Pocket>().depth, 10.0);
        ModuleInput d = a;
        QVERIFY(d == a);
        d.getIf<M4Pocket>()->depth = 5;  // changed to what it was: equal again, by value
        QVERIFY(d == a && &std::as_const(d).as<M4Pocket>() != &a.as<M4Pocket>());
    }

    // A step's path and its geometry's outline and region are optionals on the heap
    // (model/boxed.h): copied and compared by value, value() refuses when
    // there is none, and absent they cost a pointer.
    void boxedIsAnOptionalOnTheHeap()
    {
        Boxed<Quad> a;
        QVERIFY(!a && !a.has_value() && a == std::nullopt);
        QVERIFY_THROWS_EXCEPTION(std::bad_optional_access, a.value());
        a = Quad{{{{0, 0}, {4, 0}, {4, 2}, {0, 2}}}, 1};
        Boxed<Quad> b = a;
        QVERIFY(a == b && &*a != &*b);
        b->cornerRadius = 0.5;
        QCOMPARE(a->cornerRadius, 1.0);
        QVERIFY(!(a == b));
        b = std::optional<Quad>{};
        QVERIFY(!b && !(a == b));
        b = a.optional();
        QVERIFY(a == b);
        b.reset();
        QCOMPARE(b.value_or(Quad{{}, 3}).cornerRadius, 3.0);
        Step s;
        QVERIFY(!millingOf(s).outline && !millingOf(s).region && !s.path);
        QVERIFY(sizeof(millingOf(s).outline) == sizeof(void*) && sizeof(s.path) == sizeof(void*));
    }

    // A tool's reason is one shared text: a pool makes equal texts made
    // apart one; == compares the text either way.
    void reasonsAreSharedTexts()
    {
        SharedText a(std::string("largest flat end mill (10 mm)"));
        SharedText b(std::string("largest flat end mill (10 mm)"));
        SharedText c("smallest drill (6 mm)");
        QVERIFY(a == b && !(a == c) && &a.str() != &b.str());
        TextPool pool;
        pool.share(a);
        pool.share(b);
        pool.share(c);
        QCOMPARE(&a.str(), &b.str());
        QCOMPARE(b.str(), std::string("largest flat end mill (10 mm)"));
        QVERIFY(&c.str() != &a.str());
        SharedText none;
        pool.share(none);
        QVERIFY(none.empty() && none.str().empty() && none == SharedText(""));
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
