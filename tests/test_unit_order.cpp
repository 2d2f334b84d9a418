// The machining order of units through its grid: the same order as a plain
// nearest-neighbour scan (nearest first from the first unit, ties to the
// earlier unit), on thousands of centres with many ties.
#include "check/unit_checks.h"

#include <QtTest>

#include <random>

using namespace taiwa;

class TestUnitOrder : public QObject {
    Q_OBJECT
private slots:
    void unitOrderThroughTheGridEqualsTheScan()
    {
        // The grid search gives the order a plain scan gives (nearest first,
        // ties to the earlier unit), here on 3,000 centres with many ties.
        std::mt19937 random(7);
        std::uniform_int_distribution<int> coord(0, 60);
        std::vector<Point2> centres;
        for (int i = 0; i < 3000; ++i) centres.push_back({coord(random) * 2.5, coord(random) * 1.5});
        std::vector<int> scan;
        std::vector<bool> done(centres.size(), false);
        std::size_t current = 0;
        for (std::size_t k = 0; k < centres.size(); ++k) {
            scan.push_back(static_cast<int>(current));
            done[current] = true;
            std::size_t next = centres.size();
            double best = 1e300;
            for (std::size_t u = 0; u < centres.size(); ++u)
                if (!done[u] && distance(centres[current], centres[u]) < best) best = distance(centres[current], centres[u]), next = u;
            current = next;
        }
        QCOMPARE(check::machiningOrder(centres), scan);
    }

    void degenerateInputs()
    {
        QVERIFY(check::machiningOrder({}).empty());
        QCOMPARE(check::machiningOrder({{5, 5}}), std::vector<int>{0});
        // All at one point: in the order typed.
        QCOMPARE(check::machiningOrder({{1, 1}, {1, 1}, {1, 1}}), (std::vector<int>{0, 1, 2}));
        // On one line, far apart: a grid of one row still finds each nearest.
        QCOMPARE(check::machiningOrder({{0, 0}, {1000, 0}, {1, 0}, {999, 0}}), (std::vector<int>{0, 2, 3, 1}));
    }
};

QTEST_APPLESS_MAIN(TestUnitOrder)
#include "test_unit_order.moc"
