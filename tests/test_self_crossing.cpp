// Whether a contour crosses itself (core/modules/self_crossing.h), on
// generated shapes: regular polygons of up to 8,192 sides and star-shaped
// polygons are simple; a bow tie, a polygon touching itself at a corner and
// random polygons that a brute-force test finds crossing are not; open
// chains likewise. The grid's pairing must agree with looking at every pair.
#include "modules/self_crossing.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace taiwa;

namespace {

Contour polyline(const std::vector<Point2>& p, bool closed)
{
    Contour c;
    c.closed = closed;
    const std::size_t n = p.size(), edges = closed ? n : n - 1;
    for (std::size_t k = 0; k < edges; ++k) c.segments.push_back(ContourSegment::line(p[k], p[(k + 1) % n]));
    return c;
}

std::vector<Point2> regular(int n, double r)
{
    std::vector<Point2> p;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        p.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return p;
}

// Whether two edges that are not neighbours cross properly: every pair.
bool bruteForceCrosses(const std::vector<Point2>& p, bool closed)
{
    const std::size_t n = p.size(), edges = closed ? n : n - 1;
    const auto proper = [](Point2 a, Point2 b, Point2 c, Point2 d) {
        const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
        return d1 * d2 < 0 && d3 * d4 < 0;
    };
    for (std::size_t i = 0; i < edges; ++i)
        for (std::size_t j = i + 2; j < edges; ++j) {
            if (closed && i == 0 && j == edges - 1) continue;
            if (proper(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return true;
        }
    return false;
}

}  // namespace

class TestSelfCrossing : public QObject {
    Q_OBJECT
private slots:
    void regularPolygonsAreSimple()
    {
        for (int n : {3, 4, 5, 64, 1000, 8192}) {
            QVERIFY2(!crossesItself(polyline(regular(n, 100.0), true)), qPrintable(QString::number(n)));
            QVERIFY2(!crossesItself(polyline(regular(n, 100.0), false)), qPrintable(QString::number(n)));
        }
    }

    void aBowTieAndATouchCross()
    {
        QVERIFY(crossesItself(polyline({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, true)));
        // Two squares meeting at one corner, run as one contour: Clipper's
        // union splits it there, so it counts as crossing.
        QVERIFY(crossesItself(polyline({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}, true)));
        // A spike (an edge going back along the one before it) is not
        // simple, so Clipper judges it: its union is the quadrilateral
        // without the spike, one piece of the same area, so it does not
        // cross (as before the grid's test).
        QVERIFY(!crossesItself(polyline({{0, 0}, {10, 0}, {10, 10}, {10, 5}, {0, 10}}, true)));
        // An open chain that comes back over its first piece.
        QVERIFY(crossesItself(polyline({{0, 0}, {10, 0}, {10, 10}, {5, -5}}, false)));
    }

    // Star-shaped polygons (random radii at increasing angles) are simple;
    // random polygons are compared with every pair looked at.
    void generatedShapesAgreeWithEveryPair()
    {
        std::mt19937 rng(20261130);
        std::uniform_real_distribution<double> radius(20.0, 100.0), coordinate(-100.0, 100.0);
        int crossing = 0;
        for (int shape = 0; shape < 300; ++shape) {
            const int n = 4 + shape % 200;
            std::vector<Point2> star;
            for (int k = 0; k < n; ++k) {
                const double a = 2 * std::numbers::pi * k / n, r = radius(rng);
                star.push_back({r * std::cos(a), r * std::sin(a)});
            }
            QVERIFY2(!crossesItself(polyline(star, true)), qPrintable(QStringLiteral("star %1").arg(shape)));
            std::vector<Point2> random;
            for (int k = 0; k < 4 + shape % 30; ++k) random.push_back({coordinate(rng), coordinate(rng)});
            for (const bool closed : {true, false}) {
                const bool brute = bruteForceCrosses(random, closed);
                crossing += brute;
                // A proper crossing is a crossing; none at all (a simple
                // random polygon) is simple.
                if (brute) QVERIFY2(crossesItself(polyline(random, closed)), qPrintable(QStringLiteral("random %1").arg(shape)));
                else QVERIFY2(!crossesItself(polyline(random, closed)), qPrintable(QStringLiteral("random %1").arg(shape)));
            }
        }
        QVERIFY(crossing > 300);  // most random polygons cross: the test sees both answers
    }
};

QTEST_GUILESS_MAIN(TestSelfCrossing)
#include "test_self_crossing.moc"
