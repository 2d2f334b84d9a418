// Module CP (contour pocket of any outline with islands): the sample planned
// end to end and judged step by step by a geometric oracle of its own (the
// exact region's signed distance, model/contour.h, not the paths' Clipper
// rings): roughing leaves α2 on every wall and island and stops β2 above the
// floor, the floor is reached and swept, the wall passes run at the tool
// radius from every wall (1 µm) with arcs kept as arcs, and no rapid moves
// sideways below the top. Then the job file's figure round trip and every
// refusal of the module's checks with its message.
#include "support/hand_plan.h"
#include "support/support.h"
#include "test_toolpaths_support.h"

#include "figure/figure_units.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "model/contour.h"
#include "modules/cp/cp.h"
#include "modules/named_region.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace taiwa;

namespace {

const char* kSample = "cp-islands.taiwa";

Job sampleJob()
{
    auto read = readJobFile(test::sourcePath(QString("resources/samples/") + kSample).toStdString());
    if (!read.job) throw std::runtime_error("sample not read");
    return *read.job;
}

std::string messages(const Diagnostics& ds)
{
    std::string s;
    for (const auto& d : ds) s += d.field + ": " + d.message + "\n";
    return s;
}

// The first message on `field`, or "".
std::string messageOn(const Diagnostics& ds, const std::string& field)
{
    for (const auto& d : ds)
        if (d.field == field) return d.message;
    return {};
}

double segmentDistance(Point2 p, Point2 a, Point2 b)
{
    const Point2 d = b - a;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * d);
}

}  // namespace

class TestContourPocket : public QObject {
    Q_OBJECT
private slots:
    // A unit keeps the figure's contour names only to say its own is not
    // among them: thousands of units each holding every name made a tiled
    // job's check quadratic in time and memory (issue 39).
    void onlyAnUnknownNameKeepsTheFiguresNames()
    {
        ContourTable table;
        const Contour square{{ContourSegment::line({0, 0}, {10, 0}), ContourSegment::line({10, 0}, {10, 10}),
                              ContourSegment::line({10, 10}, {0, 10}), ContourSegment::line({0, 10}, {0, 0})},
                             true};
        for (int k = 1; k <= 500; ++k) table.emplace("K" + std::to_string(k), square);
        NamedRegion found;
        found.outline = "K7";
        found.resolve(table);
        QVERIFY(found.region.has_value());
        QVERIFY(found.figureContours.empty());
        NamedRegion lost;
        lost.outline = "K7";
        lost.islands = {"K9000"};
        lost.resolve(table);
        QVERIFY(!lost.region.has_value());
        QCOMPARE(lost.unknown, std::vector<std::string>{"K9000"});
        QCOMPARE(lost.figureContours.size(), std::size_t{500});
    }

    void samplePlansInThreeSteps()
    {
        const Plan plan = test::samplePlan(kSample);
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        QCOMPARE(plan.steps.size(), std::size_t{3});
        QCOMPARE(plan.steps[0].kind, StepKind::Roughing);
        QCOMPARE(plan.steps[1].kind, StepKind::FloorFinishing);
        QCOMPARE(plan.steps[2].kind, StepKind::WallFinishing);
        for (const Step& s : plan.steps) {
            QVERIFY(millingOf(s).region);
            QCOMPARE(millingOf(s).region->islands.size(), std::size_t{2});
            QVERIFY(s.tool && s.path && !s.path->moves.empty());
        }
        // The smallest inside radius is the ROUND 6 where the side meets the
        // arch: no wall tool much wider than 12 mm. That corner turns by
        // only 34°, so a cutter 0.1 mm larger than its rounding leaves less
        // than the 4 µm the reach allows (docs/modules.md, CP).
        QVERIFY2(millingOf(plan.steps[2]).reach >= 6.0 && millingOf(plan.steps[2]).reach < 6.15, qPrintable(QString::number(millingOf(plan.steps[2]).reach)));
        for (const Step& s : plan.steps) QVERIFY(plan.tool(s.tool->toolId)->radius() <= millingOf(s).reach + 1e-9);
    }

    // Every step judged against the exact region.
    void stepsKeepTheirAllowancesAndReachTheFloor()
    {
        const Plan plan = test::samplePlan(kSample);
        QVERIFY(plan.ok());
        const TechnologyData& tech = plan.technology;
        const double T = 12.0;
        for (const Step& s : plan.steps) {
            const RegionDistance distanceTo(normalised(*millingOf(s).region));
            const double R = plan.tool(s.tool->toolId)->radius();
            // Clipper's rings are within its 1 µm chords of the exact region,
            // twice (the region flattened, the offset's round joins).
            const double slack = s.kind == StepKind::WallFinishing ? 1e-6 : 2.5e-3;
            double deepest = 0.0, nearest = std::numeric_limits<double>::infinity();
            for (const auto& piece : test::cuttingPieces(*s.path))
                for (const Point3 p : test::samples(piece)) {
                    deepest = std::min(deepest, p.z);
                    if (p.z < 0.0) nearest = std::min(nearest, -distanceTo({p.x, p.y}));
                }
            const double kept = nearest - R;  // what the tool's edge left on the nearest wall
            QVERIFY2(kept >= millingOf(s).wallAllowance - slack,
                     qPrintable(QString("%1 left %2 on a wall, allowance %3").arg(s.label().c_str()).arg(kept).arg(millingOf(s).wallAllowance)));
            QVERIFY2(kept <= millingOf(s).wallAllowance + 0.05, qPrintable(QString("%1 stays %2 off the walls").arg(s.label().c_str()).arg(kept)));
            const double floor = s.kind == StepKind::Roughing ? T - tech.beta2 : T;
            QVERIFY2(std::abs(deepest + floor) < 1e-9, qPrintable(QString("%1 reaches %2").arg(s.label().c_str()).arg(deepest)));
            // No rapid sideways below the top of the stock.
            Point3 at = s.path->start;
            for (const Move& m : s.path->moves) {
                if (m.kind == MoveKind::Rapid && (m.end.z < 0.0 || at.z < 0.0))
                    QVERIFY2(m.end.x == at.x && m.end.y == at.y, "a rapid moves sideways below the stock top");
                at = m.end;
            }
        }
    }

    // The wall pass touches every wall: each point of the outline and of
    // the islands has the tool's edge on it at the floor.
    void wallPassTouchesEveryWall()
    {
        const Plan plan = test::samplePlan(kSample);
        QVERIFY(plan.ok());
        const Step& wall = plan.steps[2];
        const double R = plan.tool(wall.tool->toolId)->radius();
        // The moves at the floor as exact pieces of the plan view.
        std::vector<ContourSegment> atFloor;
        for (const auto& piece : test::cuttingPieces(*wall.path)) {
            if (std::abs(piece.from.z + 12.0) > 1e-9 || std::abs(piece.move.end.z + 12.0) > 1e-9) continue;
            const Point2 a{piece.from.x, piece.from.y}, b{piece.move.end.x, piece.move.end.y};
            atFloor.push_back(piece.move.kind == MoveKind::Feed
                                  ? ContourSegment::line(a, b)
                                  : ContourSegment::arc(a, b, piece.move.centre, piece.move.kind == MoveKind::ArcCCW));
        }
        const Region region = normalised(*millingOf(wall).region);
        std::vector<const Contour*> walls{&region.outer};
        for (const auto& i : region.islands) walls.push_back(&i);
        for (const Contour* c : walls)
            for (const Point2 q : flatten(*c, 0.01)) {
                double d = std::numeric_limits<double>::infinity();
                for (const ContourSegment& m : atFloor) d = std::min(d, distance(m.nearest(q), q));
                QVERIFY2(d <= R + 1e-6, qPrintable(QString("the wall at (%1, %2) is %3 from the tool centre").arg(q.x).arg(q.y).arg(d)));
            }
        // Arcs stay arcs: the round island (R8 at (35, 35)) is one circle of
        // radius 8 + R around its centre on the tape.
        bool circle = false;
        Point3 at = wall.path->start;
        for (const Move& m : wall.path->moves) {
            if ((m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW) && distance(m.centre, {35, 35}) < 1e-9 &&
                std::abs(std::hypot(m.end.x - 35, m.end.y - 35) - (8 + R)) < 1e-9)
                circle = true;
            at = m.end;
        }
        QVERIFY(circle);
    }

    // Roughing and floor finishing together sweep all of the floor but the
    // allowance: every point more than α2 inside the region is within the
    // floor pass's tool radius of its path at the floor.
    void floorIsSwept()
    {
        const Plan plan = test::samplePlan(kSample);
        QVERIFY(plan.ok());
        const Step& floor = plan.steps[1];
        const double R = plan.tool(floor.tool->toolId)->radius();
        std::vector<std::pair<Point2, Point2>> lines;
        for (const auto& piece : test::cuttingPieces(*floor.path))
            if (piece.move.kind == MoveKind::Feed && std::abs(piece.move.end.z + 12.0) < 1e-9 && std::abs(piece.from.z + 12.0) < 1e-9)
                lines.push_back({{piece.from.x, piece.from.y}, {piece.move.end.x, piece.move.end.y}});
        const RegionDistance distanceTo(normalised(*millingOf(floor).region));
        int points = 0;
        for (double y = 10.5; y < 70; y += 1.0)
            for (double x = 10.5; x < 110; x += 1.0) {
                if (distanceTo({x, y}) > -(millingOf(floor).wallAllowance + R)) continue;  // the wall pass's, or material
                ++points;
                double d = std::numeric_limits<double>::infinity();
                for (const auto& [a, b] : lines) d = std::min(d, segmentDistance({x, y}, a, b));
                QVERIFY2(d <= R, qPrintable(QString("the floor at (%1, %2) is %3 from the floor pass").arg(x).arg(y).arg(d)));
            }
        QVERIFY(points > 2000);
    }

    void figureRoundTripsThroughTheJobFile()
    {
        const Job job = sampleJob();
        QVERIFY(job.figure.starts_with("$$ An arched outline"));
        const std::string text = writeJob(job);
        const auto back = readJob(text);
        QVERIFY(back.job);
        QCOMPARE(back.job->figure, job.figure);
        QVERIFY(*back.job == job);
        QCOMPARE(writeJob(*back.job), text);
        QVERIFY(text.find("\"version\": 5") != std::string::npos);
    }

    // A job switched to inch keeps its contours: the figure's lengths are
    // converted with the job's, its angles and comments left alone.
    void figureConvertsWithTheJobsUnit()
    {
        const Job mm = sampleJob();
        const auto toInch = [](double v) { return v / 25.4; };
        Job inch = withLengths(mm, LengthUnit::Inch, toInch);
        inch.figure = figure::convertFigureLengths(mm.figure, toInch);
        QVERIFY(inch.figure.starts_with("$$ An arched outline"));
        QVERIFY(inch.figure.find("ATANGL, 90") != std::string::npos);
        QVERIFY(inch.figure.find("RADIUS, 60\n") == std::string::npos);
        PlanOptions stepsOnly;
        stepsOnly.withToolPaths = false;
        const Plan a = planJob(mm, TechnologyTable::builtIn(), defaultToolLibrary(), stepsOnly);
        const Plan b = planJob(inch, TechnologyTable::builtIn(), defaultToolLibrary(), stepsOnly);
        QVERIFY2(b.ok(), messages(b.diagnostics).c_str());
        const Region ra = normalised(*millingOf(a.steps[0]).region), rb = normalised(*millingOf(b.steps[0]).region);
        QCOMPARE(rb.outer.segments.size(), ra.outer.segments.size());
        for (std::size_t i = 0; i < ra.outer.segments.size(); ++i)
            QVERIFY(distance(ra.outer.segments[i].end, rb.outer.segments[i].end) < 1e-9);
        QVERIFY(std::abs(area(ra) - area(rb)) < 1e-6);
    }

    void refusals_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown contour") << "outline=K9" << "outline"
                                         << "K9 is not a contour of the job's figure elements (its contours: K1, K2, K3)";
        QTest::newRow("no outline") << "outline=" << "outline"
                                    << "name the contour of the pocket's outline (a CONTOUR of the job's figure elements)";
        QTest::newRow("island outside") << "figure:P4 = POINT/35, 35=>P4 = POINT/12, 35" << "islands"
                                        << "the island K2 reaches outside the pocket's outline K1";
        QTest::newRow("islands overlap") << "figure:P4 = POINT/35, 35=>P4 = POINT/70, 30" << "islands"
                                         << "the islands K2 and K3 overlap; make them one contour";
        QTest::newRow("sharp inside corner") << "figure:L1, ROUND, 8, L2=>L1, L2" << "outline"
                                             << "K1 has a sharp inside corner at (110 mm, 10 mm): an end mill cannot cut it "
                                                "and leaves its own radius there; round the corner (ROUND) in the contour";
        QTest::newRow("open outline")
            << "figure:K1 = CONTOUR/L1, ROUND, 8, L2, ROUND, 6, YLARGE, CCLW, C1, ROUND, 6, YLARGE, L3, ROUND, 8=>"
               "P7 = POINT/110, 40\nK1 = CONTOUR/P1, L1, ROUND, 8, L2, P7"
            << "outline"
            << "K1 is an open contour; a pocket's outline must be closed (a contour without a start and end point)";
        // Issue 33: on the island's field, naming it, where, and the gap;
        // before, on "cornerRadius" with a bare reach (or not refused at all
        // when the island touched, and the wall pass cut through it).
        QTest::newRow("island touching the outline")
            << "figure:P4 = POINT/35, 35=>P4 = POINT/35, 18" << "islands"
            << "the island K2 touches K1 at (35 mm, 10 mm): no end mill passes between them; keep it 2.6 mm off (the "
               "smallest end mill, T21 (flat end mill Ø2 mm), with what the step leaves on the walls) or make the two "
               "one contour";
        QTest::newRow("island 0.5 off the outline")
            << "figure:P4 = POINT/35, 35=>P4 = POINT/35, 18.5" << "islands"
            << "the gap between the island K2 and K1 is 0.5 mm wide at (35 mm, 10.5 mm); the smallest end mill, T21 "
               "(flat end mill Ø2 mm), needs 2.6 mm there";
        QTest::newRow("islands 1.5 apart")
            << "figure:P4 = POINT/35, 35=>P4 = POINT/62.5, 35" << "islands"
            << "the gap between the island K3 and K2 is 1.5 mm wide at (72 mm, 35 mm); the smallest end mill, T21 "
               "(flat end mill Ø2 mm), needs 2.6 mm there";
        QTest::newRow("cored U") << "U=7" << "U"
                                 << "U 7 is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 "
                                    "(walls only) or 9 (roughing only)";
        QTest::newRow("figure text") << "figure:RADIUS, 60=>RADUIS, 60" << "figure"
                                     << "7:25: expected RADIUS after ',', found 'RADUIS'";
    }
    void refusals()
    {
        QFETCH(QString, change);
        QFETCH(QString, field);
        QFETCH(QString, message);
        Job job = sampleJob();
        const std::string c = change.toStdString();
        if (c.starts_with("figure:")) {
            const auto arrow = c.find("=>");
            const std::string from = c.substr(7, arrow - 7), to = c.substr(arrow + 2);
            const auto at = job.figure.find(from);
            QVERIFY(at != std::string::npos);
            job.figure.replace(at, from.size(), to);
        } else {
            const auto text = writeJob(job);
            auto j = nlohmann::json::parse(text);
            const auto eq = c.find('=');
            const std::string key = c.substr(0, eq), value = c.substr(eq + 1);
            if (key == "U") j["units"][0]["U"] = std::stoi(value);
            else j["units"][0][key] = value;
            auto read = readJob(j.dump());
            QVERIFY(read.job);
            job = *read.job;
        }
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        const std::string got = messageOn(ds, field.toStdString());
        QVERIFY2(!got.empty(), messages(ds).c_str());
        if (!message.isEmpty()) QCOMPARE(QString::fromStdString(got), message);
    }

    // An outline of two rooms joined by a channel 2 mm wide: the neck is
    // named on the outline with its two sides and the width the smallest end
    // mill needs (issue 33; before, on "cornerRadius" with a reach of 0.7 mm).
    void neckIsNamedOnTheOutline()
    {
        Job job = sampleJob();
        job.figure = "P1 = POINT/5, 5\nP2 = POINT/45, 5\nP3 = POINT/45, 23\nP4 = POINT/65, 23\nP5 = POINT/65, 5\n"
                     "P6 = POINT/105, 5\nP7 = POINT/105, 45\nP8 = POINT/65, 45\nP9 = POINT/65, 25\nP10 = POINT/45, 25\n"
                     "P11 = POINT/45, 45\nP12 = POINT/5, 45\n"
                     "L1 = LINE/P1, P2\nL2 = LINE/P2, P3\nL3 = LINE/P3, P4\nL4 = LINE/P4, P5\nL5 = LINE/P5, P6\n"
                     "L6 = LINE/P6, P7\nL7 = LINE/P7, P8\nL8 = LINE/P8, P9\nL9 = LINE/P9, P10\nL10 = LINE/P10, P11\n"
                     "L11 = LINE/P11, P12\nL12 = LINE/P12, P1\n"
                     "K1 = CONTOUR/L1, ROUND, 3, L2, L3, L4, ROUND, 3, L5, ROUND, 3, L6, ROUND, 3, L7, ROUND, 3, L8, L9, "
                     "L10, ROUND, 3, L11, ROUND, 3, L12, ROUND, 3";
        ContourPocket& p = job.units[0].module.as<ContourPocket>();
        p.contours.islands.clear();
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QCOMPARE(ds.size(), std::size_t{1});
        QCOMPARE(ds[0].field, std::string("outline"));
        const std::string m = ds[0].message;
        QVERIFY2(m.starts_with("K1 narrows to 2 mm between (") && m.find(" mm, 2") != std::string::npos &&
                     m.ends_with("; the smallest end mill, T21 (flat end mill Ø2 mm), needs 2.6 mm there"),
                 m.c_str());
    }
};

QTEST_APPLESS_MAIN(TestContourPocket)
#include "test_contour_pocket.moc"
