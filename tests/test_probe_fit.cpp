// The fits of work-centre probing (core/modules/probe/probe_fit.h) against
// workpieces of known centre and size: exact touches (centre and size to
// 1 µm, rotation to 0.001°), touches with 5 µm of noise (centre within 3σ,
// residuals reported), bores and bosses, blocks and pockets (the stylus
// ball added or taken off), the first touch anywhere on the outline; and the
// refusals, each naming the touch to blame.
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/probe/probe.h"
#include "modules/probe/probe_fit.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>
#include <variant>

using namespace taiwa;
using namespace taiwa::probe;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBall = 2.0;  // the default probe's 4 mm ball

// Ball centres touching a circle of radius r about c (from outside: r + ball,
// from inside: r - ball), at the given angles [deg], relative to the first.
std::vector<Touch> onCircle(Point2 c, double r, bool inside, std::vector<double> degrees, double noise = 0.0,
                            unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, noise > 0 ? noise : 1.0);
    const double rb = inside ? r - kBall : r + kBall;
    std::vector<Touch> t;
    for (const double a : degrees) {
        const double e = noise > 0 ? n(rng) : 0.0;
        t.push_back({{c.x + (rb + e) * std::cos(a * kPi / 180), c.y + (rb + e) * std::sin(a * kPi / 180)}});
    }
    const Point2 first = t[0].at;
    for (auto& x : t) x.at = x.at - first;
    return t;
}

// Ball centres touching a w x l rectangle about c turned by `deg`; each
// touch given as (side, position along the side from its middle).
std::vector<Touch> onRectangle(Point2 c, double w, double l, double deg, bool inside,
                               std::vector<std::pair<Side, double>> where, double noise = 0.0, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, noise > 0 ? noise : 1.0);
    const double a = deg * kPi / 180;
    const Point2 ex{std::cos(a), std::sin(a)}, ey{-std::sin(a), std::cos(a)};
    const double out = inside ? -kBall : kBall;
    std::vector<Touch> t;
    for (const auto& [side, along] : where) {
        const double e = noise > 0 ? n(rng) : 0.0;
        Point2 local;
        switch (side) {
        case Side::XMinus: local = {-w / 2 - out - e, along}; break;
        case Side::XPlus: local = {w / 2 + out + e, along}; break;
        case Side::YMinus: local = {along, -l / 2 - out - e}; break;
        case Side::YPlus: local = {along, l / 2 + out + e}; break;
        case Side::None: break;
        }
        t.push_back({c + local.x * ex + local.y * ey, side});
    }
    const Point2 first = t[0].at;
    for (auto& x : t) x.at = x.at - first;
    return t;
}

template <class Fit, class Result>
Fit expectFit(const Result& r)
{
    if (const auto* p = std::get_if<FitProblem>(&r)) qFatal("refused: %s", p->message.c_str());
    return std::get<Fit>(r);
}

template <class Result>
FitProblem expectProblem(const Result& r)
{
    if (!std::holds_alternative<FitProblem>(r)) qFatal("accepted");
    return std::get<FitProblem>(r);
}

// The centre relative to the first touch, for a part whose first touch was
// at `first` in absolute terms.
Point2 relative(Point2 centre, Point2 first) { return centre - first; }

}  // namespace

class TestProbeFit : public QObject {
    Q_OBJECT
private slots:
    // Three touches: the circumcentre. A boss of Ø 80 at (37.5, -12.25),
    // the first touch anywhere on it (here at 200°).
    void bossFromThreeExactTouches()
    {
        const Point2 c{37.5, -12.25};
        for (const double first : {0.0, 200.0, 333.3}) {
            const auto t = onCircle(c, 40, false, {first, first + 100, first + 230});
            const auto fit = expectFit<CircleFit>(fitCircle(t, {kBall, false, 0.01}));
            const Point2 firstAt{c.x + 42 * std::cos(first * kPi / 180), c.y + 42 * std::sin(first * kPi / 180)};
            const Point2 expected = relative(c, firstAt);
            QVERIFY(distance(fit.centre, expected) < 1e-6);
            QVERIFY(std::abs(fit.radius - 40) < 1e-6);
            for (const double r : fit.residuals) QVERIFY(std::abs(r) < 1e-9);
        }
    }
    // A bore: the ball inside, the surface the ball's radius farther out.
    void boreAddsTheBallRadius()
    {
        const auto t = onCircle({0, 0}, 25, true, {10, 100, 190, 280, 330});
        const auto fit = expectFit<CircleFit>(fitCircle(t, {kBall, true, 0.01}));
        QVERIFY(std::abs(fit.radius - 25) < 1e-6);
        // The same touches taken as a boss are a circle 2 balls smaller.
        const auto boss = expectFit<CircleFit>(fitCircle(t, {kBall, false, 0.01}));
        QVERIFY(std::abs(boss.radius - 21) < 1e-6);
        QVERIFY(distance(fit.centre, boss.centre) < 1e-9);
    }
    // σ = 5 µm on 8 touches over 270°: the centre within 3σ, each residual
    // reported, and a geometric fit (the residuals sum of squares no larger
    // than the algebraic centre's).
    void noisyTouchesGiveCentreWithinThreeSigma()
    {
        const double sigma = 0.005;
        for (unsigned seed = 1; seed <= 20; ++seed) {
            const Point2 c{120, 80};
            const auto t = onCircle(c, 30, false, {0, 35, 80, 120, 160, 200, 235, 270}, sigma, seed);
            const auto fit = expectFit<CircleFit>(fitCircle(t, {kBall, false, 0.03}));
            // The true centre relative to the first touch: that touch (at 0°)
            // is 32 mm plus its own noise e right of the centre.
            const auto trueCentre = [&] {
                std::mt19937 rng(seed);
                std::normal_distribution<double> n(0.0, sigma);
                return Point2{-(32 + n(rng)), 0.0};
            }();
            QVERIFY2(distance(fit.centre, trueCentre) < 3 * sigma,
                     qPrintable(QString("seed %1: centre off by %2 mm").arg(seed).arg(distance(fit.centre, trueCentre))));
            QCOMPARE(fit.residuals.size(), t.size());
            double worst = 0;
            for (const double r : fit.residuals) worst = std::max(worst, std::abs(r));
            QVERIFY(worst > 0 && worst < 5 * sigma);
            QVERIFY(std::abs(fit.radius - 30) < 3 * sigma);
        }
    }
    // One touch a side: the centre and size of an axis-aligned block; the
    // rotation is not measured.
    void blockFromFourTouches()
    {
        const Point2 c{-50, 25};
        const auto t = onRectangle(c, 120, 70, 0, false,
                                   {{Side::YPlus, 20}, {Side::XMinus, -10}, {Side::XPlus, 5}, {Side::YMinus, -30}});
        const auto fit = expectFit<RectangleFit>(fitRectangle(t, {kBall, false, 0.01}));
        const Point2 first = c + Point2{20, 35 + kBall};
        QVERIFY(distance(fit.centre, c - first) < 1e-6);
        QVERIFY(std::abs(fit.width - 120) < 1e-6 && std::abs(fit.length - 70) < 1e-6);
        QVERIFY(!fit.rotationMeasured && fit.rotation == 0);
    }
    // A part turned by 7.5°, touched twice on -Y (and twice on +X): its
    // rotation to 0.001°, centre and size to 1 µm; a pocket as well.
    void rotatedRectangle()
    {
        for (const bool inside : {false, true}) {
            for (const double deg : {7.5, -3.25, 0.0004}) {
                const Point2 c{10, 20};
                const auto t = onRectangle(c, 90, 60, deg, inside,
                                           {{Side::XMinus, 12}, {Side::YMinus, -30}, {Side::YMinus, 25}, {Side::XPlus, -8},
                                            {Side::XPlus, 17}, {Side::YPlus, 0}});
                const auto fit = expectFit<RectangleFit>(fitRectangle(t, {kBall, inside, 0.01}));
                QVERIFY(fit.rotationMeasured);
                QVERIFY2(std::abs(fit.rotation - deg) < 0.001, qPrintable(QString::number(fit.rotation, 'g', 12)));
                QVERIFY(std::abs(fit.width - 90) < 1e-6 && std::abs(fit.length - 60) < 1e-6);
                const double a = deg * kPi / 180;
                const double out = inside ? -kBall : kBall;
                const Point2 first = c + (-45 - out) * Point2{std::cos(a), std::sin(a)} + 12 * Point2{-std::sin(a), std::cos(a)};
                QVERIFY(distance(fit.centre, c - first) < 1e-6);
                for (const double r : fit.residuals) QVERIFY(std::abs(r) < 1e-9);
            }
        }
    }
    void noisyRectangle()
    {
        const double sigma = 0.005;
        for (unsigned seed = 1; seed <= 20; ++seed) {
            const auto t = onRectangle({0, 0}, 100, 50, 2, false,
                                       {{Side::XMinus, 0}, {Side::YMinus, -35}, {Side::YMinus, 35}, {Side::XPlus, 0},
                                        {Side::YPlus, -30}, {Side::YPlus, 30}},
                                       sigma, seed);
            const auto fit = expectFit<RectangleFit>(fitRectangle(t, {kBall, false, 0.03}));
            QVERIFY(std::abs(fit.width - 100) < 4 * sigma && std::abs(fit.length - 50) < 4 * sigma);
            QVERIFY(std::abs(fit.rotation - 2) < 0.02);
            QCOMPARE(fit.residuals.size(), t.size());
        }
    }

    // Refusals, each naming the touch to blame.
    void tooFewTouches()
    {
        const auto p = expectProblem(fitCircle(onCircle({0, 0}, 10, false, {0, 90}), {kBall, false, 0.01}));
        QCOMPARE(p.point, 0);
        QCOMPARE(p.message, std::string("a round workpiece needs at least 3 touch points, 2 given"));
        const auto q = expectProblem(fitRectangle(
            onRectangle({0, 0}, 40, 30, 0, false, {{Side::XMinus, 0}, {Side::XPlus, 0}, {Side::YMinus, 0}}), {kBall, false, 0.01}));
        QCOMPARE(q.message, std::string("a rectangular workpiece needs a touch on every side: none on +Y"));
    }
    void coincidentTouches()
    {
        auto t = onCircle({0, 0}, 10, false, {0, 90, 180});
        t.push_back({t[1].at + Point2{0.0002, 0}});
        const auto p = expectProblem(fitCircle(t, {kBall, false, 0.01}));
        QCOMPARE(p.point, 4);
        QCOMPARE(p.message, std::string("point 4 coincides with point 2: touch the outline elsewhere"));
    }
    // Judged at the unit's tolerance, not at 1 µm: two touches 5 µm apart
    // with a tolerance of 0.01 mm are one point measured twice (the later
    // one named), on a circle and on a side of a rectangle; 15 µm apart they
    // are two touches.
    void touchesWithinTheToleranceCoincide()
    {
        auto c = onCircle({0, 0}, 10, false, {0, 90, 180});
        c.push_back({c[1].at + Point2{0.005, 0}});  // along the outline, 5 µm
        const auto p = expectProblem(fitCircle(c, {kBall, false, 0.01}));
        QCOMPARE(p.point, 4);
        QCOMPARE(p.message, std::string("point 4 coincides with point 2: touch the outline elsewhere"));
        c.back().at = c[1].at + Point2{0.015, 0};
        QVERIFY(std::holds_alternative<CircleFit>(fitCircle(c, {kBall, false, 0.01})));
        // A tolerance of 0.001 mm (the smallest): 5 µm apart are two touches.
        c.back().at = c[1].at + Point2{0.005, 0};
        QVERIFY(std::holds_alternative<CircleFit>(fitCircle(c, {kBall, false, 0.001})));

        auto r = onRectangle({0, 0}, 40, 30, 0, false,
                             {{Side::XMinus, 0}, {Side::XPlus, 0}, {Side::YMinus, -5}, {Side::YPlus, 0}, {Side::YMinus, 5}});
        r.push_back({r[2].at + Point2{0.005, 0}, Side::YMinus});
        const auto q = expectProblem(fitRectangle(r, {kBall, false, 0.01}));
        QCOMPARE(q.point, 6);
        QCOMPARE(q.message, std::string("point 6 coincides with point 3: touch the outline elsewhere"));
    }
    void collinearTouches()
    {
        const std::vector<Touch> t{{{0, 0}}, {{10, 5}}, {{20, 10}}};
        const auto p = expectProblem(fitCircle(t, {kBall, false, 0.01}));
        QCOMPARE(p.point, 3);
        QVERIFY(p.message.starts_with("point 3 lies on the line of points 1 to 2"));
    }
    void touchOffTheCircle()
    {
        auto t = onCircle({5, 5}, 20, false, {0, 60, 120, 180, 240, 300});
        t[4].at = t[4].at + Point2{0.2, 0.1};  // a chip under the ball
        const auto p = expectProblem(fitCircle(t, {kBall, false, 0.02}));
        QCOMPARE(p.point, 5);
        QVERIFY2(p.message.starts_with("point 5 is ") && p.message.find("off the fitted circle (tolerance 0.02 mm)") != std::string::npos,
                 p.message.c_str());
    }
    void touchOffTheRectangle()
    {
        // Three touches on -Y (two would take any error for a rotation).
        auto t = onRectangle({0, 0}, 60, 40, 0, false,
                             {{Side::XMinus, 0}, {Side::XPlus, 0}, {Side::YMinus, -20}, {Side::YMinus, 0}, {Side::YMinus, 20},
                              {Side::YPlus, 0}});
        t[3].at.y -= 0.1;  // the middle -Y touch 0.1 mm out: a chip under the ball
        const auto p = expectProblem(fitRectangle(t, {kBall, false, 0.01}));
        QVERIFY2(p.point == 4, p.message.c_str());
        QVERIFY(p.message.find("off the fitted rectangle") != std::string::npos);
    }
    void swappedSides()
    {
        auto t = onRectangle({0, 0}, 60, 40, 0, false, {{Side::XMinus, 0}, {Side::XPlus, 0}, {Side::YMinus, 0}, {Side::YPlus, 0}});
        std::swap(t[0].side, t[1].side);  // the operator said +X for the left side and -X for the right
        const auto p = expectProblem(fitRectangle(t, {kBall, false, 0.01}));
        QCOMPARE(p.point, 1);
        QCOMPARE(p.message, std::string("the points on -X and +X are swapped: the +X side (point 1) lies at or left of the -X side (point 2)"));
    }
    // Through the job: the refusal on the touch's own field, named in words
    // the operator reads on the form.
    void checkNamesTheTouchField()
    {
        Job job;
        job.stock = {-50, -50, 100, 100, 30};
        ProbeUnit p;
        const auto t = onCircle({0, 0}, 30, false, {0, 70, 150, 230, 300});
        for (std::size_t i = 0; i < t.size(); ++i) p.x[i] = t[i].at.x, p.y[i] = t[i].at.y;
        *p.x[3] += 0.5;  // P4 half a millimetre off
        p.sizeX = 60;
        job.units.push_back({"Boss", p});
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QCOMPARE(ds.size(), std::size_t(1));
        QCOMPARE(ds[0].field, std::string("touches[3]"));
        QVERIFY2(ds[0].message.starts_with("point 4 is "), ds[0].message.c_str());
        // P1 is the measuring origin.
        *p.x[3] -= 0.5;
        p.x[0] = 1.0;
        job.units[0] = {"Boss", p};
        const Diagnostics origin = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(!origin.empty() && origin[0].field == "touches[0]");
    }
    // A half-typed touch (X without Y) and a touch left out are saved as the
    // operator left them, and refused with the point named.
    void halfTypedTouchesSurviveTheJobFile()
    {
        Job job;
        job.stock = {-50, -50, 100, 100, 30};
        ProbeUnit p;
        p.x[0] = p.y[0] = 0.0;
        p.x[1] = 12.5;       // its Y not yet typed
        p.x[3] = 4, p.y[3] = 5;  // P3 left out
        p.sizeX = 40;
        job.units.push_back({"", p});
        const std::string text = writeJob(job);
        QVERIFY2(text.find("[12.5, null]") != std::string::npos && text.find("null,") != std::string::npos, text.c_str());
        const JobReadResult back = readJob(text);
        QVERIFY(back.job);
        QVERIFY(*back.job == job);
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(!ds.empty());
        QCOMPARE(ds[0].field, std::string("touches[1]"));
        QCOMPARE(ds[0].message, std::string("point 2: its Y is missing"));
    }
    void sideNotGiven()
    {
        auto t = onRectangle({0, 0}, 60, 40, 0, false, {{Side::XMinus, 0}, {Side::XPlus, 0}, {Side::YMinus, 0}, {Side::YPlus, 0}});
        t[2].side = Side::None;
        const auto p = expectProblem(fitRectangle(t, {kBall, false, 0.01}));
        QCOMPARE(p.point, 3);
    }
};

QTEST_APPLESS_MAIN(TestProbeFit)
#include "test_probe_fit.moc"
