// Proof of the contour units by generation (issue 33): seeded random
// contour jobs (support/contour_generator.h: CP pockets of lines and arcs
// with necks and islands, some touching the outline; SIDE open runs with a
// notch, closed bosses and pockets). Each planned case must be verified
// clean by the product's verification, its linuxcnc tape accepted by
// rs274, and the tool centre kept at least R − 1 µm from every wall (the
// distance computed by the test itself); each refused case must be refused
// on a field its module has, with a reason. 240 seeds here, 10,000 in
// bench/bench_contour_generator.cpp; the counts are printed. The wall
// measure is shown to find a centre 0.2 mm and 2 µm too near.
#include "support/contour_generator.h"

#include "job/job_file.h"
#include "modules/cp/cp.h"

#include <QDir>
#include <QFile>

#include <QElapsedTimer>
#include <QtTest>

#include <cstdint>

using namespace taiwa;
using namespace taiwa::test;

class TestContourGenerator : public QObject {
    Q_OBJECT

private slots:
    // A seed is a job: the same one every time, another for another seed;
    // both modules are made, and the figure text gives every contour.
    void aSeedIsReproducible()
    {
        const ContourCase a = generateContourCase(17), b = generateContourCase(17), c = generateContourCase(19);
        QVERIFY(a.job == b.job);
        QVERIFY(!(a.job == c.job));
        QCOMPARE(a.module, std::string("CP"));
        QCOMPARE(generateContourCase(18).module, std::string("SIDE"));
        QVERIFY(!a.job.figure.empty());
        QVERIFY(a.job.figure.find("CONTOUR/") != std::string::npos);
    }

    // The wall distance is exact on lines and arcs, and finds a point 0.2 mm
    // or 2 µm nearer the wall than a tool's radius.
    void theWallMeasureIsExact()
    {
        Contour k;
        k.segments = {ContourSegment::line({0, 0}, {10, 0}), ContourSegment::arc({10, 0}, {20, 0}, {15, 0}, false)};
        QVERIFY(std::abs(wallDistance(k, {5, 3}) - 3.0) < 1e-12);
        QVERIFY(std::abs(wallDistance(k, {15, 1}) - 4.0) < 1e-12);   // inside the arc's circle, above it: the arc bulges up
        QVERIFY(std::abs(wallDistance(k, {15, -2}) - std::hypot(5.0, 2.0)) < 1e-12);  // below it: the ends are nearest
        QVERIFY(std::abs(wallDistance(k, {-3, -4}) - 5.0) < 1e-12);  // past the line's start
        for (const double into : {0.2, 0.002}) {
            const double R = 3.0;
            QVERIFY(wallDistance(k, {5, R - into}) - R < -1e-3);
        }
    }

    // 240 seeds (120 CP, 120 SIDE): every plan clean, every tape accepted,
    // every centre ≥ R − 1 µm off the walls, every refusal on a field of the
    // module with its reason; the run covers necks, touching islands and
    // notches, and plans most cases.
    void generatedContoursAreRightTheFirstTime()
    {
        ContourTally tally;
        QElapsedTimer clock;
        clock.start();
        const int n = qEnvironmentVariableIntValue("TAIWA_CONTOUR_SEEDS") > 0 ? qEnvironmentVariableIntValue("TAIWA_CONTOUR_SEEDS") : 240;
        // TAIWA_CONTOUR_FIRST=K: seeds K to K + n - 1 (to look at one seed).
        const std::uint64_t first = qEnvironmentVariableIntValue("TAIWA_CONTOUR_FIRST") > 0
                                        ? static_cast<std::uint64_t>(qEnvironmentVariableIntValue("TAIWA_CONTOUR_FIRST"))
                                        : 1;
        // Planned in turn, their tapes through rs274 twenty at a time.
        std::vector<ContourCase> cases;
        std::vector<ContourOutcome> outcomes;
        const auto flush = [&] {
            std::vector<std::pair<const ContourCase*, ContourOutcome*>> batch;
            for (std::size_t k = 0; k < cases.size(); ++k)
                if (outcomes[k].planned) batch.push_back({&cases[k], &outcomes[k]});
            if (!batch.empty()) runTapes(batch);
            for (std::size_t k = 0; k < cases.size(); ++k) {
                const std::size_t failing = tally.failing.size();
                tally.add(cases[k], outcomes[k]);
                // TAIWA_CONTOUR_DUMP=DIR: each failing case (or the one seed run) as a job file, to look at with taiwa.
                if ((tally.failing.size() > failing || n == 1) && qEnvironmentVariableIsSet("TAIWA_CONTOUR_DUMP")) {
                    QFile f(QDir(qEnvironmentVariable("TAIWA_CONTOUR_DUMP")).filePath(QString("contour-%1.taiwa").arg(cases[k].seed)));
                    if (f.open(QIODevice::WriteOnly)) f.write(QByteArray::fromStdString(writeJob(cases[k].job)));
                }
            }
            cases.clear();
            outcomes.clear();
        };
        for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(n); ++seed) {
            cases.push_back(generateContourCase(seed));
            outcomes.push_back(runContourCase(cases.back(), false));
            if (cases.size() == 20) flush();
        }
        flush();
        qInfo("%s; %lld ms", tally.summary().c_str(), clock.elapsed());
        QVERIFY2(tally.failing.empty(), tally.summary().c_str());
        QCOMPARE(tally.tapes, tally.planned);
        QCOMPARE(tally.tapesAccepted, tally.planned);
        QVERIFY(tally.smallestClMargin >= -1e-3);
        QVERIFY(tally.smallestMargin >= -2.5e-3);  // the tape's 3 decimals: 1.5 µm more
        QVERIFY(tally.planned >= n / 2);
        QVERIFY(tally.necks >= 10 && tally.touching >= 3 && tally.notches >= 20);
    }

    // A CP pocket whose narrowest place lets only the Ø2 end mill pass made
    // deeper than its flutes: generated seed 189 (a gap of 2.96 mm between
    // the island K2 and the outline K1) at T 8, where Ø2's flutes are 6 mm
    // and Ø3's 9 mm. The wall finishing was refused on `tools` for the
    // flutes ("T21 … is the nearest, but its flutes (6 mm) are shorter than
    // the depth 8 mm"); now on `islands`, naming the gap, its width and
    // place, the end mill whose flutes reach (Ø3) and how much wider the gap
    // must be for it (3 mm, 0.04 mm more).
    void aNarrowPlaceForcingShortFlutesIsNamed()
    {
        ContourCase c = generateContourCase(189);
        QCOMPARE(c.module, std::string("CP"));
        c.job.units.front().module.as<ContourPocket>().depth = 8.0;
        const ContourOutcome o = runContourCase(c, false);
        QVERIFY2(o.failure.empty(), o.failure.c_str());
        QVERIFY(!o.planned);
        QCOMPARE(QString::fromStdString(o.refusedOn), QString("islands"));
        for (const char* words : {"the gap between the island K2 and K1 is 2.96 mm wide at (23.984 mm, 15.39 mm)",
                                  "(the longest-fluted, T21 (flat end mill Ø2 mm))", "T22 (flat end mill Ø3 mm) reaches",
                                  "needs 3 mm there, 0.04 mm more", "depth 8 mm"})
            QVERIFY2(o.refusal.find(words) != std::string::npos, o.refusal.c_str());
    }

    // The seeds the generator found failing, each named with what it was.
    void seedsThatFailedBefore_data()
    {
        QTest::addColumn<quint64>("seed");
        QTest::addColumn<QString>("refusedOn");  // "" when it must now be planned, verified clean and accepted
        // The SIDE end mill was allowed flutes shorter than T whatever F:
        // with F1 the finishing pass at full depth ran the shank 2.9 mm into
        // the wall. Now refused on F (asking for F2), naming the longest.
        QTest::newRow("SIDE F1, Ø2 with 6 mm flutes at T 8.9: the shank 2.9 mm into the wall") << quint64(84) << "F";
        // A SIDE notch whose tool centre turns on an arc of 2 µm: the tape
        // said "G3 X23.029 Y21.99 I-0.002 J0.001", whose end is 0.001 mm from
        // its centre as written, and rs274 refused the tape ("Zero-radius
        // arc"). A radius under two units of the tape is now a line.
        QTest::newRow("SIDE notch: an arc of 2 µm, a zero-radius arc to rs274") << quint64(4752) << "";
    }
    void seedsThatFailedBefore()
    {
        QFETCH(quint64, seed);
        QFETCH(QString, refusedOn);
        const ContourCase c = generateContourCase(seed);
        const ContourOutcome o = runContourCase(c, true);
        QVERIFY2(o.failure.empty(), o.failure.c_str());
        if (refusedOn.isEmpty()) {
            QVERIFY2(o.planned && o.clean && o.tapeAccepted, o.refusal.c_str());
        } else {
            QCOMPARE(QString::fromStdString(o.refusedOn), refusedOn);
            QVERIFY2(o.refusal.find("finish in several incisions (F 2)") != std::string::npos, o.refusal.c_str());
        }
    }
};

QTEST_GUILESS_MAIN(TestContourGenerator)
#include "test_contour_generator.moc"
