// Module AREA (area clearing by drawn passes, seed 002's seventh abstract):
// the sample planned end to end and judged by an oracle of its own — the
// tape follows the drawn points in their order at every layer, every strip
// is cut to the depth, the tool never leaves the area (exact signed distance
// to the figure's lines and arcs), no rapid runs below the top except down
// into what is cut — and what is left unswept, measured on a grid here, is
// what the check reports. Then the exact nearest approach of a pass to a
// line or an arc (hand-computed), the points' text, the job file's round
// trip and inch conversion, and every refusal with its message.
#include "support/hand_plan.h"
#include "support/support.h"

#include "job/job_check.h"
#include "job/job_file.h"
#include "model/contour.h"
#include "modules/area/area.h"
#include "modules/registry.h"
#include "paths/drawn_passes.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace taiwa;

namespace {

const char* kSample = "area-drawn-passes.taiwa";
constexpr double kTol = 1e-3;  // mm: the tape's resolution

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

const Diagnostic* on(const Diagnostics& ds, const std::string& field)
{
    for (const auto& d : ds)
        if (d.field == field) return &d;
    return nullptr;
}

double segmentDistance(Point2 p, Point2 a, Point2 b)
{
    const Point2 d = b - a;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * d);
}

double polylineDistance(const std::vector<Point2>& pts, Point2 p)
{
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < pts.size(); ++k) d = std::min(d, segmentDistance(p, pts[k - 1], pts[k]));
    return d;
}

// Points every `step` mm along the path's moves (lines; arcs by their chord
// are not in this path), with the move's kind.
struct Sample {
    Point3 p;
    MoveKind kind;
};
std::vector<Sample> samples(const ToolPath& path, double step)
{
    std::vector<Sample> out;
    Point3 from = path.start;
    for (const Move& m : path.moves) {
        const double len = std::hypot(std::hypot(m.end.x - from.x, m.end.y - from.y), m.end.z - from.z);
        const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
        for (int i = 1; i <= n; ++i) {
            const double t = static_cast<double>(i) / n;
            out.push_back({{from.x + t * (m.end.x - from.x), from.y + t * (m.end.y - from.y), from.z + t * (m.end.z - from.z)},
                           m.kind});
        }
        from = m.end;
    }
    return out;
}

}  // namespace

class TestAreaClearing : public QObject {
    Q_OBJECT
private slots:
    void samplePlansOneStepWithItsTool()
    {
        const Plan plan = test::samplePlan(kSample);
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        QCOMPARE(plan.steps.size(), std::size_t{1});
        const Step& s = plan.steps[0];
        QCOMPARE(s.kind, StepKind::AreaClearing);
        QCOMPARE(s.machiningType, MachiningType::AreaClearing);
        QCOMPARE(s.label(), std::string("Area clearing I"));
        QVERIFY(s.tool && s.path);
        QCOMPARE(s.tool->toolId, 27);  // the library's 10 mm flat end mill
        QCOMPARE(plan.tool(27)->diameter, 10.0);
        QCOMPARE(s.payload.as<DrawnPoints>().points.size(), std::size_t{14});
        QCOMPARE(millingOf(s).cutDepth, 6.0);
    }

    // The feed moves at each layer's depth go through the drawn points in
    // the order drawn, after the ramp; the depth is reached in layers of at
    // most γ·D.
    void tapeFollowsThePassesInTheirOrder()
    {
        const Plan plan = test::samplePlan(kSample);
        const Step& s = plan.steps[0];
        const double D = plan.tool(s.tool->toolId)->diameter;
        std::vector<double> layers;
        for (const Move& m : s.path->moves)
            if (m.kind == MoveKind::Feed && (layers.empty() || m.end.z < layers.back() - 1e-9)) layers.push_back(m.end.z);
        QCOMPARE(layers.back(), -6.0);
        const int expected = static_cast<int>(std::ceil(6.0 / (plan.technology.gamma * D) - 1e-9));
        std::vector<double> levels;
        for (const Move& m : s.path->moves)
            if (m.kind == MoveKind::Feed && m.feed == FeedKind::Cut &&
                std::find(levels.begin(), levels.end(), m.end.z) == levels.end())
                levels.push_back(m.end.z);
        QCOMPARE(static_cast<int>(levels.size()), expected);
        for (const double z : levels) {
            // The cutting moves at this level, after the ramp's return to the start.
            std::vector<Point2> at;
            for (const Move& m : s.path->moves)
                if (m.kind == MoveKind::Feed && m.feed == FeedKind::Cut && std::abs(m.end.z - z) < 1e-9)
                    at.push_back({m.end.x, m.end.y});
            // The drawn points appear in order as the ends of the last moves.
            const auto& pts = s.payload.as<DrawnPoints>().points;
            QVERIFY(at.size() >= pts.size() - 1);
            const std::vector<Point2> tail(at.end() - static_cast<long>(pts.size() - 1), at.end());
            for (std::size_t i = 1; i < pts.size(); ++i)
                QVERIFY2(distance(tail[i - 1], pts[i]) < 1e-9, qPrintable(QString("pass %1 at z %2").arg(i).arg(z)));
        }
    }

    // Every point of every move keeps the tool inside the area (outline and
    // island); rapids below the top only straight down over the start; every
    // point of the strips is within the radius of a cut at the full depth.
    void toolStaysInTheAreaAndCutsEveryStrip()
    {
        const Plan plan = test::samplePlan(kSample);
        const Step& s = plan.steps[0];
        const double R = plan.tool(s.tool->toolId)->radius();
        const Region region = normalised(*millingOf(s).region);
        const RegionDistance inside(region);
        std::vector<Point2> floor;
        // Rapids below the top: straight down over the start point, no
        // deeper than a clearance above the floor cut there so far.
        Point3 from = s.path->start;
        double cut = 0.0;
        for (const Move& m : s.path->moves) {
            if (m.kind == MoveKind::Rapid && m.end.z < 0.0) {
                QVERIFY(std::abs(m.end.x - from.x) < 1e-9 && std::abs(m.end.y - from.y) < 1e-9);
                QVERIFY(distance({m.end.x, m.end.y}, s.payload.as<DrawnPoints>().points.front()) < 1e-9);
                QVERIFY2(m.end.z >= cut + 1.0 - 1e-9, "a rapid into material");
            }
            if (m.kind != MoveKind::Rapid) cut = std::min(cut, m.end.z);
            from = m.end;
        }
        for (const Sample& p : samples(*s.path, 0.05)) {
            if (p.p.z >= 0.0) continue;
            QVERIFY2(inside({p.p.x, p.p.y}) + R <= kTol,
                     qPrintable(QString("the tool leaves the area at (%1, %2)").arg(p.p.x).arg(p.p.y)));
            if (std::abs(p.p.z + millingOf(s).cutDepth) < 1e-9) floor.push_back({p.p.x, p.p.y});
        }
        // The strips, sampled across: all reached at the depth.
        int checked = 0;
        const auto& pts = s.payload.as<DrawnPoints>().points;
        for (std::size_t k = 1; k < pts.size(); ++k) {
            const Point2 a = pts[k - 1], b = pts[k], u = (1.0 / distance(a, b)) * (b - a), n{-u.y, u.x};
            for (double t = 0.0; t <= distance(a, b); t += 0.5)
                for (double w = -R * 0.98; w <= R * 0.98; w += R * 0.49) {
                    const Point2 q = a + t * u + w * n;
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const Point2 f : floor) nearest = std::min(nearest, distance(q, f));
                    QVERIFY2(nearest <= R + 0.03, qPrintable(QString("(%1, %2) not cut to depth").arg(q.x).arg(q.y)));
                    ++checked;
                }
        }
        QVERIFY(checked > 1000);
    }

    // The unswept area the check reports, against a count of 0.1 mm cells
    // inside the area farther than R from every pass.
    void unsweptAreaIsReportedAsMeasured()
    {
        const Job job = sampleJob();
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        const Diagnostic* d = on(ds, "points");
        QVERIFY2(d && d->severity == Severity::Warning, messages(ds).c_str());
        QVERIFY(!hasErrors(ds));
        const Plan plan = test::samplePlan(kSample);
        const Step& s = plan.steps[0];
        const Region region = normalised(*millingOf(s).region);
        const RegionDistance inside(region);
        const paths::Unswept u = paths::unsweptArea(region, s.payload.as<DrawnPoints>().points, 5.0);
        double cells = 0.0, largestSide = 0.0;
        constexpr double h = 0.1;
        for (double x = 10 + h / 2; x < 110; x += h)
            for (double y = 10 + h / 2; y < 70; y += h)
                if (inside({x, y}) < 0.0 && polylineDistance(s.payload.as<DrawnPoints>().points, {x, y}) > 5.0) {
                    cells += h * h;
                    if (x > 62 && y > 29 && y < 51) largestSide += h * h;
                }
        QVERIFY2(std::abs(u.area - cells) < 0.01 * cells, qPrintable(QString("%1 vs %2").arg(u.area).arg(cells)));
        // The largest piece is the one right of the boss, left on purpose.
        QVERIFY2(std::abs(u.largest - largestSide) < 0.02 * largestSide, qPrintable(QString("%1 vs %2").arg(u.largest).arg(largestSide)));
        QVERIFY(u.largestAt.x > 62 && u.largestAt.y > 29 && u.largestAt.y < 51);
        QVERIFY2(d->message.starts_with(fmt::format("the passes leave {:.1f} mm² of the area unswept in {} places",
                                                    u.area, u.pieces)),
                 d->message.c_str());
        // More passes, past the boss on its right and along the gap under
        // the top row, sweep most of what was left.
        std::vector<Point2> more = s.payload.as<DrawnPoints>().points;
        for (const Point2 p : {Point2{15, 65}, Point2{15, 60}, Point2{105, 60}, Point2{105, 51}, Point2{98, 51},
                               Point2{98, 29}, Point2{105, 29}, Point2{105, 40}, Point2{95, 40}})
            more.push_back(p);
        const paths::Unswept fewer = paths::unsweptArea(region, more, 5.0);
        QVERIFY2(fewer.area < 0.5 * u.area, qPrintable(QString("%1 of %2").arg(fewer.area).arg(u.area)));
        QVERIFY(!paths::firstExcursion(region, more, 5.0));
    }

    // The nearest approach of a straight pass to a line and to an arc, by hand.
    void nearestApproachIsExact()
    {
        const auto line = ContourSegment::line({0, 0}, {10, 0});
        auto a = paths::nearestApproach({2, 3}, {8, 5}, line);
        QCOMPARE(a.distance, 3.0);
        QVERIFY(distance(a.at, {2, 3}) < 1e-12);
        a = paths::nearestApproach({2, 3}, {4, -1}, line);  // crossing at x = 3.5
        QCOMPARE(a.distance, 0.0);
        QVERIFY(distance(a.at, {3.5, 0}) < 1e-12);
        a = paths::nearestApproach({12, 4}, {15, 0}, line);  // past the line's end
        // The foot of (10, 0) on the pass (12,4)-(15,0): t = ((10-12)*3 + (0-4)*(-4)) / 25 = 0.4 -> (13.2, 2.4).
        QVERIFY(std::abs(a.distance - std::hypot(3.2, 2.4)) < 1e-12);
        // A half circle of radius 5 about the origin, counter-clockwise from (5, 0) to (-5, 0).
        const auto arc = ContourSegment::arc({5, 0}, {-5, 0}, {0, 0}, true);
        a = paths::nearestApproach({-6, 8}, {6, 8}, arc);  // above: nearest at (0, 8), 3 from the arc's top
        QCOMPARE(a.distance, 3.0);
        QVERIFY(distance(a.at, {0, 8}) < 1e-12);
        a = paths::nearestApproach({-6, -2}, {6, -2}, arc);  // below the half circle: nearest to its ends, straight below them
        QVERIFY(std::abs(a.distance - 2.0) < 1e-12);
        QVERIFY(distance(a.at, {5, -2}) < 1e-12 || distance(a.at, {-5, -2}) < 1e-12);
        a = paths::nearestApproach({0, 1}, {0, 9}, arc);  // through the arc at (0, 5)
        QCOMPARE(a.distance, 0.0);
        QVERIFY(distance(a.at, {0, 5}) < 1e-12);
        a = paths::nearestApproach({-1, 1}, {1, 1}, arc);  // inside the circle: 5 - |(±1, 1)|
        QVERIFY(std::abs(a.distance - (5 - std::sqrt(2.0))) < 1e-12);
    }

    void pointsReadAndWriteAsText()
    {
        QCOMPARE(formatPoints({{15, 15}, {105.5, -2}}), std::string("15, 15; 105.5, -2"));
        const auto p = parsePoints(" 1, 2;3.5 ,-4 ; ");
        QVERIFY(p && p->size() == 2 && (*p)[1].x == 3.5 && (*p)[1].y == -4);
        QVERIFY(parsePoints("") && parsePoints("")->empty());
        QVERIFY(!parsePoints("1 2; 3, 4"));
        QVERIFY(!parsePoints("1, 2, 3"));
        QVERIFY(!parsePoints("1, x"));
        QVERIFY(!parsePoints("1, nan"));
        // The form keeps what does not read and the check refuses it.
        Job job = sampleJob();
        const ModuleKind& kind = *findModuleKind("AREA");
        const auto field = std::find_if(kind.fields().begin(), kind.fields().end(),
                                        [](const FormField& f) { return f.key == "points"; });
        QVERIFY(field != kind.fields().end() && field->kind == FormFieldKind::Points);
        QCOMPARE(field->getText(job.units[0].module).substr(0, 16), std::string("15, 15; 105, 15;"));
        field->setText(job.units[0].module, "15, 15; 105");
        QCOMPARE(field->getText(job.units[0].module), std::string("15, 15; 105"));
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(on(ds, "points"));
        QCOMPARE(on(ds, "points")->message,
                 std::string("'15, 15; 105' is not a list of points; type each point as X, Y and separate the points "
                             "with ';' (10, 20; 60, 20), or draw the passes in the Figure tab"));
        field->setText(job.units[0].module, "15, 15; 105, 15");
        QCOMPARE(field->getText(job.units[0].module), std::string("15, 15; 105, 15"));
    }

    void jobFileRoundTripAndInch()
    {
        const Job job = sampleJob();
        const std::string text = writeJob(job);
        const auto j = nlohmann::json::parse(text);
        QCOMPARE(j["units"][0]["points"].size(), std::size_t{14});
        QVERIFY(j["units"][0]["points"][1] == nlohmann::json::parse("[105, 15]"));
        const auto back = readJob(text);
        QVERIFY(back.job && *back.job == job);
        QCOMPARE(writeJob(*back.job), text);
        const Job inch = withLengths(job, LengthUnit::Inch, [](double v) { return v / 25.4; });
        const auto read = readJob(writeJob(inch));
        QVERIFY(read.job);
        const auto tiny = [](double v) { return std::abs(v) < 1e-12; };
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(!hasErrors(ds));
        QVERIFY(tiny(inch.units[0].module.as<AreaClearing>().points[1].x - 105 / 25.4));
        QVERIFY(tiny(inch.units[0].module.as<AreaClearing>().diameter - 10 / 25.4));
    }

    void refusals_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        QTest::newRow("one point") << "points=[[15, 15]]" << "points"
                                   << "only one point is drawn; a pass runs from a start point to an end point: draw at "
                                      "least two points";
        QTest::newRow("outside the stock") << "points=[[15, 15], [130, 15]]" << "points"
                                           << "point 2 (130 mm, 15 mm) lies outside the stock";
        QTest::newRow("same point") << "points=[[15, 15], [40, 15], [40, 15]]" << "points"
                                    << "pass 2 ends where it starts; remove the repeated point";
        QTest::newRow("pass near the wall") << "points=[[15, 15], [105, 15], [105, 14]]" << "points"
                                            << "pass 2 takes the tool's edge 1 mm outside the area K1 (or into an island) "
                                               "with the tool's centre at (105 mm, 14 mm); keep each pass a tool radius "
                                               "from the walls";
        QTest::newRow("through the boss") << "points=[[15, 40], [100, 40]]" << "points"
                                          << "pass 1 takes the tool's edge 13 mm outside the area K1 (or into an island) "
                                             "with the tool's centre at (80 mm, 40 mm); keep each pass a tool radius "
                                             "from the walls";
        QTest::newRow("start on the boss") << "points=[[80, 40], [100, 40]]" << "points"
                                           << "the start point (80 mm, 40 mm) puts the tool's edge 13 mm outside the "
                                              "area K1 or into an island; start at least a tool radius inside";
        QTest::newRow("no tool of that diameter") << "diameter=7" << "diameter"
                                                  << "the library has no centre-cutting flat end mill of 7 mm, the width "
                                                     "the passes were drawn for; its flat end mills: 2 mm, 3 mm, 4 mm, "
                                                     "5 mm, 6 mm, 8 mm, 10 mm, 12 mm, 16 mm, 20 mm, 25 mm";
        QTest::newRow("diameter zero") << "diameter=0" << "diameter"
                                       << "the tool diameter is 0 mm; it must be positive: the passes are strips one "
                                          "tool wide";
        QTest::newRow("pinned tool of another diameter") << "tools={\"area\": 26}" << "tools"
                                                         << "T26 (flat end mill Ø8 mm) is pinned, but the passes were "
                                                            "drawn for a tool of 10 mm; pin a tool of that diameter or "
                                                            "change the diameter and redraw";
        QTest::newRow("unknown contour") << "outline=\"K9\"" << "outline"
                                         << "K9 is not a contour of the job's figure elements (its contours: K1, K2)";
    }
    void refusals()
    {
        QFETCH(QString, change);
        QFETCH(QString, field);
        QFETCH(QString, message);
        auto j = nlohmann::json::parse(writeJob(sampleJob()));
        const std::string c = change.toStdString();
        const auto eq = c.find('=');
        j["units"][0][c.substr(0, eq)] = nlohmann::json::parse(c.substr(eq + 1));
        auto read = readJob(j.dump());
        QVERIFY(read.job);
        const Diagnostics ds = checkJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        const Diagnostic* d = on(ds, field.toStdString());
        QVERIFY2(d && d->severity == Severity::Error, messages(ds).c_str());
        if (!message.isEmpty()) QCOMPARE(QString::fromStdString(d->message), message);
    }
};

QTEST_APPLESS_MAIN(TestAreaClearing)
#include "test_area_clearing.moc"
