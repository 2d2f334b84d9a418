// The exact inward offset of pocket regions (core/paths/region_offset.h):
// hand-computed cases to 1e-6 mm (a rectangle, rounded corners, the inner
// corner of an L, a round island, islands whose loops merge, an island that
// splits the pocket, an offset too large), and on every answer: each point of
// each segment at distance d from the region's boundary on the pocket side,
// loops closed, outer loops counter-clockwise and island loops clockwise,
// arcs kept as arcs. Also the time of one offset of a 2,000-segment gear
// outline with 20 islands.
#include "paths/region_offset.h"

#include <QElapsedTimer>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::paths;

namespace {

constexpr double kTol = 1e-6;
constexpr double kPi = std::numbers::pi;

Contour polygon(const std::vector<Point2>& pts)
{
    Contour c;
    c.closed = true;
    for (std::size_t i = 0; i < pts.size(); ++i) c.segments.push_back(ContourSegment::line(pts[i], pts[(i + 1) % pts.size()]));
    return c;
}

Contour rectangle(double x0, double y0, double x1, double y1) { return polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}); }

Contour circle(Point2 c, double r, bool ccw)
{
    const Point2 p{c.x + r, c.y};
    return Contour{{ContourSegment::arc(p, p, c, ccw)}, true};
}

// A rectangle with corner arcs of radius r, counter-clockwise.
Contour roundedRectangle(double x0, double y0, double x1, double y1, double r)
{
    Contour c;
    c.closed = true;
    const auto line = [&](Point2 a, Point2 b) { c.segments.push_back(ContourSegment::line(a, b)); };
    const auto arc = [&](Point2 a, Point2 b, Point2 m) { c.segments.push_back(ContourSegment::arc(a, b, m, true)); };
    line({x0 + r, y0}, {x1 - r, y0});
    arc({x1 - r, y0}, {x1, y0 + r}, {x1 - r, y0 + r});
    line({x1, y0 + r}, {x1, y1 - r});
    arc({x1, y1 - r}, {x1 - r, y1}, {x1 - r, y1 - r});
    line({x1 - r, y1}, {x0 + r, y1});
    arc({x0 + r, y1}, {x0, y1 - r}, {x0 + r, y1 - r});
    line({x0, y1 - r}, {x0, y0 + r});
    arc({x0, y0 + r}, {x0 + r, y0}, {x0 + r, y0 + r});
    return c;
}

int count(const Contour& c, ContourSegment::Kind kind)
{
    return static_cast<int>(std::count_if(c.segments.begin(), c.segments.end(), [&](const auto& s) { return s.kind == kind; }));
}

int arcs(const std::vector<Region>& pieces)
{
    int n = 0;
    for (const auto& c : loopsOf(pieces)) n += count(c, ContourSegment::Kind::ArcCCW) + count(c, ContourSegment::Kind::ArcCW);
    return n;
}

bool hasSegment(const Contour& c, const ContourSegment& want)
{
    for (const auto& s : c.segments)
        if (s.kind == want.kind && distance(s.start, want.start) < kTol && distance(s.end, want.end) < kTol &&
            (!s.isArc() || distance(s.centre, want.centre) < kTol))
            return true;
    return false;
}

// What every answer must be: closed loops, outer counter-clockwise and
// islands clockwise inside their outer loop, every sampled point of every
// segment (and the arc radii) at exactly d from the boundary on the pocket
// side.
void checkOffset(const Region& region, const std::vector<Region>& pieces, double d, int samples)
{
    for (const auto& piece : pieces) {
        QVERIFY(signedArea(piece.outer) > 0.0);
        for (const auto& island : piece.islands) {
            QVERIFY(signedArea(island) < 0.0);
            QVERIFY(contains(piece.outer, island.segments.front().start));
        }
    }
    for (const auto& loop : loopsOf(pieces)) {
        QVERIFY(loop.closed);
        QVERIFY(!loop.empty());
        QVERIFY2(largestGap(loop) < kTol, qPrintable(QString::number(largestGap(loop))));
        for (const auto& s : loop.segments) {
            if (s.isArc()) QVERIFY(std::abs(distance(s.start, s.centre) - distance(s.end, s.centre)) < kTol);
            for (int k = 0; k <= samples; ++k) {
                const Point2 p = s.at(static_cast<double>(k) / samples);
                // The side is found once a loop (signedDistance flattens the
                // region each time: slow on the gear), the distance everywhere.
                double sd = distanceTo(region.outer, p);
                for (const auto& island : region.islands) sd = std::min(sd, distanceTo(island, p));
                if (k == 0 && &s == &loop.segments.front()) sd = signedDistance(region, p);
                else sd = -sd;
                QVERIFY2(std::abs(sd + d) < kTol, qPrintable(QStringLiteral("(%1, %2) at %3 from the boundary, not -%4")
                                                                 .arg(p.x, 0, 'f', 9)
                                                                 .arg(p.y, 0, 'f', 9)
                                                                 .arg(sd, 0, 'f', 9)
                                                                 .arg(d)));
            }
        }
    }
}

std::vector<Region> offsetOk(const Region& region, double d)
{
    auto r = offsetRegion(region, d);
    if (!r) qWarning("%s", r.error().c_str());
    return r ? r.value() : std::vector<Region>{};
}

// A gear of `teeth` teeth around the origin (4 segments each: flank, tip
// arc, flank, root arc), counter-clockwise, and `islands` islands on a ring
// inside it: round ones and rounded squares by turns.
Region gear(int teeth, double root, double tip, int islands)
{
    Region r;
    r.outer.closed = true;
    const double pitch = 2.0 * kPi / teeth;
    const auto at = [](double radius, double a) { return Point2{radius * std::cos(a), radius * std::sin(a)}; };
    for (int k = 0; k < teeth; ++k) {
        const double a0 = k * pitch, a1 = a0 + 0.5 * pitch, a2 = a0 + pitch;
        r.outer.segments.push_back(ContourSegment::line(at(root, a0), at(tip, a0)));
        r.outer.segments.push_back(ContourSegment::arc(at(tip, a0), at(tip, a1), {0, 0}, true));
        r.outer.segments.push_back(ContourSegment::line(at(tip, a1), at(root, a1)));
        r.outer.segments.push_back(ContourSegment::arc(at(root, a1), at(root, k + 1 == teeth ? 0.0 : a2), {0, 0}, true));
    }
    for (int i = 0; i < islands; ++i) {
        const Point2 c = at(0.6 * root, 2.0 * kPi * i / islands);
        if (i % 2 == 0) {
            r.islands.push_back(circle(c, 15.0, false));
        } else {
            r.islands.push_back(reversed(roundedRectangle(c.x - 12, c.y - 12, c.x + 12, c.y + 12, 4.0)));
        }
    }
    return r;
}

}  // namespace

class TestRegionOffset : public QObject {
    Q_OBJECT
private slots:
    void rectangleGivesTheSmallerRectangle()
    {
        const Region region{rectangle(0, 0, 100, 60), {}};
        const auto pieces = offsetOk(region, 5.0);
        QCOMPARE(pieces.size(), std::size_t{1});
        const Contour& c = pieces[0].outer;
        QVERIFY(pieces[0].islands.empty());
        QCOMPARE(c.segments.size(), std::size_t{4});
        QCOMPARE(count(c, ContourSegment::Kind::Line), 4);
        QVERIFY(std::abs(signedArea(c) - 90.0 * 50.0) < kTol);
        for (const Point2 p : {Point2{5, 5}, Point2{95, 5}, Point2{95, 55}, Point2{5, 55}}) {
            bool found = false;
            for (const auto& s : c.segments) found = found || distance(s.start, p) < kTol;
            QVERIFY(found);
        }
        checkOffset(region, pieces, 5.0, 50);
    }
    void clockwiseInputIsTheSamePocket()
    {
        const Region region{reversed(rectangle(0, 0, 100, 60)), {}};
        const auto pieces = offsetOk(region, 5.0);
        QCOMPARE(pieces.size(), std::size_t{1});
        QVERIFY(std::abs(signedArea(pieces[0].outer) - 90.0 * 50.0) < kTol);
    }
    void cornerArcsBecomeConcentricArcs()
    {
        const Region region{roundedRectangle(0, 0, 100, 60, 10.0), {}};
        const auto pieces = offsetOk(region, 4.0);
        QCOMPARE(pieces.size(), std::size_t{1});
        const Contour& c = pieces[0].outer;
        QCOMPARE(c.segments.size(), std::size_t{8});
        QCOMPARE(count(c, ContourSegment::Kind::ArcCCW), 4);
        QVERIFY(hasSegment(c, ContourSegment::arc({90, 4}, {96, 10}, {90, 10}, true)));
        QVERIFY(hasSegment(c, ContourSegment::arc({96, 50}, {90, 56}, {90, 50}, true)));
        QVERIFY(hasSegment(c, ContourSegment::arc({10, 56}, {4, 50}, {10, 50}, true)));
        QVERIFY(hasSegment(c, ContourSegment::arc({4, 10}, {10, 4}, {10, 10}, true)));
        QVERIFY(hasSegment(c, ContourSegment::line({10, 4}, {90, 4})));
        for (const auto& s : c.segments)
            if (s.isArc()) QVERIFY(std::abs(s.radius() - 6.0) < kTol);
        checkOffset(region, pieces, 4.0, 50);
    }
    void innerCornerOfAnLGivesAnArcOfTheToolRadius()
    {
        // The L's corner at (40, 40) points into the pocket: the tool centre
        // runs round it on a radius of d, clockwise within the
        // counter-clockwise loop.
        const Region region{polygon({{0, 0}, {100, 0}, {100, 40}, {40, 40}, {40, 100}, {0, 100}}), {}};
        const auto pieces = offsetOk(region, 5.0);
        QCOMPARE(pieces.size(), std::size_t{1});
        const Contour& c = pieces[0].outer;
        QCOMPARE(count(c, ContourSegment::Kind::Line), 6);
        QCOMPARE(count(c, ContourSegment::Kind::ArcCW), 1);
        QCOMPARE(count(c, ContourSegment::Kind::ArcCCW), 0);
        QVERIFY(hasSegment(c, ContourSegment::arc({40, 35}, {35, 40}, {40, 40}, false)));
        QVERIFY(hasSegment(c, ContourSegment::line({95, 35}, {40, 35})));
        QVERIFY(hasSegment(c, ContourSegment::line({35, 40}, {35, 95})));
        QVERIFY(hasSegment(c, ContourSegment::line({95, 5}, {95, 35})));
        checkOffset(region, pieces, 5.0, 50);
    }
    void roundIslandGrowsToALargerCircle()
    {
        const Region region{rectangle(0, 0, 100, 60), {circle({50, 30}, 10.0, false)}};
        const auto pieces = offsetOk(region, 5.0);
        QCOMPARE(pieces.size(), std::size_t{1});
        QCOMPARE(pieces[0].islands.size(), std::size_t{1});
        const Contour& island = pieces[0].islands[0];
        QCOMPARE(island.segments.size(), std::size_t{1});
        const ContourSegment& s = island.segments[0];
        QCOMPARE(s.kind, ContourSegment::Kind::ArcCW);
        QVERIFY(distance(s.start, s.end) < kTol);  // a full circle
        QVERIFY(distance(s.centre, {50, 30}) < kTol);
        QVERIFY(std::abs(s.radius() - 15.0) < kTol);
        QVERIFY(std::abs(signedArea(island) + kPi * 15.0 * 15.0) < kTol);
        QVERIFY(std::abs(signedArea(pieces[0].outer) - 90.0 * 50.0) < kTol);
        checkOffset(region, pieces, 5.0, 50);
    }
    void islandsCloseTogetherMergeIntoOneLoop()
    {
        const Region region{rectangle(0, 0, 100, 60), {circle({35, 30}, 10.0, false), circle({65, 30}, 10.0, false)}};
        const auto apart = offsetOk(region, 4.0);  // R14 circles 30 apart: two loops
        QCOMPARE(apart.size(), std::size_t{1});
        QCOMPARE(apart[0].islands.size(), std::size_t{2});
        checkOffset(region, apart, 4.0, 50);

        const auto merged = offsetOk(region, 6.0);  // R16 circles 30 apart: one loop of two arcs
        QCOMPARE(merged.size(), std::size_t{1});
        QCOMPARE(merged[0].islands.size(), std::size_t{1});
        const Contour& island = merged[0].islands[0];
        QCOMPARE(island.segments.size(), std::size_t{2});
        QCOMPARE(count(island, ContourSegment::Kind::ArcCW), 2);
        const double h = std::sqrt(16.0 * 16.0 - 15.0 * 15.0);  // where the two circles cross
        QVERIFY(hasSegment(island, ContourSegment::arc({50, 30 - h}, {50, 30 + h}, {35, 30}, false)));
        QVERIFY(hasSegment(island, ContourSegment::arc({50, 30 + h}, {50, 30 - h}, {65, 30}, false)));
        checkOffset(region, merged, 6.0, 50);
    }
    void islandMeetingTheWallsSplitsThePocket()
    {
        // R10 island grown by 12 reaches past the shrunk walls at y = 12 and
        // y = 48: the tool-centre area falls apart into a left and a right
        // piece, each an outer loop of three lines and one arc of the island.
        const Region region{rectangle(0, 0, 100, 60), {circle({50, 30}, 10.0, false)}};
        const auto pieces = offsetOk(region, 12.0);
        QCOMPARE(pieces.size(), std::size_t{2});
        for (const auto& p : pieces) {
            QVERIFY(p.islands.empty());
            QCOMPARE(count(p.outer, ContourSegment::Kind::ArcCW), 1);
            QCOMPARE(count(p.outer, ContourSegment::Kind::Line), 3);
        }
        const double x = std::sqrt(22.0 * 22.0 - 18.0 * 18.0);  // where the R22 circle meets y = 12 and y = 48
        const Contour& left = pieces[0].outer.segments.front().start.x < 50 ? pieces[0].outer : pieces[1].outer;
        QVERIFY(hasSegment(left, ContourSegment::line({12, 12}, {50 - x, 12})));
        QVERIFY(hasSegment(left, ContourSegment::arc({50 - x, 12}, {50 - x, 48}, {50, 30}, false)));
        QVERIFY(std::abs(area(pieces[0]) - area(pieces[1])) < kTol);
        checkOffset(region, pieces, 12.0, 50);
    }
    void offsetTooLargeLeavesNothing()
    {
        const Region region{rectangle(0, 0, 100, 60), {}};
        auto r = offsetRegion(region, 31.0);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QVERIFY(r->empty());
        auto withIsland = offsetRegion(Region{rectangle(0, 0, 100, 60), {circle({50, 30}, 10.0, false)}}, 25.0);
        QVERIFY(withIsland.ok());
        QVERIFY(withIsland->empty());
    }
    void zeroAndNegativeOffsets()
    {
        const Region region{rectangle(0, 0, 100, 60), {circle({50, 30}, 10.0, true)}};
        auto zero = offsetRegion(region, 0.0);
        QVERIFY(zero.ok());
        QCOMPARE(zero->size(), std::size_t{1});
        QCOMPARE(zero->front(), normalised(region));
        QVERIFY(!offsetRegion(region, -1.0).ok());
    }
    void brokenInputIsAFailureNotACrash()
    {
        Contour open = rectangle(0, 0, 100, 60);
        open.segments[1].end = {100, 50};  // the loop does not close
        const auto r = offsetRegion(Region{open, {}}, 5.0);
        QVERIFY(!r.ok());
        QVERIFY(!r.error().empty());
    }
    void roundedIslandsAndArcsStayArcs()
    {
        Region region{roundedRectangle(0, 0, 200, 120, 15.0),
                      {reversed(roundedRectangle(30, 30, 70, 60, 8.0)), circle({120, 50}, 12.0, false),
                       polygon({{150, 80}, {150, 100}, {170, 100}})}};
        for (double d : {2.0, 5.0, 9.0, 14.0}) {
            const auto pieces = offsetOk(region, d);
            QVERIFY(!pieces.empty());
            QVERIFY(arcs(pieces) >= 4 + 4 + 1 + 3);  // outer corners, rounded island, circle, triangle corners
            checkOffset(region, pieces, d, 50);
        }
    }
    void gearWithTwentyIslands()
    {
        const Region region = gear(500, 400.0, 410.0, 20);
        QCOMPARE(region.outer.segments.size(), std::size_t{2000});
        for (double d : {1.0, 3.0}) {
            // The best of three runs: the build machine is shared.
            std::vector<Region> pieces;
            double ms = 1e9;
            for (int run = 0; run < 3; ++run) {
                QElapsedTimer timer;
                timer.start();
                pieces = offsetOk(region, d);
                ms = std::min(ms, static_cast<double>(timer.nsecsElapsed()) / 1e6);
            }
            std::size_t segments = 0;
            for (const auto& c : loopsOf(pieces)) segments += c.segments.size();
            qInfo("gear of 2000 segments, 20 islands, d = %.0f: %.1f ms, %zu pieces, %zu loops, %zu segments, %d arcs", d,
                  ms, pieces.size(), loopsOf(pieces).size(), segments, arcs(pieces));
            QCOMPARE(pieces.size(), std::size_t{1});
            QCOMPARE(pieces[0].islands.size(), std::size_t{20});
            QVERIFY(arcs(pieces) >= 1000);
            checkOffset(region, pieces, d, 3);
        }
    }
};

QTEST_GUILESS_MAIN(TestRegionOffset)
#include "test_region_offset.moc"
