// The machine-time model (core/machine/motion_time): a long line's
// trapezoid, a short line's triangle, collinear blocks run through with
// look-ahead and stopped at without it, corners slowed by the tolerance,
// rapids at each axis' rate, drill cycles; the samples' steps and totals;
// machine definitions whose motion keys are wrong, refused by key. Turning
// (turnMachineMinutes): a long feed along Z at a fixed rpm and at G96, a
// rapid across the axis, a face under G96 reaching the spindle limit; the
// lathe samples' steps against their feed time.
#include "machine/machine.h"
#include "machine/motion_time.h"
#include "model/turn_path.h"
#include "support/hand_plan.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;

namespace {

Machine machine(double accel = 1000, int lookAhead = 200, double corner = 0.01)
{
    Machine m;
    m.id = "test";
    m.maxFeed = 10000;
    m.rapid = {{"x", 36000}, {"y", 36000}, {"z", 18000}};
    m.acceleration = {{"x", accel}, {"y", accel}, {"z", accel}};
    m.lookAhead = lookAhead;
    m.cornerTolerance = corner;
    return m;
}

double seconds(const ToolPath& p, const Machine& m, double feed = 6000)
{
    return machineMinutes(p, {feed, feed / 2}, m) * 60.0;
}

ToolPath line(double length, int pieces = 1)
{
    ToolPath p{{0, 0, 0}, {}};
    for (int k = 1; k <= pieces; ++k) p.moves.push_back({MoveKind::Feed, {length * k / pieces, 0, 0}});
    return p;
}

// A lathe: X (the radius) 2,000 mm/s², Z 1,000 mm/s²; rapids 12 m/min in
// X, 24 m/min in Z.
Machine lathe()
{
    Machine m;
    m.id = "test-lathe";
    m.kind = MachineKind::Lathe;
    m.xDiameter = true;
    m.maxFeed = 5000;
    m.maxSpindleSpeed = 4000;
    m.rapid = {{"x", 12000}, {"z", 24000}};
    m.acceleration = {{"x", 2000}, {"z", 1000}};
    m.lookAhead = 100;
    return m;
}

TurnStep turnStep(turning::ZR start, std::vector<TurnMove> moves, TurnCutting c)
{
    TurnStep t;
    t.cutting = c;
    t.path.start = start;
    t.path.moves = std::move(moves);
    return t;
}

TurnCutting fixedRpm(double rpm, double feedPerRev)
{
    TurnCutting c;
    c.constantSurfaceSpeed = false;
    c.rpm = rpm;
    c.feedPerRev = feedPerRev;
    c.plungeFeedPerRev = feedPerRev / 2;
    return c;
}

TurnCutting surfaceSpeed(double vc, double maxRpm, double feedPerRev)
{
    TurnCutting c;
    c.surfaceSpeed = vc;
    c.maxRpm = maxRpm;
    c.feedPerRev = feedPerRev;
    c.plungeFeedPerRev = feedPerRev / 2;
    return c;
}

}  // namespace

class TestMachineTime : public QObject {
    Q_OBJECT
private slots:
    // 100 mm at 100 mm/s with 1000 mm/s²: 0.1 s up, 0.9 s at speed, 0.1 s down.
    void longLineIsATrapezoid() { QVERIFY(std::abs(seconds(line(100), machine()) - 1.1) < 1e-9); }

    // 1 mm never reaches the feed: up and down, 2 sqrt(L / a).
    void shortLineIsATriangle() { QVERIFY(std::abs(seconds(line(1), machine()) - 2 * std::sqrt(1.0 / 1000)) < 1e-9); }

    // The same 100 mm in 100 blocks: run through with look-ahead, a stop at
    // every block without.
    void lookAheadRunsThroughCollinearBlocks()
    {
        QVERIFY(std::abs(seconds(line(100, 100), machine()) - 1.1) < 1e-9);
        QVERIFY(std::abs(seconds(line(100, 100), machine(1000, 1)) - 100 * 2 * std::sqrt(1.0 / 1000)) < 1e-9);
        // Looking 5 blocks (5 mm) ahead it must be able to stop within them:
        // at most sqrt(2 a 5 mm) = 100 mm/s, just the feed: no time lost.
        QVERIFY(std::abs(seconds(line(100, 100), machine(1000, 5)) - 1.1) < 1e-6);
        // Two blocks ahead: at most sqrt(2 a 2 mm) = 63 mm/s, slower.
        QVERIFY(seconds(line(100, 100), machine(1000, 2)) > 1.5);
    }

    // A 100 mm square: the corners slow it to sqrt(a δ sin(θ/2) / (1 - sin(θ/2))),
    // a little faster than four stops; a larger tolerance, faster still.
    void cornersSlowDown()
    {
        ToolPath sq{{0, 0, 0}, {}};
        for (Point3 c : {Point3{100, 0, 0}, Point3{100, 100, 0}, Point3{0, 100, 0}, Point3{0, 0, 0}})
            sq.moves.push_back({MoveKind::Feed, c});
        const double tight = seconds(sq, machine()), loose = seconds(sq, machine(1000, 200, 1.0));
        QVERIFY2(tight < 4 * 1.1 && tight > 4 * 1.1 - 0.05, qPrintable(QString::number(tight)));
        QVERIFY(loose < tight - 0.05);
        const double s = std::sqrt(0.5), corner = std::sqrt(1000 * 0.01 * s / (1 - s));
        // Each of the three corners is left and entered at that speed instead
        // of from a stop: each of its two blocks saves v / a - v² / (2 a V).
        const double saved = 3 * 2 * (corner / 1000 - corner * corner / (2 * 1000) / 100);
        QVERIFY2(std::abs((4 * 1.1 - tight) - saved) < 1e-6, qPrintable(QString::number(4 * 1.1 - tight - saved)));
    }

    // Rapids at each axis' rate, stopping at their end.
    void rapidsAtTheAxisRate()
    {
        ToolPath p{{0, 0, 0}, {{MoveKind::Rapid, {300, 0, 0}}}};
        QVERIFY(std::abs(seconds(p, machine(3000)) - (300.0 / 600 + 600.0 / 3000)) < 1e-9);
        // Down Z at 18,000 mm/min = 300 mm/s.
        ToolPath z{{0, 0, 0}, {{MoveKind::Rapid, {0, 0, -90}}}};
        QVERIFY(std::abs(seconds(z, machine(3000)) - (90.0 / 300 + 300.0 / 3000)) < 1e-9);
    }

    // A drill cycle: blocks with stops; pecks take longer.
    void drillCyclesPeck()
    {
        Move straight{MoveKind::DrillCycle, {10, 10, -20}};
        straight.retractZ = 2;
        Move pecked = straight;
        pecked.peck = 5;
        const double a = seconds(ToolPath{{10, 10, 5}, {straight}}, machine(), 300);
        const double b = seconds(ToolPath{{10, 10, 5}, {pecked}}, machine(), 300);
        QVERIFY(a > 22.0 / 5);  // 22 mm at 5 mm/s
        QVERIFY(b > a);
    }

    void samplesHaveMachineTimes()
    {
        for (const char* name : {"plate.taiwa", "m4-standard.taiwa", "m2d-standard.taiwa"}) {
            const Plan plan = test::samplePlan(name);
            QVERIFY(plan.ok());
            QVERIFY(plan.totalMachineMinutes);
            for (const Step& s : plan.steps) {
                QVERIFY(s.machineMinutes && *s.machineMinutes > 0);
                QVERIFY2(*s.machineMinutes > 0.3 * *s.minutes && *s.machineMinutes < 5 * *s.minutes,
                         qPrintable(QString("%1 %2: %3 vs %4").arg(name).arg(QString::fromStdString(s.label())).arg(*s.machineMinutes).arg(*s.minutes)));
            }
        }
    }

    // 100 mm along Z at 2,000 rpm and 0.25 mm/rev: 500 mm/min, a trapezoid
    // at Z's 1,000 mm/s²: L / V + V / a. Under G96 at 150 m/min on Ø40 the
    // same with V = 0.25 · 1000 · 150 / (π 40) mm/min.
    void turningFeedAlongZIsATrapezoid()
    {
        const std::vector<TurnMove> along{{TurnMove::Feed, {-100, 20}}};
        const double v = 500.0 / 60;
        const double fixed = turnMachineMinutes(turnStep({0, 20}, along, fixedRpm(2000, 0.25)), lathe()) * 60;
        QVERIFY2(std::abs(fixed - (100 / v + v / 1000)) < 1e-9, qPrintable(QString::number(fixed)));
        const double w = 0.25 * 1000 * 150 / (std::numbers::pi * 40) / 60;
        const double css = turnMachineMinutes(turnStep({0, 20}, along, surfaceSpeed(150, 4000, 0.25)), lathe()) * 60;
        QVERIFY2(std::abs(css - (100 / w + w / 1000)) < 1e-9, qPrintable(QString::number(css)));
        // A rapid of 50 mm across the axis (the radius: X's 12 m/min move
        // the tool 50 mm, not 25) at X's rate and acceleration, with a stop.
        const std::vector<TurnMove> rapid{{TurnMove::Rapid, {0, 70}}};
        const double r = turnMachineMinutes(turnStep({0, 20}, rapid, fixedRpm(2000, 0.25)), lathe()) * 60;
        QVERIFY2(std::abs(r - (50.0 / 200 + 200.0 / 2000)) < 1e-9, qPrintable(QString::number(r)));
    }

    // Facing from r = 25 to the axis at 200 m/min, 0.2 mm/rev, at most
    // 2,000 rpm: the limit holds below r_c = 1000 vc / (2π n_max) = 15.9 mm.
    // The feed time is ∫ dr / (f n(r)) = π (R² + r_c²) / (1000 vc f) min;
    // without the limit π R² / (1000 vc f), all at the limit R / (f n_max).
    // The planner's pieces (1 % in radius, each at its smaller diameter)
    // may be up to 1 % quicker; accelerating adds at most 2 V / a.
    void facingReachesTheSpindleLimit()
    {
        const double R = 25, vc = 200, f = 0.2, nMax = 2000;
        const double rc = 1000 * vc / (2 * std::numbers::pi * nMax);
        const double limited = std::numbers::pi * (R * R + rc * rc) / (1000 * vc * f) * 60;
        const double unlimited = std::numbers::pi * R * R / (1000 * vc * f) * 60;
        const double allAtLimit = R / (f * nMax) * 60;
        const double t = turnMachineMinutes(turnStep({0, R}, {{TurnMove::Feed, {0, 0}}}, surfaceSpeed(vc, nMax, f)), lathe()) * 60;
        const QString figures = QString("%1 s; limited %2, unlimited %3, all at the limit %4").arg(t).arg(limited).arg(unlimited).arg(allAtLimit);
        QVERIFY2(t > unlimited && t > allAtLimit, qPrintable(figures));
        QVERIFY2(t >= 0.99 * limited && t <= limited + 2 * (f * nMax / 60) / 2000, qPrintable(figures));
        // Without the limit it would be the unlimited time, give or take.
        const double free = turnMachineMinutes(turnStep({0, R}, {{TurnMove::Feed, {0, 0}}}, surfaceSpeed(vc, 1e6, f)), lathe()) * 60;
        QVERIFY2(free < limited && free >= 0.99 * unlimited - 1e-3, qPrintable(QString::number(free)));
    }

    // Every lathe sample's steps: a machine time, no less than its feed
    // time (feed per revolution at each move's mean diameter, rapids left
    // out: the machine cannot cut faster than its feeds) less the 1 % the
    // pieces at their smaller diameter may gain; the total covers them.
    void latheSamplesHaveMachineTimes()
    {
        for (const char* name : {"lathe-angle-cases.taiwa", "lathe-bore-grinding.taiwa", "lathe-both-ground.taiwa", "lathe-bushing.taiwa",
                                 "lathe-grooved-shaft.taiwa", "lathe-shaft-grinding.taiwa", "lathe-tangent-nose.taiwa",
                                 "lathe-turned-shaft.taiwa"}) {
            const Plan plan = test::samplePlan(name);
            QVERIFY2(plan.ok(), name);
            QVERIFY2(plan.totalMachineMinutes, name);
            double sum = 0;
            for (const Step& s : plan.steps) {
                QVERIFY(turnOf(s));
                QVERIFY(s.machineMinutes && *s.machineMinutes > 0);
                const double feedOnly = turnMinutes(turnOf(s)->path, turnOf(s)->cutting, 1e12);
                const QString figures = QString("%1 %2: %3 vs %4 (feed only %5)").arg(name).arg(QString::fromStdString(s.label()))
                                            .arg(*s.machineMinutes).arg(*s.minutes).arg(feedOnly);
                QVERIFY2(*s.machineMinutes >= 0.99 * feedOnly, qPrintable(figures));
                QVERIFY2(*s.machineMinutes < 3 * *s.minutes, qPrintable(figures));
                sum += *s.machineMinutes;
            }
            QVERIFY(*plan.totalMachineMinutes >= sum);
        }
    }

    void badMotionKeysRefused()
    {
        const std::string base = R"({"format": "taiwa-machine", "version": 1, "id": "m", "name": "M", "kind": "mill",
            "travel": {"x": [0, 1], "y": [0, 1], "z": [-1, 0]}, "maxSpindleSpeed": 1, "maxFeed": 1,
            "rapid": {"x": 1, "y": 1, "z": 1}, "toolChanger": {"pockets": 1})";
        QVERIFY(readMachine(base + "}", "m.json"));
        const auto a = readMachine(base + R"(, "acceleration": {"x": 1, "y": -2, "z": 1}})", "m.json");
        QVERIFY(!a);
        QVERIFY2(QString::fromStdString(a.error()).contains("acceleration.y"), a.error().c_str());
        const auto l = readMachine(base + R"(, "lookAhead": 0})", "m.json");
        QVERIFY(!l);
        QVERIFY(QString::fromStdString(l.error()).contains("lookAhead"));
        const auto ok = readMachine(base + R"(, "acceleration": {"x": 1, "y": 2, "z": 3}, "lookAhead": 50})", "m.json");
        QVERIFY(ok);
        QCOMPARE(ok->acceleration.at("y"), 2.0);
        QCOMPARE(ok->lookAhead, 50);
    }
};

QTEST_GUILESS_MAIN(TestMachineTime)
#include "test_machine_time.moc"
