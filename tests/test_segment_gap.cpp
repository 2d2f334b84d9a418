// The exact gap between two contour segments (core/paths/segment_gap.h) and
// the side-milling chain proof built on it (paths::chainClearance): on
// random lines and arcs (crossing, tangent, concentric, nested, far apart)
// the gap must be reached by points truly on both segments and must be no
// more than a dense brute force finds (the distance is 1-Lipschitz along a
// segment, so the brute force is within its spacing); crossings give 0; and
// on generated contours the chains' clearance must agree with probing them
// densely — exactly the offset where the chain keeps off, less in a channel
// narrower than the tool.
#include "paths/contour_offset.h"
#include "paths/segment_gap.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace taiwa;
using taiwa::paths::segmentGap;

namespace {

constexpr double kPi = std::numbers::pi;

ContourSegment randomSegment(std::mt19937& rng)
{
    std::uniform_real_distribution<double> coord(-50.0, 50.0), radius(0.5, 40.0), angle(-kPi, kPi), sweep(0.05, 2 * kPi - 0.05);
    std::uniform_int_distribution<int> kind(0, 2);
    const int k = kind(rng);
    if (k == 0) return ContourSegment::line({coord(rng), coord(rng)}, {coord(rng), coord(rng)});
    const Point2 c{coord(rng), coord(rng)};
    const double r = radius(rng), a0 = angle(rng), s = sweep(rng);
    const bool ccw = k == 1;
    const double a1 = ccw ? a0 + s : a0 - s;
    return ContourSegment::arc(c + r * Point2{std::cos(a0), std::sin(a0)}, c + r * Point2{std::cos(a1), std::sin(a1)}, c, ccw);
}

// The least distance from n + 1 points spread along a to the segment b
// (exact point-to-segment distances).
double sampledGap(const ContourSegment& a, const ContourSegment& b, int n)
{
    double best = 1e300;
    for (int i = 0; i <= n; ++i) {
        const Point2 p = a.at(static_cast<double>(i) / n);
        best = std::min(best, distance(p, b.nearest(p)));
    }
    return best;
}

void checkPair(const ContourSegment& a, const ContourSegment& b, const char* what)
{
    constexpr int kSamples = 20000;
    const paths::SegmentGap g = segmentGap(a, b);
    // The points are on the segments and the gap is theirs.
    QVERIFY2(distance(a.nearest(g.onA), g.onA) < 1e-9, what);
    QVERIFY2(distance(b.nearest(g.onB), g.onB) < 1e-9, what);
    QVERIFY2(std::abs(distance(g.onA, g.onB) - g.gap) < 1e-12, what);
    // No nearer pair: the dense brute force, either way round, never finds
    // less, and finds as little within its spacing.
    const double brute = std::min(sampledGap(a, b, kSamples), sampledGap(b, a, kSamples));
    const double spacing = std::max(a.length(), b.length()) / kSamples;
    QVERIFY2(g.gap <= brute + 1e-9, qPrintable(QString("%1: exact %2 > sampled %3").arg(what).arg(g.gap, 0, 'g', 12).arg(brute, 0, 'g', 12)));
    QVERIFY2(brute - g.gap <= spacing, qPrintable(QString("%1: exact %2, sampled %3").arg(what).arg(g.gap, 0, 'g', 12).arg(brute, 0, 'g', 12)));
    QVERIFY2(std::abs(segmentGap(b, a).gap - g.gap) < 1e-9, what);
}

Contour roundedRectangle(Point2 lo, Point2 hi, double r)
{
    Contour k;
    k.closed = true;
    const auto arc = [&](Point2 c, double a0) {
        const Point2 from = c + r * Point2{std::cos(a0), std::sin(a0)};
        const Point2 to = c + r * Point2{std::cos(a0 + kPi / 2), std::sin(a0 + kPi / 2)};
        if (!k.segments.empty()) k.segments.push_back(ContourSegment::line(k.segments.back().end, from));
        k.segments.push_back(ContourSegment::arc(from, to, c, true));
    };
    arc({hi.x - r, lo.y + r}, -kPi / 2);
    arc({hi.x - r, hi.y - r}, 0.0);
    arc({lo.x + r, hi.y - r}, kPi / 2);
    arc({lo.x + r, lo.y + r}, kPi);
    k.segments.push_back(ContourSegment::line(k.segments.back().end, k.segments.front().start));
    return k;
}

// The clearance found by probing the chains every `spacing` mm.
double probedClearance(const Contour& c, const std::vector<Contour>& chains, double spacing)
{
    double best = 1e300;
    for (const Contour& chain : chains)
        for (const ContourSegment& s : chain.segments) {
            const int n = std::max(1, static_cast<int>(std::ceil(s.length() / spacing)));
            for (int i = 0; i <= n; ++i) best = std::min(best, distanceTo(c, s.at(static_cast<double>(i) / n)));
        }
    return best;
}

}  // namespace

class TestSegmentGap : public QObject {
    Q_OBJECT
private slots:
    void randomPairsAgreeWithTheBruteForce()
    {
        std::mt19937 rng(20261130);
        for (int i = 0; i < 600; ++i) {
            const ContourSegment a = randomSegment(rng), b = randomSegment(rng);
            checkPair(a, b, qPrintable(QString("pair %1").arg(i)));
        }
    }

    void crossingsTangenciesAndConcentricArcs()
    {
        const auto line = ContourSegment::line;
        const auto arc = ContourSegment::arc;
        // Two lines crossing in their middles.
        QCOMPARE(segmentGap(line({-1, -1}, {1, 1}), line({-1, 1}, {1, -1})).gap, 0.0);
        // A line through an arc's middle (the arc's ends far from it).
        const ContourSegment upper = arc({10, 0}, {-10, 0}, {0, 0}, true);
        QVERIFY(segmentGap(line({0, -5}, {0, 20}), upper).gap < 1e-12);
        // A line missing the arc by 2 above its top: the gap is square to it.
        const paths::SegmentGap above = segmentGap(line({-30, 12}, {30, 12}), upper);
        QVERIFY(std::abs(above.gap - 2.0) < 1e-12);
        QVERIFY(distance(above.onB, {0, 10}) < 1e-9);
        // Tangent: the same line at the top touches it.
        QVERIFY(segmentGap(line({-30, 10}, {30, 10}), upper).gap < 1e-9);
        // Two arcs of circles crossing, on the parts that cross.
        QVERIFY(segmentGap(arc({10, 0}, {-10, 0}, {0, 0}, true), arc({-5, 0}, {25, 0}, {10, 0}, false)).gap < 1e-12);
        // Concentric arcs: where their angles overlap, the radii's difference;
        // where not, end to end.
        QVERIFY(std::abs(segmentGap(upper, arc({4, 0}, {0, 4}, {0, 0}, true)).gap - 6.0) < 1e-12);
        const paths::SegmentGap apart = segmentGap(upper, arc({0, -4}, {4, 0}, {0, 0}, true));
        QVERIFY(std::abs(apart.gap - 6.0) < 1e-12);
        QVERIFY(distance(apart.onA, {10, 0}) < 1e-12 && distance(apart.onB, {4, 0}) < 1e-12);
        // An arc around a line's middle, the line inside the circle: the gap
        // is to the arc's ends, not square.
        const ContourSegment lower = arc({-10, 0}, {10, 0}, {0, 0}, true);  // the lower half
        QVERIFY(std::abs(segmentGap(line({-3, 4}, {3, 4}), lower).gap - distance({-3, 4}, {-10, 0})) < 1e-12);
    }

    // A boss's chains keep exactly their offset; an open hook whose end
    // comes back near its start: the clearance finds the part the trimming
    // of neighbours did not see, as near as probing finds it.
    void chainClearanceIsTheProbesLimit()
    {
        const Contour boss = roundedRectangle({0, 0}, {80, 50}, 6.0);
        for (const double d : {3.0, 7.5, 20.0}) {
            const bool left = !paths::toolInside(boss, true);  // outside the boss
            const auto chains = paths::offsetSide(boss, left, d);
            QVERIFY(chains && !chains->empty());
            const paths::Clearance c = paths::chainClearance(boss, *chains);
            QVERIFY2(std::abs(c.nearest - d) < 1e-9, qPrintable(QString::number(c.nearest, 'g', 15)));
            QVERIFY(c.nearest <= probedClearance(boss, *chains, 0.05) + 1e-12);
        }
        // A hook (test_side_milling's channel): along y 20, round a circle
        // of radius 20, back along y 60, down x 50 to 1.5 mm above its start.
        Contour hook;
        hook.segments = {ContourSegment::line({-15, 20}, {100, 20}), ContourSegment::arc({100, 20}, {100, 60}, {100, 40}, true),
                         ContourSegment::line({100, 60}, {50, 60}), ContourSegment::line({50, 60}, {50, 21.5})};
        // d 1: the first run's chain (y 21) passes 0.5 under the last
        // segment's end; d 4: it (y 24) crosses the last segment.
        for (const auto& [d, expected] : {std::pair{1.0, 0.5}, std::pair{4.0, 0.0}}) {
            const auto chains = paths::offsetSide(hook, true, d);  // inside the hook
            QVERIFY(chains && !chains->empty());
            const paths::Clearance c = paths::chainClearance(hook, *chains);
            const double probed = probedClearance(hook, *chains, 0.01);
            QVERIFY2(std::abs(c.nearest - expected) < 1e-9 && c.nearest <= probed + 1e-12 && probed - c.nearest <= 0.01,
                     qPrintable(QString("d %1: exact %2, probed %3").arg(d).arg(c.nearest).arg(probed)));
        }
    }
};

QTEST_APPLESS_MAIN(TestSegmentGap)
#include "test_segment_gap.moc"
