// Post-processors on hand-made steps: number formatting, modal words,
// framing of both dialects, inch conversion of coordinates and feeds, arcs,
// drilling cycles, tool changes, step comments, the block-to-move map, the
// tape image list.
#include "post/gcode_writer.h"
#include "post/post.h"
#include "support/rs274.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace taiwa;

namespace {

Tool tool(int id, ToolType type, double d)
{
    Tool t;
    t.id = id;
    t.name = "tool " + std::to_string(id);
    t.type = type;
    t.diameter = d;
    t.flutes = 2;
    t.cutting.push_back({"aluminium-6061", 10.0 * std::numbers::pi, 0.05, 0.5});  // n = 10000 / D: 1000 rpm at 10 mm
    return t;
}

// A pilot hole with T5 (10 mm drill) and a roughing pass with T12 (10 mm end mill).
std::vector<Step> steps()
{
    Step drill;
    drill.kind = StepKind::PilotHole;
    drill.module = "M4";
    drill.tool = ToolChoice{5, ""};
    drill.path = ToolPath{{10, 20, 5}, {}};
    Move cycle{MoveKind::DrillCycle, {10, 20, -11}};
    cycle.retractZ = 1;
    cycle.peck = 2;
    drill.path->moves.push_back(cycle);

    Step rough;
    rough.kind = StepKind::Roughing;
    rough.module = "M4";
    rough.tool = ToolChoice{12, ""};
    rough.path = ToolPath{{10, 20, 5}, {}};
    auto& m = rough.path->moves;
    m.push_back({MoveKind::Rapid, {10, 20, 1}});
    Move plunge{MoveKind::Feed, {10, 20, -3}};
    plunge.feed = FeedKind::Plunge;
    m.push_back(plunge);
    m.push_back({MoveKind::Feed, {30, 20, -3}});
    m.push_back({MoveKind::Feed, {30, 40, -3}});
    m.push_back({MoveKind::ArcCCW, {20, 50, -3}, {20, 40}});
    m.push_back({MoveKind::Rapid, {20, 50, 5}});
    return {drill, rough};
}

std::vector<Tool> library() { return {tool(5, ToolType::Drill, 10), tool(12, ToolType::FlatEndMill, 10)}; }

PostOptions options(const std::string& dialect, LengthUnit u = LengthUnit::Millimetre)
{
    PostOptions o;
    o.dialect = dialect;
    o.units = u;
    o.programName = "demo";
    o.material = "aluminium-6061";
    return o;
}

QStringList lines(const std::string& nc) { return QString::fromStdString(nc).split('\n', Qt::SkipEmptyParts); }

}  // namespace

class TestPost : public QObject {
    Q_OBJECT
private slots:
    void numbersAreFormattedByTheWriter()
    {
        using post::formatNumber;
        QCOMPARE(formatNumber(12.5, 3, false), std::string("12.5"));
        QCOMPARE(formatNumber(10.0, 3, false), std::string("10"));
        QCOMPARE(formatNumber(10.0, 3, true), std::string("10."));
        QCOMPARE(formatNumber(-0.0001, 3, false), std::string("0"));
        QCOMPARE(formatNumber(-0.0004, 3, true), std::string("0."));
        QCOMPARE(formatNumber(-1.23456, 4, false), std::string("-1.2346"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, formatNumber(std::nan(""), 3, false));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, formatNumber(std::numeric_limits<double>::infinity(), 3, false));
    }

    void linuxcncProgram()
    {
        const PostedProgram p = postProcess(steps(), library(), options("linuxcnc"));
        const QStringList l = lines(p.nc);
        QVERIFY(l.contains("G17 G21 G40 G49 G80 G90 G94 G64 P0.01"));
        QVERIFY(l.contains("T5 M6"));
        QVERIFY(l.contains("G43 H5"));
        QVERIFY(l.contains("G54 G0 X10 Y20 S1000 M3"));
        QVERIFY(l.contains("G98 G83 X10 Y20 Z-11 R1 Q2 F50"));  // drill: n x f = 1000 x 0.05
        QVERIFY(l.contains("G80"));
        QVERIFY(l.contains("(STEP 2: UNIT 1 M4 ROUGHING I T12)"));
        QVERIFY(l.contains("G1 Z-3 F50"));      // plunge at half the feed
        QVERIFY(l.contains("X30 F100"));        // modal G1, only what changes
        QVERIFY(l.contains("Y40"));
        QVERIFY(l.contains("G3 X20 Y50 I-10 J0"));
        QCOMPARE(l.last(), QString("M30"));
        QVERIFY(!p.nc.starts_with("%"));
        QVERIFY(p.nc.find("-0 ") == std::string::npos && p.nc.find("-0\n") == std::string::npos);
    }

    void fanucProgram()
    {
        const PostedProgram p = postProcess(steps(), library(), options("fanuc"));
        const QStringList l = lines(p.nc);
        QCOMPARE(l.first(), QString("%"));
        QCOMPARE(l.last(), QString("%"));
        QVERIFY(l[1].startsWith("O1000 (DEMO)"));
        QVERIFY(l.contains("N10 G17 G21 G40 G49 G80 G90"));
        QVERIFY(p.nc.find(" T5 M6\n") != std::string::npos);
        QVERIFY(p.nc.find(" G43 H12 Z5. M8\n") != std::string::npos);
        QVERIFY(p.nc.find(" G91 G28 Z0.\n") != std::string::npos);
        QVERIFY(p.nc.find(" G98 G83 X10. Y20. Z-11. R1. Q2. F50.\n") != std::string::npos);
        QVERIFY(p.nc.find("(STEP 1: UNIT 1 M4 PILOT HOLE T5)") != std::string::npos);
        // Sequence numbers rise by 10 on every block.
        int last = 0;
        for (const auto& line : l) {
            if (!line.startsWith('N')) continue;
            const int n = line.mid(1, line.indexOf(' ') - 1).toInt();
            QCOMPARE(n, last + 10);
            last = n;
        }
    }

    void inchOutputConvertsLengthsAndFeeds()
    {
        const PostedProgram p = postProcess(steps(), library(), options("linuxcnc", LengthUnit::Inch));
        const QStringList l = lines(p.nc);
        QVERIFY(l.contains("G17 G20 G40 G49 G80 G90 G94 G64 P0.01"));
        QVERIFY(l.contains("G54 G0 X0.3937 Y0.7874 S1000 M3"));
        QVERIFY(l.contains("G1 Z-0.1181 F1.97"));  // 50 mm/min
    }

    void everyLineKnowsItsSource()
    {
        const PostedProgram p = postProcess(steps(), library(), options("linuxcnc"));
        const QStringList l = lines(p.nc);
        QCOMPARE(p.lines.size(), static_cast<std::size_t>(l.size()));
        const int arc = static_cast<int>(l.indexOf("G3 X20 Y50 I-10 J0"));
        QCOMPARE(p.lines[static_cast<std::size_t>(arc)].step, 1);
        QCOMPARE(p.lines[static_cast<std::size_t>(arc)].move, 4);
        QCOMPARE(p.lines[0].step, -1);
    }

    void tapeImageCountsBlocksAndTape()
    {
        const PostedProgram p = postProcess(steps(), library(), options("fanuc"));
        const QString tape = QString::fromStdString(p.tapeImage);
        // Blocks: every line but comments and the '%' framing (the O-number line is a block).
        const int blocks = static_cast<int>(lines(p.nc).filter(QRegularExpression("^[^(%]")).size());
        QVERIFY2(tape.contains(QString("blocks %1 ").arg(blocks)), qPrintable(tape.right(200)));
        QVERIFY(tape.contains(QString("characters %1 ").arg(p.nc.size())));
        QVERIFY(tape.contains("     1  %"));
    }

    // Every linuxcnc program this test writes must satisfy LinuxCNC's own
    // interpreter, and what it reads back is our path.
    void linuxcncOutputPassesRs274()
    {
        for (const auto units : {LengthUnit::Millimetre, LengthUnit::Inch}) {
            const PostedProgram p = postProcess(steps(), library(), options("linuxcnc", units));
            const auto r = test::runRs274(p.nc);
            QVERIFY2(r.ok, qPrintable(r.errors));
            const double k = units == LengthUnit::Inch ? 25.4 : 1.0;
            const auto& last = r.moves.back();
            const auto arc = std::find_if(r.moves.begin(), r.moves.end(), [](const test::CanonMove& m) { return m.kind == test::CanonMove::Arc; });
            QVERIFY(arc != r.moves.end());
            QVERIFY(std::abs(arc->end.x * k - 20) < 2e-3 && std::abs(arc->end.y * k - 50) < 2e-3 && arc->rotation == 1);
            QVERIFY(std::abs(arc->centre.x * k - 20) < 2e-3 && std::abs(arc->centre.y * k - 40) < 2e-3);
            QVERIFY(last.kind == test::CanonMove::Traverse);
        }
    }

    void unknownDialectAndMissingToolAreRefused()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(steps(), library(), options("heidenhain")));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(steps(), {library()[0]}, options("fanuc")));
        QVERIFY(isDialect("fanuc") && isDialect("linuxcnc") && !isDialect("mazatrol"));
    }
};

QTEST_APPLESS_MAIN(TestPost)
#include "test_post.moc"
