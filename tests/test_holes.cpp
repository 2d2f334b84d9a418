// Module HOLES (hole patterns): a geometric oracle of its own, the hole
// centres computed by hand (the bolt circle's angles, the rotated grid row
// by row, every other row backwards), each step's cycle at every hole at
// the depth the rules give (docs/holes.md) with the R plane 1 mm above the
// top, the tools in machining order, the dialects' cycles, the cavity, the
// job file round trip, and every refusal with its message.
#include "support/hand_plan.h"
#include "support/support.h"

#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/registry.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/cutting.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <cmath>

using namespace taiwa;

namespace {

constexpr double kTol = 1e-4;  // mm

std::string messages(const Diagnostics& ds)
{
    std::string s;
    for (const auto& d : ds) s += d.field + ": " + d.message + "\n";
    return s;
}

// A job of HOLES units written as the job file has them.
Job holesJob(const std::string& units, double height = 25)
{
    const std::string text = R"({"format": "taiwa-job", "version": 5, "lengthUnit": "mm", "material": "aluminium-6061",
        "stock": {"shape": "block", "x": 0, "y": 0, "width": 140, "length": 140, "height": )" +
                             std::to_string(height) + R"(}, "units": [)" + units + "]}";
    auto r = readJob(text);
    if (!r.job) throw std::runtime_error("job not read: " + text);
    return *r.job;
}

Diagnostics checked(const std::string& units, const std::vector<Tool>& library = defaultToolLibrary())
{
    return checkJob(holesJob(units), TechnologyTable::builtIn(), library);
}

// The message on `field` of unit 1 (or 2), or "".
std::string messageOn(const Diagnostics& ds, const std::string& field, int unit = 1)
{
    for (const auto& d : ds)
        if (d.field == field && d.unit == unit) return d.message;
    return {};
}

std::vector<Point3> cycleHoles(const Step& s)
{
    std::vector<Point3> out;
    for (const Move& m : s.path->moves)
        if (m.kind == MoveKind::DrillCycle) out.push_back(m.end);
    return out;
}

const Step* stepOf(const Plan& plan, int unit, StepKind kind)
{
    for (const Step& s : plan.steps)
        if (s.unit == unit && s.kind == kind) return &s;
    return nullptr;
}

int indexOf(const Plan& plan, const Step* s) { return static_cast<int>(s - plan.steps.data()); }

void compareHoles(const Step& s, const std::vector<Point2>& expected, double z, double r, CycleKind cycle)
{
    const auto at = cycleHoles(s);
    QCOMPARE(at.size(), expected.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
        QVERIFY2(std::abs(at[i].x - expected[i].x) < kTol && std::abs(at[i].y - expected[i].y) < kTol,
                 qPrintable(QString("%1 hole %2 at %3 %4, not %5 %6").arg(QString::fromStdString(s.label())).arg(i + 1)
                                .arg(at[i].x).arg(at[i].y).arg(expected[i].x).arg(expected[i].y)));
        QVERIFY2(std::abs(at[i].z - z) < kTol, qPrintable(QString("depth %1, not %2").arg(at[i].z).arg(z)));
    }
    for (const Move& m : s.path->moves) {
        QCOMPARE(m.kind, MoveKind::DrillCycle);
        QCOMPARE(m.cycle, cycle);
        QVERIFY(std::abs(m.retractZ - r) < kTol);
    }
}

// Drill points of 118°: the point below the full diameter is r / tan(59°).
double point118(double d) { return d / 2 / std::tan(59.0 * M_PI / 180.0); }

// The bolt circle of the flange, by hand: centre (70, 70), R 45, 30° + k·60°.
const std::vector<Point2> kBoltCircle{{70 + 38.971143, 92.5}, {70, 115},       {70 - 38.971143, 92.5},
                                      {70 - 38.971143, 47.5}, {70, 25},        {70 + 38.971143, 47.5}};

}  // namespace

class TestHoles : public QObject {
    Q_OBJECT
private slots:
    void flangeIsCentreDrilledDrilledThenTappedAndReamed()
    {
        const Plan plan = test::samplePlan("holes-bolt-circle.taiwa");
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        QCOMPARE(plan.steps.size(), std::size_t{6});
        // Unit 1: six M8 holes. Spot with the A6.3 centre drill (the largest
        // no wider than the 6.8 tap drill) to its 90° cone's full width.
        const Step* spot = stepOf(plan, 0, StepKind::CentreDrilling);
        const Step* drill = stepOf(plan, 0, StepKind::Drilling);
        const Step* tap = stepOf(plan, 0, StepKind::Tapping);
        QVERIFY(spot && drill && tap);
        QCOMPARE(spot->tool->toolId, 2);
        QCOMPARE(plan.tool(drill->tool->toolId)->diameter, 6.8);
        QCOMPARE(tap->tool->toolId, 65);
        QVERIFY(indexOf(plan, spot) < indexOf(plan, drill) && indexOf(plan, drill) < indexOf(plan, tap));
        compareHoles(*spot, kBoltCircle, -3.15, 1.0, CycleKind::Drill);
        // The tap drill's full diameter 3 pitches below the thread (12 + 3.75), its point below.
        compareHoles(*drill, kBoltCircle, -(15.75 + point118(6.8)), 1.0, CycleKind::Drill);
        // The tap 2 pitches below the full thread, at its pitch.
        compareHoles(*tap, kBoltCircle, -14.5, 1.0, CycleKind::Tap);
        for (const Move& m : tap->path->moves) QCOMPARE(m.pitch, 1.25);
        for (const Move& m : drill->path->moves) QCOMPARE(m.peck, 0.0);  // 17.8 mm < 3 x 6.8

        // Unit 2: reamed Ø12 H7: the 11.8 pre-drill 1 mm below the depth, the reamer 0.5 mm.
        const Step* rspot = stepOf(plan, 1, StepKind::CentreDrilling);
        const Step* rdrill = stepOf(plan, 1, StepKind::Drilling);
        const Step* ream = stepOf(plan, 1, StepKind::Reaming);
        QVERIFY(rspot && rdrill && ream);
        QCOMPARE(plan.tool(rdrill->tool->toolId)->diameter, 11.8);
        QCOMPARE(plan.tool(ream->tool->toolId)->type, ToolType::Reamer);
        QVERIFY(indexOf(plan, rspot) < indexOf(plan, rdrill) && indexOf(plan, rdrill) < indexOf(plan, ream));
        compareHoles(*rdrill, {{70, 70}}, -(16 + point118(11.8)), 1.0, CycleKind::Drill);
        compareHoles(*ream, {{70, 70}}, -15.5, 1.0, CycleKind::Ream);
        // Tapping feeds its pitch a revolution exactly.
        const auto sf = stepSpeedsFeeds(*tap, *plan.tool(65), plan.mmJob.material);
        QVERIFY(sf);
        QCOMPARE(sf->feed, sf->rpm * 1.25);
    }

    void gridRowsRunEveryOtherBackwards()
    {
        const Plan plan = test::samplePlan("holes-grid.taiwa");
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        // By hand: u = (cos 15°, sin 15°) = (0.9659258, 0.2588190), v = (-0.2588190, 0.9659258);
        // corner (20, 20), 20 along the rows, 18 between them, 4 x 3.
        const double ux = 0.96592583, uy = 0.25881905, vx = -0.25881905, vy = 0.96592583;
        std::vector<Point2> expected;
        for (const auto& [c, r] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1},
                                                                    {1, 1}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}})
            expected.push_back({20 + 20 * c * ux + 18 * r * vx, 20 + 20 * c * uy + 18 * r * vy});
        QVERIFY(std::abs(expected[3].x - 77.955548) < 1e-5 && std::abs(expected[3].y - 35.529142) < 1e-5);
        QVERIFY(std::abs(expected[11].x - 68.638064) < 1e-5 && std::abs(expected[11].y - 70.302471) < 1e-5);
        const Step* drill = stepOf(plan, 0, StepKind::Drilling);
        QVERIFY(drill);
        QCOMPARE(plan.tool(drill->tool->toolId)->diameter, 6.0);
        compareHoles(*drill, expected, -(22 + point118(6)), 1.0, CycleKind::Drill);
        // 23.8 mm deep is more than 3 x 6: pecks of one diameter.
        for (const Move& m : drill->path->moves) QCOMPARE(m.peck, 6.0);
        // The bores: a line up the Y axis; the 18 mm pre-drill (2 mm under), the boring tool to depth.
        const std::vector<Point2> line{{125, 20}, {125, 50}, {125, 80}};
        const Step* pre = stepOf(plan, 1, StepKind::Drilling);
        const Step* bore = stepOf(plan, 1, StepKind::Boring);
        QVERIFY(pre && bore);
        QCOMPARE(plan.tool(pre->tool->toolId)->diameter, 18.0);
        QCOMPARE(plan.tool(bore->tool->toolId)->type, ToolType::BoringBar);
        compareHoles(*pre, line, -(16 + point118(18)), 1.0, CycleKind::Drill);
        compareHoles(*bore, line, -15, 1.0, CycleKind::Bore);
        QVERIFY(indexOf(plan, pre) < indexOf(plan, bore));
    }

    void arcGoesClockwiseForANegativePitch()
    {
        const Job j = holesJob(R"({"module": "HOLES", "pattern": "arc", "x": 70, "y": 70, "radius": 20, "angle": 0,
            "angularPitch": -90, "count": 3, "hole": "drilled", "diameter": 5, "depth": 5})");
        const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        compareHoles(*stepOf(plan, 0, StepKind::Drilling), {{90, 70}, {70, 50}, {50, 70}}, -(5 + point118(5)), 1.0,
                     CycleKind::Drill);
    }

    void dialectsWriteTheirCycles()
    {
        const Plan plan = test::samplePlan("holes-bolt-circle.taiwa");
        const auto tape = [&](const char* dialect) {
            return postProcess(plan.steps, defaultToolLibrary(), postOptions(plan, dialect, std::nullopt, 1000, "flange")).nc;
        };
        const std::string linuxcnc = tape("linuxcnc"), fanuc = tape("fanuc"), haas = tape("haas");
        const std::string siemens = tape("sinumerik"), heidenhain = tape("heidenhain");
        QVERIFY(linuxcnc.find("G33.1 Z-14.5 K1.25") != std::string::npos);
        QVERIFY(linuxcnc.find("G98 G85 X70 Y70 Z-15.5 R1") != std::string::npos);
        QVERIFY(fanuc.find("M29 S") != std::string::npos && fanuc.find("G98 G84 X") != std::string::npos);
        QVERIFY(haas.find("M29") == std::string::npos && haas.find("G84") != std::string::npos);
        QVERIFY(siemens.find("MCALL CYCLE84(5,1,0,-14.5,,0,3,,1.25,0,") != std::string::npos);
        QVERIFY(siemens.find("MCALL CYCLE85(5,1,0,-15.5,,0,") != std::string::npos);
        QVERIFY(heidenhain.find("CYCL DEF 207 RIGID TAPPING NEW ~") != std::string::npos);
        QVERIFY(heidenhain.find("Q239=+1.25 ;THREAD PITCH ~") != std::string::npos);
        QVERIFY(heidenhain.find("CYCL DEF 201 REAMING ~") != std::string::npos);
        const Plan grid = test::samplePlan("holes-grid.taiwa");
        const std::string bores = postProcess(grid.steps, defaultToolLibrary(), postOptions(grid, "linuxcnc", std::nullopt, 1000, "g")).nc;
        QVERIFY(bores.find("G98 G86 X125 Y20 Z-15 R1") != std::string::npos && bores.find(" P0") != std::string::npos);
        QVERIFY(bores.find("G98 G83 X") != std::string::npos && bores.find(" Q6") != std::string::npos);
        const std::string bores840 = postProcess(grid.steps, defaultToolLibrary(), postOptions(grid, "sinumerik", std::nullopt, 1000, "g")).nc;
        QVERIFY(bores840.find("MCALL CYCLE86(5,1,0,-15,,0,3,0,0,0,0)") != std::string::npos);
        const std::string bores530 = postProcess(grid.steps, defaultToolLibrary(), postOptions(grid, "heidenhain", std::nullopt, 1000, "g")).nc;
        QVERIFY(bores530.find("CYCL DEF 202 BORING ~") != std::string::npos);
    }

    void cavityIsTheHoleWithItsDrillPoint()
    {
        const Plan plan = test::samplePlan("holes-bolt-circle.taiwa");
        const ModuleInput& m = plan.mmJob.units[0].module;
        const auto cav = moduleKind(m).cavity(m, plan.technology);
        QVERIFY(cav);
        const Point2 hole = kBoltCircle[1];
        QCOMPARE(cav->depthAt(hole, 0.0), 15.75 + 3.4);                      // the tap drill's 90° bound
        QCOMPARE(cav->depthAt({hole.x + 3.9, hole.y}, 0.0), 14.5);           // the tap's flat tip
        QCOMPARE(cav->depthAt({hole.x + 4.1, hole.y}, 0.0), 0.0);            // outside the thread
        QCOMPARE(cav->depthAt({hole.x + 4.1, hole.y}, 0.2), 14.5);           // grown by 0.2
        QCOMPARE(cav->depthAt({70, 70}, 0.0), 0.0);                          // the centre is the other unit's
    }

    void jobFileRoundTripIsVersion5()
    {
        auto read = readJobFile(test::sourcePath("resources/samples/holes-bolt-circle.taiwa").toStdString());
        QVERIFY(read.job);
        QCOMPARE(formatVersionFor(*read.job), 5);
        const std::string text = writeJob(*read.job);
        QVERIFY(text.find("\"thread\": \"M8\"") != std::string::npos);
        QVERIFY(text.find("\"pitchY\"") == std::string::npos);  // only the pattern's own keys
        auto again = readJob(text);
        QVERIFY(again.job);
        QCOMPARE(*again.job, *read.job);
    }

    void refusals_data()
    {
        QTest::addColumn<QString>("unit");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const char* unit, const char* field, const char* message) {
            QTest::newRow(name) << unit << field << message;
        };
        row("pattern", R"({"module": "HOLES", "pattern": "star", "x": 70, "y": 70, "hole": "drilled", "diameter": 5, "depth": 5})",
            "pattern", "pattern \"star\" is not one of \"single\", \"line\", \"grid\", \"bolt circle\" or \"arc\"");
        row("hole", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "punched", "diameter": 5, "depth": 5})",
            "hole", "hole \"punched\" is not one of \"drilled\", \"tapped\", \"reamed\" or \"bored\"");
        row("count", R"({"module": "HOLES", "pattern": "line", "x": 10, "y": 10, "pitch": 10, "count": 0, "hole": "drilled", "diameter": 5, "depth": 5})",
            "count", "the number of holes 0 must be 1 to 1000");
        row("grid too many", R"({"module": "HOLES", "pattern": "grid", "x": 10, "y": 10, "pitch": 10, "pitchY": 10, "count": 100, "rows": 20, "hole": "drilled", "diameter": 5, "depth": 5})",
            "rows", "100 columns by 20 rows are 2000 holes, more than the 1000 a unit may have");
        row("pitch", R"({"module": "HOLES", "pattern": "line", "x": 10, "y": 10, "pitch": 5, "count": 3, "hole": "drilled", "diameter": 5, "depth": 5})",
            "pitch", "the pitch 5 mm is not more than the hole's diameter 5 mm: the holes would cut into each other");
        row("pitchY", R"({"module": "HOLES", "pattern": "grid", "x": 10, "y": 10, "pitch": 10, "pitchY": 4, "count": 2, "rows": 2, "hole": "drilled", "diameter": 5, "depth": 5})",
            "pitchY", "the pitch between rows 4 mm is not more than the hole's diameter 5 mm: the holes would cut into each other");
        row("bolt circle", R"({"module": "HOLES", "pattern": "bolt circle", "x": 70, "y": 70, "radius": 10, "count": 20, "hole": "drilled", "diameter": 5, "depth": 5})",
            "count", "the distance between neighbouring holes 3.129 mm is not more than the hole's diameter 5 mm: the holes would cut into each other");
        row("arc closes", R"({"module": "HOLES", "pattern": "arc", "x": 70, "y": 70, "radius": 30, "angularPitch": 115, "count": 4, "hole": "drilled", "diameter": 8, "depth": 5})",
            "count", "holes 1 and 4 lie 7.832 mm apart, not more than the diameter 8 mm: the arc closes on itself; fewer holes or a smaller angular pitch");
        row("angular pitch", R"({"module": "HOLES", "pattern": "arc", "x": 70, "y": 70, "radius": 30, "angularPitch": 0, "count": 2, "hole": "drilled", "diameter": 8, "depth": 5})",
            "angularPitch", "the angular pitch 0° must not be 0 and lie within ±360°");
        row("radius", R"({"module": "HOLES", "pattern": "bolt circle", "x": 70, "y": 70, "radius": 0, "count": 4, "hole": "drilled", "diameter": 8, "depth": 5})",
            "radius", "the radius 0 mm must be greater than zero");
        row("angle", R"({"module": "HOLES", "pattern": "line", "x": 10, "y": 10, "angle": 400, "pitch": 10, "count": 2, "hole": "drilled", "diameter": 5, "depth": 5})",
            "angle", "the angle 400° must be from -360° to 360°");
        row("outside", R"({"module": "HOLES", "pattern": "line", "x": 10, "y": 10, "pitch": 65, "count": 3, "hole": "drilled", "diameter": 5, "depth": 5})",
            "pattern", "hole 3 (X 140 mm, Y 10 mm) reaches outside the stock; move the pattern or enlarge the stock");
        row("through", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 10, "depth": 22})",
            "depth", "the hole goes down to 27 mm with its drill point (its tools go deeper than the depth 22 mm; docs/holes.md), below the stock's height 25 mm: through holes are not made; make it shallower");
        row("thread", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "tapped", "thread": "M7", "depth": 5})",
            "thread", "thread \"M7\" is not one this program taps: ISO metric coarse M3, M4, M5, M6, M8, M10, M12, M14, M16, M18, M20");
        row("tapped diameter", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "tapped", "thread": "M6", "diameter": 6, "depth": 5})",
            "diameter", "a tapped hole's diameter is its thread's: leave out \"diameter\"");
        row("thread on drilled", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "thread": "M6", "diameter": 6, "depth": 5})",
            "thread", "only a tapped hole has a thread; the hole is drilled");
        row("diameter range", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 0.5, "depth": 5})",
            "diameter", "the diameter 0.5 mm must be 1 mm to 100 mm");
        row("depth", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 5, "depth": 0})",
            "depth", "the depth 0 mm must be greater than zero");
        row("pin key", R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 5, "depth": 5, "tools": {"tap": 65}})",
            "tools.tap", "a drilled hole has no step \"tap\"; its steps are \"centre-drill\" or \"drill\"");
    }
    void refusals()
    {
        QFETCH(QString, unit);
        QFETCH(QString, field);
        QFETCH(QString, message);
        const Diagnostics ds = checked(unit.toStdString());
        QCOMPARE(QString::fromStdString(messageOn(ds, field.toStdString())), message);
    }

    void overlappingUnitsAreRefused()
    {
        // A bolt circle's ring leaves its middle free; a hole on the ring does not.
        const std::string ring = R"({"module": "HOLES", "pattern": "bolt circle", "x": 70, "y": 70, "radius": 40, "count": 6, "hole": "drilled", "diameter": 8, "depth": 5})";
        QVERIFY(checked(ring + R"(, {"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 20, "depth": 5})").empty());
        const Diagnostics ds = checked(ring + R"(, {"module": "HOLES", "pattern": "single", "x": 110, "y": 75, "hole": "drilled", "diameter": 8, "depth": 5})");
        QVERIFY2(!messageOn(ds, "pattern", 2).empty(), messages(ds).c_str());
    }

    void missingToolIsNamed()
    {
        std::vector<Tool> library;
        for (const Tool& t : defaultToolLibrary())
            if (t.type != ToolType::Tap && t.type != ToolType::CentreDrill) library.push_back(t);
        const Job j = holesJob(R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "tapped", "thread": "M8", "depth": 10})");
        const Plan plan = planJob(j, TechnologyTable::builtIn(), library);
        QVERIFY(!plan.ok());
        QCOMPARE(QString::fromStdString(messageOn(plan.diagnostics, "tools.tap")),
                 QString("no tap M8x1.25 (type tap, Ø8 mm, pitch 1.25 mm) whose flutes reach 12.5 mm in the tool library; add one"));
        QCOMPARE(QString::fromStdString(messageOn(plan.diagnostics, "tools.centre-drill")),
                 QString("no centre drill in the tool library; add one"));
        // A pinned tool of the wrong kind.
        const Job pinned = holesJob(R"({"module": "HOLES", "pattern": "single", "x": 70, "y": 70, "hole": "drilled", "diameter": 8, "depth": 10, "tools": {"drill": 27}})");
        const Plan p2 = planJob(pinned, TechnologyTable::builtIn(), defaultToolLibrary());
        QCOMPARE(QString::fromStdString(messageOn(p2.diagnostics, "tools.drill")),
                 QString("T27 (Flat end mill 10 mm carbide) is pinned for \"drill\" but is not a drill of Ø8 mm (the hole's) whose flutes reach 14 mm"));
    }
};

QTEST_APPLESS_MAIN(TestHoles)
#include "test_holes.moc"
