// Post-processors on hand-made steps (no path generator involved): number
// formatting, modal words, the framing of both dialects, inch conversion of
// coordinates and feeds, arcs, drilling cycles, tool changes, comments, line
// limits, sequence numbers, the block-to-move map and the tape image list.
#include "post/dialect.h"
#include "post/gcode_writer.h"
#include "post/number_format.h"
#include "post/post.h"
#include "post/tape_image.h"

#include <QtTest>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

using namespace taiwa;

namespace {

// Cutting data giving n = 1000 rpm at 10 mm and feed = 1000 x 0.05 x 2 = 100 mm/min (drills 50).
Tool tool(int id, ToolType type, double d)
{
    Tool t;
    t.id = id;
    t.name = "tool " + std::to_string(id);
    t.type = type;
    t.diameter = d;
    t.flutes = 2;
    t.cutting.push_back({"aluminium-6061", 10.0 * std::numbers::pi, 0.05, 0.5});
    return t;
}

// Two pecked holes with T5 (10 mm drill), then a roughing pass with T12 (10 mm end mill).
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
    cycle.end = {30, 20, -11};
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
    o.machine = "vmc";
    return o;
}

QStringList lines(const std::string& nc) { return QString::fromStdString(nc).split('\n', Qt::SkipEmptyParts); }

// The lines strictly between two lines of a tape.
QStringList between(const QStringList& l, const QString& from, const QString& to)
{
    const auto a = l.indexOf(from), b = l.indexOf(to, a + 1);
    return a < 0 || b < 0 ? QStringList{} : l.mid(a + 1, b - a - 1);
}

}  // namespace

class TestPost : public QObject {
    Q_OBJECT
private slots:
    void fastNumbersEqualFmtsExactRounding()
    {
        // The writer formats scaled integers instead of fmt's "{:.3f}": the
        // text must be the same, half cases included (fmt rounds the exact
        // binary value; near a half the writer leaves the choice to fmt).
        const auto reference = [](double v, int d, bool point) {
            std::string s = fmt::format("{:.{}f}", v, d);
            if (s.find('.') != std::string::npos) {
                while (s.back() == '0') s.pop_back();
                if (s.back() == '.' && !point) s.pop_back();
            } else if (point) {
                s += '.';
            }
            if (s == "-0" || s == "-0.") s.erase(0, 1);
            return s;
        };
        std::mt19937_64 random(11);
        std::uniform_real_distribution<double> wide(-5000, 5000);
        std::uniform_int_distribution<int> grid(-5'000'000, 5'000'000);
        for (int i = 0; i < 400'000; ++i) {
            for (const int d : {3, 4}) {
                const double a = wide(random);
                const double half = (grid(random) + 0.5) / std::pow(10.0, d);  // x.xxx5: the half cases
                const double exact = grid(random) / std::pow(10.0, d);
                for (const double v : {a, half, exact, -half})
                    for (const bool point : {false, true})
                        if (post::formatNumber(v, d, point) != reference(v, d, point))
                            QFAIL(qPrintable(QString("%1 with %2 decimals: %3, fmt %4")
                                                 .arg(v, 0, 'g', 17).arg(d)
                                                 .arg(QString::fromStdString(post::formatNumber(v, d, point)),
                                                      QString::fromStdString(reference(v, d, point)))));
            }
        }
    }

    void numbersAreFormattedByTheWriter()
    {
        using post::formatNumber;
        QCOMPARE(formatNumber(12.5, 3, false), std::string("12.5"));     // trailing zeros trimmed
        QCOMPARE(formatNumber(10.0, 3, false), std::string("10"));
        QCOMPARE(formatNumber(10.0, 3, true), std::string("10."));       // FANUC: point always
        QCOMPARE(formatNumber(0.0, 3, true), std::string("0."));
        QCOMPARE(formatNumber(-0.0001, 3, false), std::string("0"));     // never -0
        QCOMPARE(formatNumber(-0.0004, 3, true), std::string("0."));
        QCOMPARE(formatNumber(-0.0, 4, false), std::string("0"));
        QCOMPARE(formatNumber(1.23456, 3, false), std::string("1.235"));  // mm: 3 decimals
        QCOMPARE(formatNumber(-1.23456, 4, false), std::string("-1.2346")); // inch: 4
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, formatNumber(std::nan(""), 3, false));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, formatNumber(std::numeric_limits<double>::infinity(), 3, false));
        QCOMPARE(post::formatInteger(3819.6), std::string("3820"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, post::formatInteger(std::nan("")));
    }

    void aNonNumberNeverReachesTheTape()
    {
        auto s = steps();
        s[1].path->moves[2].end.y = std::nan("");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(s, library(), options("linuxcnc")));
    }

    // The whole linuxcnc tape of the hand-made job, reviewed line by line.
    void linuxcncProgram()
    {
        const PostedProgram p = postProcess(steps(), library(), options("linuxcnc"));
        const QStringList expected{
            "(Program demo)",
            "(Generated by Taiwa " TAIWA_VERSION "; machine vmc; dialect linuxcnc; material aluminium-6061; units mm)",
            "(T5 D10 tool 5)",
            "(T12 D10 tool 12)",
            "G17 G21 G40 G49 G54 G80 G90 G94 G64 P0.01",
            "(STEP 1: UNIT 1 M4 PILOT HOLE T5)",
            "G53 G0 Z0",
            "T5 M6",
            "G43 H5",
            "S1000 M3",
            "G0 G54 X10 Y20",
            "Z5",
            "M8",
            "G98 G83 X10 Y20 Z-11 R1 Q2 F50",  // drill: n x f = 1000 x 0.05
            "X30 Y20",                         // the same cycle, one more hole
            "G80",
            "(STEP 2: UNIT 1 M4 ROUGHING I T12)",
            "M9",
            "M5",
            "G53 G0 Z0",
            "T12 M6",
            "G43 H12",
            "S1000 M3",
            "G0 G54 X10 Y20",
            "Z5",
            "M8",
            "Z1",
            "G1 Z-3 F50",          // plunge at half the feed
            "X30 F100",            // modal G1 and Z, only what changes
            "Y40",
            "G3 X20 Y50 I-10 J0",  // I, J from the start point
            "G0 Z5",
            "M9",
            "M5",
            "G53 G0 Z0",
            "M30",
        };
        QCOMPARE(lines(p.nc), expected);
        QVERIFY(p.nc.ends_with("M30\n"));
    }

    void fanucProgram()
    {
        auto o = options("fanuc");
        o.programName = "demo (v2) für";
        const PostedProgram p = postProcess(steps(), library(), o);
        const QStringList l = lines(p.nc);
        QCOMPARE(l.first(), QString("%"));
        QCOMPARE(l.last(), QString("%"));
        QCOMPARE(l[1], QString("O1000 (DEMO  V2  F?R)"));  // upper case, no nested parentheses, ASCII
        QCOMPARE(l[2], QString("(GENERATED BY TAIWA " TAIWA_VERSION "; MACHINE VMC; DIALECT FANUC; MATERIAL ALUMINIUM-6061; UNITS MM)"));
        QVERIFY(l.contains("N10 G17 G21 G40 G49 G80 G90"));
        QVERIFY(l.contains("(STEP 1: UNIT 1 M4 PILOT HOLE T5)"));
        QCOMPARE(l[l.size() - 2], QString("N310 M30"));
        // Sequence numbers rise by 10 on every block, and only blocks carry one.
        int last = 0;
        for (const auto& line : l) {
            if (line == "%" || line.startsWith('(') || line.startsWith('O')) continue;
            QVERIFY2(line.startsWith('N'), qPrintable(line));
            const int n = line.mid(1, line.indexOf(' ') - 1).toInt();
            QCOMPARE(n, last + 10);
            last = n;
        }
        QVERIFY(l.contains("N90 G98 G83 X10. Y20. Z-11. R1. Q2. F50."));
        QVERIFY(l.contains("N250 G3 X20. Y50. I-10. J0."));
    }

    void toolChangeSequences()
    {
        const QStringList fanuc = lines(postProcess(steps(), library(), options("fanuc")).nc);
        QCOMPARE(between(fanuc, "(STEP 2: UNIT 1 M4 ROUGHING I T12)", "N210 Z1."),
                 (QStringList{"N120 M9", "N130 M5", "N140 G91 G28 Z0.", "N150 G90", "N160 T12 M6", "N170 S1000 M3",
                              "N180 G0 G54 X10. Y20.", "N190 G43 H12 Z5.", "N200 M8"}));
        const QStringList linuxcnc = lines(postProcess(steps(), library(), options("linuxcnc")).nc);
        QCOMPARE(between(linuxcnc, "(STEP 2: UNIT 1 M4 ROUGHING I T12)", "Z1"),
                 (QStringList{"M9", "M5", "G53 G0 Z0", "T12 M6", "G43 H12", "S1000 M3", "G0 G54 X10 Y20", "Z5", "M8"}));
    }

    void sameToolNextStepRetractsWithoutChange()
    {
        auto s = steps();
        Step again = s[1];
        again.number = 2;
        again.path->start = {50, 50, 5};
        s.push_back(again);
        const QStringList l = lines(postProcess(s, library(), options("linuxcnc")).nc);
        QCOMPARE(l.filter("M6").size(), 2);
        QCOMPARE(between(l, "(STEP 3: UNIT 1 M4 ROUGHING II T12)", "X10 Y20 Z1"), (QStringList{"X50"}));
    }

    void inchOutputConvertsLengthsAndFeeds()
    {
        const QStringList l = lines(postProcess(steps(), library(), options("linuxcnc", LengthUnit::Inch)).nc);
        QVERIFY(l.contains("G17 G20 G40 G49 G54 G80 G90 G94 G64 P0.01"));
        QVERIFY(l.contains("(T5 D0.3937 tool 5)"));
        QVERIFY(l.contains("G0 G54 X0.3937 Y0.7874"));
        QVERIFY(l.contains("G98 G83 X0.3937 Y0.7874 Z-0.4331 R0.0394 Q0.0787 F1.97"));  // 50 mm/min
        QVERIFY(l.contains("G1 Z-0.1181 F1.97"));
        QVERIFY(l.contains("X1.1811 F3.94"));  // 100 mm/min
        QVERIFY(l.contains("G3 X0.7874 Y1.9685 I-0.3937 J0"));
        QVERIFY(l.contains("S1000 M3"));  // a speed is not a length
    }

    void arcsFullPartialAndHelical()
    {
        auto s = steps();
        auto& m = s[1].path->moves;
        m.insert(m.end() - 1, {MoveKind::ArcCW, {20, 50, -3}, {20, 45}});    // full circle: end = start
        m.insert(m.end() - 1, {MoveKind::ArcCCW, {25, 45, -4}, {20, 45}});   // quarter helix down 1 mm
        const QStringList l = lines(postProcess(s, library(), options("linuxcnc")).nc);
        const auto i = l.indexOf("G3 X20 Y50 I-10 J0");
        QVERIFY(i > 0);
        QCOMPARE(l[i + 1], QString("G2 X20 Y50 I0 J-5"));        // X, Y stated even when unchanged
        QCOMPARE(l[i + 2], QString("G3 X25 Y45 Z-4 I0 J-5"));    // Z only when it changes
    }

    // The writer's last guard: an arc whose radius or length is below one
    // unit of the tape (0.001 mm, 0.0001 in) is written as a line, or not at
    // all, never as "G3 X92 Y30 I0 J0"; a full circle stays a full circle.
    void degenerateArcsBecomeLines()
    {
        using Sink = post::MachineSink;
        const auto tape = [](LengthUnit u, const std::function<void(Sink&)>& moves) {
            post::GCodeWriter w(post::linuxcncDialect(), u);
            w.toolChange(1);
            w.rapid({92, 29.9999, -2});
            moves(w);
            const QStringList l = lines(w.text());
            return l.mid(l.indexOf(QRegularExpression("^G0 G54 X92 .*")) + 2);  // after the rapid across and down
        };
        const auto mm = LengthUnit::Millimetre, in = LengthUnit::Inch;
        // A slot's collapsed ring: quarter arcs of radius 0.1 µm around (92, 30).
        QCOMPARE(tape(mm, [](Sink& w) {
                     w.arc({92.0001, 30, -2}, {92, 30}, false, 100);
                     w.arc({92, 30.0001, -2}, {92, 30}, false, 100);
                     w.feed({28, 30.0001, -2}, 100);
                 }),
                 (QStringList{"G1 X28 F100"}));
        // Radius 0.4 µm, half a turn down a little: a line.
        QCOMPARE(tape(mm, [](Sink& w) { w.arc({92, 30.0007, -2.1}, {92, 30.0003}, true, 100); }),
                 (QStringList{"G1 Y30.001 Z-2.1 F100"}));
        // Radius 10 mm but 0.5 µm along the arc: a line, not a full circle.
        QCOMPARE(tape(mm, [](Sink& w) {
                     const double a = 5e-5;  // rad
                     w.arc({82 + 10 * std::cos(a), 29.9999 + 10 * std::sin(a), -2}, {82, 29.9999}, false, 100);
                 }),
                 QStringList{});
        // A true full circle of 1 µm radius is still written as one.
        QCOMPARE(tape(mm, [](Sink& w) { w.arc({92, 29.9999, -2}, {92.001, 29.9999}, false, 100); }),
                 (QStringList{"G3 X92 Y30 I0.001 J0 F100"}));
        // In inch (the writer's input is in tape units) one unit is 0.0001 in:
        // a radius of 0.00008 in is a line, one of 0.0003 in an arc.
        QCOMPARE(tape(in, [](Sink& w) { w.arc({92.00016, 29.9999, -2}, {92.00008, 29.9999}, false, 100); }),
                 (QStringList{"G1 X92.0002 F100"}));
        QCOMPARE(tape(in, [](Sink& w) { w.arc({92.0006, 29.9999, -2}, {92.0003, 29.9999}, false, 100); }),
                 (QStringList{"G3 X92.0006 Y29.9999 I0.0003 J0 F100"}));
    }

    // The job's work offset reaches the tape: in LinuxCNC's preamble and with
    // the first move after each tool change in both dialects, and nowhere a
    // G54 the job did not ask for. Every G54..G59; FANUC's G54.1 P1..P48;
    // LinuxCNC's G59.1..G59.3. Before, the tape always said G54.
    void workOffsetReachesTheTape_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("asked");
        QTest::addColumn<QString>("words");
        const auto row = [](const QString& dialect, const QString& asked, const QString& words) {
            QTest::newRow(qPrintable(dialect + " " + asked)) << dialect << asked << words;
        };
        for (const char* d : {"linuxcnc", "fanuc"})
            for (const char* g : {"G54", "G55", "G56", "G57", "G58", "G59"}) row(d, g, g);
        for (const char* g : {"G59.1", "G59.2", "G59.3"}) row("linuxcnc", g, g);
        for (const int p : {1, 2, 17, 47, 48}) row("fanuc", QString("G54.1 P%1").arg(p), QString("G54.1 P%1").arg(p));
        // One spelling on the tape whatever the job's.
        row("fanuc", "g54.1p7", "G54.1 P7");
        row("linuxcnc", " g56 ", "G56");
    }
    void workOffsetReachesTheTape()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, asked);
        QFETCH(QString, words);
        for (const LengthUnit u : {LengthUnit::Millimetre, LengthUnit::Inch}) {
            auto o = options(dialect.toStdString(), u);
            o.workOffset = asked.toStdString();
            QCOMPARE(workOffsetProblem(o.dialect, o.workOffset), std::nullopt);
            const QStringList l = lines(postProcess(steps(), library(), o).nc);
            const bool fanuc = dialect == "fanuc";
            const QString units = u == LengthUnit::Inch ? "G20" : "G21";
            const QString across = u == LengthUnit::Inch ? "X0.3937 Y0.7874" : fanuc ? "X10. Y20." : "X10 Y20";
            // Both tool changes restate it with the first move across.
            const QRegularExpression restated("^(N\\d+ )?G0 " + QRegularExpression::escape(words) + " " + across + "$");
            QCOMPARE(l.filter(restated).size(), 2);
            if (fanuc) QVERIFY(l.contains("N10 G17 " + units + " G40 G49 G80 G90"));
            else QVERIFY(l.contains("G17 " + units + " G40 G49 " + words + " G80 G90 G94 G64 P0.01"));
            // No other work offset anywhere: every G5x word on the tape is the job's.
            for (const auto& line : l) {
                if (line.startsWith('(')) continue;
                const QString rest = QString(line).remove(words);
                QVERIFY2(!rest.contains(QRegularExpression("G5[4-9]")), qPrintable(line));
            }
        }
    }

    // What a controller does not have is refused, saying what it offers,
    // before anything is written; LinuxCNC has no G54.1 (its interpreter
    // stops at "Unknown g code used"), FANUC no G59.1.
    void workOffsetTheControllerLacksIsRefused_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("asked");
        QTest::addColumn<QString>("message");
        const QString lcnc = "linuxcnc offers G54 to G59, G59.1, G59.2 and G59.3";
        const QString fanuc = "fanuc offers G54 to G59 and G54.1 P1 to P48";
        QTest::newRow("linuxcnc G54.1 P1")
            << "linuxcnc" << "G54.1 P1"
            << "work offset 'G54.1 P1' cannot be posted for linuxcnc: linuxcnc has no G54.1 P (FANUC's extended work "
               "offsets); " + lcnc;
        QTest::newRow("linuxcnc G54.1 P48") << "linuxcnc" << "G54.1 P48" << lcnc;
        QTest::newRow("fanuc G59.1") << "fanuc" << "G59.1"
                                    << "work offset 'G59.1' cannot be posted for fanuc: fanuc has no G59.1; " + fanuc;
        QTest::newRow("fanuc G54.1 P0") << "fanuc" << "G54.1 P0" << "there is no G54.1 P0; " + fanuc;
        QTest::newRow("fanuc G54.1 P49") << "fanuc" << "G54.1 P49" << "there is no G54.1 P49; " + fanuc;
        QTest::newRow("linuxcnc G59.4") << "linuxcnc" << "G59.4" << "linuxcnc has no G59.4; " + lcnc;
        QTest::newRow("linuxcnc G53") << "linuxcnc" << "G53" << "not a work offset; " + lcnc;
        QTest::newRow("fanuc G60") << "fanuc" << "G60" << "not a work offset; " + fanuc;
        QTest::newRow("fanuc G54 P1") << "fanuc" << "G54 P1" << "not a work offset";
        QTest::newRow("empty") << "fanuc" << "" << "work offset '' cannot be posted for fanuc: not a work offset";
    }
    void workOffsetTheControllerLacksIsRefused()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, asked);
        QFETCH(QString, message);
        auto o = options(dialect.toStdString());
        o.workOffset = asked.toStdString();
        const auto why = workOffsetProblem(o.dialect, o.workOffset);
        QVERIFY(why.has_value());
        QCOMPARE(why->field, std::string("workOffset"));
        QVERIFY2(QString::fromStdString(why->message).contains(message), why->message.c_str());
        try {
            postProcess(steps(), library(), o);
            QFAIL("posted a work offset the controller lacks");
        } catch (const std::invalid_argument& e) {
            QCOMPARE(std::string(e.what()), why->message);
        }
    }

    void drillingWithAndWithoutPeck()
    {
        auto s = steps();
        auto& m = s[0].path->moves;
        m[1].peck = 0;  // second hole straight: a different cycle, stated in full
        Move third = m[1];
        third.end = {50, 20, -11};
        m.push_back(third);
        const QStringList l = lines(postProcess(s, library(), options("linuxcnc")).nc);
        QCOMPARE(between(l, "M8", "(STEP 2: UNIT 1 M4 ROUGHING I T12)"),
                 (QStringList{"G98 G83 X10 Y20 Z-11 R1 Q2 F50", "G81 X30 Y20 Z-11 R1", "X50 Y20", "G80"}));
    }

    void everyLineKnowsItsSource()
    {
        const PostedProgram p = postProcess(steps(), library(), options("linuxcnc"));
        const QStringList l = lines(p.nc);
        QCOMPARE(p.lines.size(), static_cast<std::size_t>(l.size()));
        const auto at = [&](const char* block) { return p.lines.at(static_cast<std::size_t>(l.indexOf(block))); };
        QCOMPARE(at("G3 X20 Y50 I-10 J0").step, 1);
        QCOMPARE(at("G3 X20 Y50 I-10 J0").move, 4);
        QCOMPARE(at("X30 F100").move, 2);
        QCOMPARE(at("X30 Y20").step, 0);  // the second hole
        QCOMPARE(at("X30 Y20").move, 1);
        QCOMPARE(at("T12 M6").step, 1);   // frame of step 2
        QCOMPARE(at("T12 M6").move, -1);
        QCOMPARE(p.lines.front().step, -1);  // program header
        QCOMPARE(p.lines.back().step, -1);   // M30
    }

    void tapeImageCountsBlocksAndTape()
    {
        const PostedProgram p = postProcess(steps(), library(), options("fanuc"));
        const QString tape = QString::fromStdString(p.tapeImage);
        // 39 lines: '%', O-number, 3 header comments, 2 step comments, 31 numbered blocks, '%'.
        // Blocks are the lines that are neither comments nor '%': the O line and N10..N310.
        const auto t = post::measureTape(p.nc);
        QCOMPARE(t.lines, std::size_t(39));
        QCOMPARE(t.blocks, std::size_t(32));
        QCOMPARE(t.characters, p.nc.size());  // LF is the end-of-block character
        QVERIFY(std::abs(t.metres() - static_cast<double>(p.nc.size()) * 0.00254) < 1e-12);
        QVERIFY2(tape.contains(QString("blocks 32   lines 39   characters %1 (EOB included)   tape length %2 m")
                                   .arg(p.nc.size())
                                   .arg(static_cast<double>(p.nc.size()) * 0.00254, 0, 'f', 2)),
                 qPrintable(tape.right(200)));
        QVERIFY(tape.contains("\n     10      40  T5 M6\n"));  // listing line 10 is block N40
        QVERIFY(tape.contains("\n      1          %\n"));
    }

    void sequenceNumbersWrapAfterN99999()
    {
        auto s = steps();
        auto& m = s[1].path->moves;
        for (int i = 0; i < 10000; ++i) m.insert(m.end() - 1, {MoveKind::Feed, {20.0 + (i % 2), 50, -3}});
        const QStringList l = lines(postProcess(s, library(), options("fanuc")).nc);
        QVERIFY(l.contains(QRegularExpression("N99990 .*")));
        const auto wrap = l.indexOf(QRegularExpression("N99990 .*"));
        QVERIFY(l[wrap + 1].startsWith("N10 "));
    }

    void commentsKeepWithinTheLine()
    {
        auto o = options("fanuc");
        o.programName = std::string(300, 'x');
        const PostedProgram p = postProcess(steps(), library(), o);
        for (const auto& line : lines(p.nc)) QVERIFY2(line.size() <= 128, qPrintable(line));
        QVERIFY(lines(p.nc)[1].startsWith("O1000 (XXXXXXXX"));
    }

    void writerDwellAndOrder()
    {
        post::GCodeWriter fanuc(post::fanucDialect(), LengthUnit::Millimetre);
        fanuc.toolChange(3);
        fanuc.dwell(1.5);
        QVERIFY(fanuc.text().ends_with("G4 X1.5\n"));
        post::GCodeWriter lcnc(post::linuxcncDialect(), LengthUnit::Millimetre);
        lcnc.toolChange(3);
        lcnc.dwell(1.5);
        QVERIFY(lcnc.text().ends_with("G4 P1.5\n"));
        // A cut from an unknown position is a bug of the caller, refused.
        QVERIFY_THROWS_EXCEPTION(std::logic_error, lcnc.feed({1, 2, 3}, 100));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, lcnc.arc({1, 2, 3}, {0, 0}, true, 100));
    }

    // LinuxCNC's G98 returns to the higher of the initial level and R: the
    // writer's idea of Z after a cycle started below R is R.
    void cycleStartedBelowRLeavesToolAtR()
    {
        post::GCodeWriter w(post::linuxcncDialect(), LengthUnit::Millimetre);
        w.toolChange(1);
        w.rapid({0, 0, 0.5});
        w.drillCycle({{5, 5, -3}, 1, 0, 100});
        w.rapid({5, 5, 1});  // already there
        w.rapid({6, 5, 1});
        QVERIFY2(w.text().ends_with("G98 G81 X5 Y5 Z-3 R1 F100\nG80\nG0 X6\n"), w.text().c_str());
    }

    void refusals()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(steps(), library(), options("mazatrol")));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(steps(), {library()[0]}, options("fanuc")));
        auto o = options("fanuc");
        o.material = "titanium";  // no cutting data
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(steps(), library(), o));
        auto s = steps();
        s[0].path.reset();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, postProcess(s, library(), options("fanuc")));
        QCOMPARE(dialectNames(), (std::vector<std::string>{"fanuc", "linuxcnc", "haas", "sinumerik", "heidenhain"}));
        QVERIFY(isDialect("fanuc") && isDialect("linuxcnc") && !isDialect("mazatrol"));
    }
};

QTEST_APPLESS_MAIN(TestPost)
#include "test_post.moc"
