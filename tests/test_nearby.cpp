// The boundary's nearness tree (core/paths/nearby.h), the test every piece
// of an exact offset goes through: on generated outlines (n-gons, rounded
// polygons, stars, arcs over half a circle, islands) its answer must be
// the brute force's (the exact distance to every segment) for random points
// and for limits a hair either side of the true distance; and the query the
// grid it replaced spent O(n) on — a disc nearly tangent to a round outline
// from inside — must look at O(log n) nodes.
#include "paths/nearby.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

using namespace taiwa;
using taiwa::paths::offset::Nearby;

namespace {

constexpr double kPi = std::numbers::pi;

Contour ngon(int n, Point2 c, double r, double phase = 0.0)
{
    Contour k;
    k.closed = true;
    for (int i = 0; i < n; ++i) {
        const double a0 = phase + 2 * kPi * i / n, a1 = phase + 2 * kPi * (i + 1) / n;
        k.segments.push_back(ContourSegment::line(c + Point2{r * std::cos(a0), r * std::sin(a0)}, c + Point2{r * std::cos(a1), r * std::sin(a1)}));
    }
    return k;
}

// A regular n-gon whose corners are rounded by arcs of radius `round`.
Contour roundedNgon(int n, Point2 c, double r, double round)
{
    Contour k;
    k.closed = true;
    const double turn = 2 * kPi / n, back = round / std::cos(turn / 2);  // corner to arc centre
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * i / n;
        const Point2 corner = c + Point2{r * std::cos(a), r * std::sin(a)};
        const Point2 centre = corner - back * Point2{std::cos(a), std::sin(a)};
        const double in = a - turn / 2, out = a + turn / 2;
        const Point2 from = centre + round * Point2{std::cos(in), std::sin(in)};
        const Point2 to = centre + round * Point2{std::cos(out), std::sin(out)};
        if (!k.segments.empty()) k.segments.push_back(ContourSegment::line(k.segments.back().end, from));
        k.segments.push_back(ContourSegment::arc(from, to, centre, true));
    }
    k.segments.push_back(ContourSegment::line(k.segments.back().end, k.segments.front().start));
    return k;
}

Contour star(int n, std::mt19937& rng)
{
    std::uniform_real_distribution<double> radius(20.0, 100.0);
    std::vector<Point2> pts;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * i / n, r = radius(rng);
        pts.push_back({r * std::cos(a), r * std::sin(a)});
    }
    Contour k;
    k.closed = true;
    for (int i = 0; i < n; ++i) k.segments.push_back(ContourSegment::line(pts[i], pts[(i + 1) % n]));
    return k;
}

// Two arcs, of 270° and 90°, round one centre: arcs past a half circle.
Contour bigArcs(Point2 c, double r)
{
    const Point2 a = c + Point2{r, 0.0}, b = c + Point2{0.0, -r};
    return Contour{{ContourSegment::arc(a, b, c, true), ContourSegment::arc(b, a, c, true)}, true};
}

std::vector<const ContourSegment*> segmentsOf(const std::vector<Contour>& loops)
{
    std::vector<const ContourSegment*> out;
    for (const auto& l : loops)
        for (const auto& s : l.segments) out.push_back(&s);
    return out;
}

double nearestDistance(const std::vector<const ContourSegment*>& segs, Point2 p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto* s : segs) best = std::min(best, distance(p, s->nearest(p)));
    return best;
}

// The tree against the brute force at `queries` random points of the box
// round the loops: limits at random, and a hair either side of the truth.
void agreesWithBruteForce(const std::vector<Contour>& loops, std::mt19937& rng, int queries)
{
    const auto segs = segmentsOf(loops);
    const Nearby nearby(segs);
    Box2 box = bounds(loops.front());
    std::uniform_real_distribution<double> x(box.min.x - 10, box.max.x + 10), y(box.min.y - 10, box.max.y + 10), u(0.0, 1.0);
    for (int q = 0; q < queries; ++q) {
        const Point2 p{x(rng), y(rng)};
        const double truth = nearestDistance(segs, p);
        const double someLimit = u(rng) * 2.0 * truth;
        QCOMPARE(nearby.anyNearer(p, someLimit), truth < someLimit);
        QVERIFY2(nearby.anyNearer(p, truth * (1 + 1e-9) + 1e-12), "a limit just past the nearest segment finds it");
        QVERIFY2(!nearby.anyNearer(p, truth * (1 - 1e-9)), "a limit just short of the nearest segment finds nothing");
    }
}

}  // namespace

class TestNearby : public QObject {
    Q_OBJECT
private slots:
    void answersAsTheBruteForceDoes()
    {
        std::mt19937 rng(7);
        agreesWithBruteForce({ngon(5, {0, 0}, 50)}, rng, 300);
        agreesWithBruteForce({ngon(1000, {10, -20}, 400, 0.3)}, rng, 300);
        agreesWithBruteForce({roundedNgon(7, {0, 0}, 80, 3)}, rng, 300);
        agreesWithBruteForce({roundedNgon(600, {0, 0}, 300, 0.2)}, rng, 300);
        agreesWithBruteForce({star(200, rng)}, rng, 300);
        agreesWithBruteForce({bigArcs({5, 5}, 40)}, rng, 300);
        // An outline with islands: the loops follow one another in the tree.
        agreesWithBruteForce({ngon(300, {0, 0}, 200), ngon(40, {-80, 0}, 30, 0.1), bigArcs({90, 20}, 25), roundedNgon(9, {0, 110}, 40, 2)},
                             rng, 300);
    }

    void anEmptyBoundaryHasNothingNear()
    {
        const std::vector<const ContourSegment*> none;
        QVERIFY(!Nearby(none).anyNearer({0, 0}, 1e9));
    }

    // The offsets near the inscribed radius of a round pocket: a disc of
    // radius d about a point at d - 1 µm from the outline touches the
    // outline's whole stretch within a box's slack. The nodes looked at
    // must grow as log n, not √n (the grid's) or n.
    void aNearlyTangentDiscLooksAtLogNNodes()
    {
        std::vector<std::pair<int, std::size_t>> visits;
        for (int n : {1024, 4096, 16384, 65536}) {
            const Contour outline = roundedNgon(n, {500, 500}, 400, 1.0);
            const std::vector<Contour> loops{outline};
            const auto segs = segmentsOf(loops);
            const Nearby nearby(segs);
            std::size_t most = 0;
            for (double d : {10.0, 64.0, 100.0, 300.0}) {
                for (int k = 0; k < 50; ++k) {
                    const double a = 2 * kPi * k / 50 + 0.01;
                    const Point2 p = Point2{500, 500} + (396.0 - d) * Point2{std::cos(a), std::sin(a)};
                    const double truth = nearestDistance(segs, p);
                    QVERIFY(!nearby.anyNearer(p, truth - 1e-6));
                    most = std::max(most, nearby.lastVisited());
                }
            }
            visits.push_back({n, most});
            const double log2n = std::log2(static_cast<double>(segs.size()));
            QVERIFY2(static_cast<double>(most) <= 8.0 * log2n,
                     qPrintable(QStringLiteral("%1 segments: %2 nodes looked at, more than 8 log2 n").arg(segs.size()).arg(most)));
        }
        qInfo("nodes looked at, most of 200 nearly tangent queries: %d: %zu, %d: %zu, %d: %zu, %d: %zu", visits[0].first, visits[0].second,
              visits[1].first, visits[1].second, visits[2].first, visits[2].second, visits[3].first, visits[3].second);
    }
};

QTEST_GUILESS_MAIN(TestNearby)
#include "test_nearby.moc"
