// Input processing of whole jobs: overlapping versus touching figures
// (rounded corners included), several errors collected at once and capped,
// inch jobs quoting inches, the technology data in force, and the unit order.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "job/job_check.h"
#include "support/check_fixtures.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace taiwa;
using namespace taiwa::test;

class TestInputCheckJob : public QObject {
    Q_OBJECT
private slots:
    void touchingFiguresPassOverlappingAreRefused()
    {
        // Shared straight edge x = 120, and a shared slanted edge.
        QVERIFY(check(job({m4(20, 20), m4(120, 20, 60, 60)})).empty());
        M4Pocket a = m4(), b = m4();
        a.corners = {{{20, 20}, {80, 20}, {100, 80}, {20, 80}}};
        b.corners = {{{80, 20}, {180, 20}, {180, 80}, {100, 80}}};
        QVERIFY2(check(job({a, b})).empty(), dump(check(job({a, b}))));
        // 10 mm of overlap along x: refused, on the later unit, naming both.
        EXPECT_ONLY(check(job({m4(20, 20), m4(110, 20, 60, 60)})), 2, "corners", "the figure of unit 2 overlaps the figure of unit 1");
        // An overlap of 0.01 mm along a 60 mm edge is still an overlap.
        QCOMPARE(check(job({m4(20, 20), m4(119.99, 20, 60, 60)})).size(), std::size_t(1));
        // M4 against M2D.
        M2DPocket q = m2d();
        q.corner = {115, 20};
        EXPECT_ONLY(check(job({m4(), q})), 2, "corner", "overlaps the figure of unit 1");
    }
    // Turned figures meet along a slanted side, where the quick test of the
    // sides' normals must tell touching (accepted) from 5 µm of overlap
    // (refused) as the boolean does.
    void turnedFiguresTouchingOrOverlapping()
    {
        const double a = 30 * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
        const auto square = [&](double shift) {
            M4Pocket m = m4();
            const Point2 o{60 + shift * c, 30 + shift * s};
            const Point2 ex{40 * c, 40 * s}, ey{-40 * s, 40 * c};
            m.corners = {{o, o + ex, o + ex + ey, o + ey}};
            return m;
        };
        QVERIFY2(check(job({square(0), square(40)})).empty(), dump(check(job({square(0), square(40)}))));
        EXPECT_ONLY(check(job({square(0), square(39.995)})), 2, "corners", "overlaps the figure of unit 1");
    }
    void roundedCornersKeepDiagonalNeighboursApart()
    {
        // The sharp corners overlap by 1 x 1 mm: with r1 = 8 the rounded outlines
        // stay apart, with r1 = 0.4 they overlap.
        QVERIFY(check(job({m4(20, 20, 50, 50), m4(69, 69, 50, 50)})).empty());
        M4Pocket a = m4(20, 20, 50, 50), b = m4(69, 69, 50, 50);
        a.cornerRadius = b.cornerRadius = 0.4;  // r1 - alpha2 = 0.1 leaves room for a 0.1 mm end mill
        const auto ds = checkJob(job({a, b}), TechnologyTable::builtIn(), {tool(2, ToolType::FlatEndMill, 0.1)});
        EXPECT_ONLY(ds, 2, "corners", "overlaps the figure of unit 1");
    }

    void severalErrorsCollectedAtOnce()
    {
        M4Pocket bad = m4();
        bad.depth = 0;
        M2DPocket worse = m2d();
        worse.toolUse = 3;
        Job j = job({bad, worse});
        j.material = "unobtainium";
        const auto ds = check(j);
        QCOMPARE(ds.size(), std::size_t(3));
        QCOMPARE(ds[0].field, std::string("material"));
        QVERIFY(ds[1].unit == 1 && ds[1].field == "depth");
        QVERIFY(ds[2].unit == 2 && ds[2].field == "U" && ds[2].module == "M2D");
    }
    void errorsAreCapped()
    {
        std::vector<ModuleInput> units;
        for (int i = 0; i < 150; ++i) {
            M4Pocket p = m4();
            p.toolUse = 2;
            units.push_back(p);
        }
        const auto ds = check(job(units));
        QCOMPARE(ds.size(), std::size_t(100));
        QVERIFY(ds.back().message.find("more errors not listed") != std::string::npos);
    }

    // More than 100 warnings (a tiled job's unswept areas) once filled the
    // list, and its "N more errors not listed" line, an error, refused a job
    // with none; an error coming after them was not shown.
    void warningsNeverHideOrMakeAnError()
    {
        const auto warning = [](int k) { return Diagnostic{Severity::Warning, k, "AREA", "points", "unswept " + std::to_string(k)}; };
        DiagnosticSink notes;
        for (int k = 0; k < 150; ++k) notes.add(warning(k));
        const Diagnostics onlyNotes = std::move(notes).finish();
        QCOMPARE(onlyNotes.size(), kMaxDiagnostics);
        QVERIFY(!hasErrors(onlyNotes));
        QCOMPARE(onlyNotes.back().severity, Severity::Warning);
        QCOMPARE(onlyNotes.back().message, std::string("51 more warnings not listed"));

        DiagnosticSink mixed;
        for (int k = 0; k < 150; ++k) mixed.add(warning(k));
        mixed.add({Severity::Error, 151, "M4", "depth", "the depth is -1 mm"});
        const Diagnostics ds = std::move(mixed).finish();
        QCOMPARE(ds.size(), kMaxDiagnostics);
        QCOMPARE(std::count_if(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.message == "the depth is -1 mm"; }), 1);
        QCOMPARE(ds.back().message, std::string("52 more warnings not listed"));
        QCOMPARE(ds.front().message, std::string("unswept 0"));

        // Errors past the list: counted in an error line after the warnings' line.
        DiagnosticSink both;
        for (int k = 0; k < 50; ++k) both.add(warning(k));
        for (int k = 0; k < 120; ++k) both.add({Severity::Error, k, "M4", "depth", "error " + std::to_string(k)});
        const Diagnostics all = std::move(both).finish();
        QCOMPARE(all.size(), kMaxDiagnostics);
        QCOMPARE(all[all.size() - 2].message, std::string("50 more warnings not listed"));
        QCOMPARE(all.back().message, std::string("22 more errors not listed; correct the ones above first"));
        QCOMPARE(std::count_if(all.begin(), all.end(), [](const Diagnostic& d) { return d.severity == Severity::Warning; }), 1);
    }

    void inchJobQuotesInches()
    {
        Job j = job({m4(1, 1, 4, 2)});
        j.lengthUnit = LengthUnit::Inch;
        j.stock = {0, 0, 8, 6, 2};
        auto& p = (j.units[0].module).as<M4Pocket>();
        p.cornerRadius = 0.3;
        p.depth = 0.5;
        QVERIFY2(check(j).empty(), dump(check(j)));
        p.cornerRadius = 1.25;
        EXPECT_ONLY(check(j), 1, "cornerRadius", "corner radius 1.25 in is larger than half the shortest side (2 in long)");
        p.cornerRadius = 0.3;
        p.depth = -0.5;
        EXPECT_ONLY(check(j), 1, "depth", "the depth is -0.5 in");
        p.depth = 0.5;
        p.tools = {{"roughing", 5}};
        EXPECT_ONLY(check(j), 1, "tools.roughing", "r1 − α2 = 0.2882 in");  // 7.62 mm - 0.3 mm
    }

    // The vice's jaws grip the block from its bottom, below its top; a lathe
    // has no vice. The units are checked as without a clamping.
    void theClampingIsChecked()
    {
        Job j = job({m4()});
        j.clamping = Clamping{Clamping::Grip::Y, 12};
        QVERIFY2(check(j).empty(), dump(check(j)));
        j.clamping->height = 0;
        EXPECT_ONLY(check(j), 0, "clamping.height", "the jaws' height is 0 mm");
        j.clamping->height = 40;
        EXPECT_ONLY(check(j), 0, "clamping.height", "the jaws reach 40 mm up the block, its top or beyond (the stock is 40 mm high)");
        j.clamping->height = std::nan("");
        EXPECT_ONLY(check(j), 0, "clamping.height", "");
        j.clamping->height = 12;
        j.machine = "lathe";
        j.bar = BarStock{};
        j.units.clear();
        EXPECT_ONLY(check(j), 0, "clamping", "a lathe holds its bar in the chuck");
    }

    void technologyInForce()
    {
        Job j = job({m4()});
        j.technology.alpha2 = 0.5;
        const auto t = jobTechnology(j, TechnologyTable::builtIn());
        QVERIFY(t && t->alpha2 == 0.5 && t->alpha1 == 1.0 && t->gamma == 0.5);
        j.material = "steel-s45c";
        QCOMPARE(jobTechnology(j, TechnologyTable::builtIn())->beta2, 0.25);
        j.material = "unobtainium";
        QVERIFY(!jobTechnology(j, TechnologyTable::builtIn()));
    }

    void thousandsOfStackedFiguresAreCheckedInBoundedWork()
    {
        // 3,000 units at one place: every pair overlaps (4.5 million pairs; all
        // were once compared and kept: 171 s, 2.2 GB). The first overlaps are
        // listed, and the rest is said not to have been looked for.
        std::vector<ModuleInput> units(3000, m4(20, 20));
        const Diagnostics ds = check(job(units));
        QCOMPARE(ds.size(), std::size_t{100});
        QCOMPARE(ds[0].message.substr(0, 46), std::string("the figure of unit 2 overlaps the figure of un"));
        QCOMPARE(ds.back().message, std::string("2 more errors not listed; correct the ones above first"));
        QVERIFY(std::count_if(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.field == "corners"; }) == 99);
    }

    void unitOrderIsNearestNeighbourFromTheFirst()
    {
        const Job j = job({m4(0, 0, 20, 20), m4(100, 0, 20, 20), m4(20, 0, 20, 20), m4(60, 0, 20, 20)});
        QCOMPARE(machiningOrder(j), (std::vector<int>{0, 2, 3, 1}));
        const Job tie = job({m4(40, 0, 20, 20), m4(80, 0, 20, 20), m4(0, 0, 20, 20)});
        QCOMPARE(machiningOrder(tie), (std::vector<int>{0, 1, 2}));  // equal distance: the earlier unit first
        QVERIFY(machiningOrder(job({})).empty());
    }
};

QTEST_APPLESS_MAIN(TestInputCheckJob)
#include "test_input_check_job.moc"
