// The probing programs read back (verify/tape_readback.h readBackProbing,
// verify/tape_reader_probe.h, verify/tape_params.h): the parameter
// language's evaluator on hand-computed expressions and its refusals; every
// probe sample's setting program and probing cycle read back in every
// dialect that writes them, mm and inch, touching five times with no
// finding; a moving word planted in the program found on its line, fatal
// (and one from a dialect built in memory, through verify::readBack); a
// search shortened so that it touches nothing, and a touch target moved,
// found at the probing move's line; the programs handed to the read-back
// (post/posted_job.h, as the export posts them) are the ones it judges.
#include "support/readback.h"
#include "support/support.h"

#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "post/posted_job.h"
#include "post/probe_program.h"
#include "verify/tape_params.h"
#include "verify/tape_readback.h"
#include "verify/tape_reader_machine.h"
#include "verify/tape_reader_probe.h"
#include "verify/verify.h"

#include <QtTest>

#include <algorithm>
#include <functional>

#include <string>

using namespace taiwa;

namespace {

// The 1-based line of `text` holding `piece`; 0: none.
int lineOf(const std::string& text, const std::string& piece)
{
    const auto at = text.find(piece);
    if (at == std::string::npos) return 0;
    return static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 1;
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

QString described(const std::vector<verify::Finding>& found, const Plan& plan)
{
    QString s;
    for (const auto& f : found) s += QString::fromStdString(verify::describe(f, plan)) + "\n";
    return s;
}

double refusedOr(double fallback, const std::function<double()>& f)
{
    try {
        return f();
    } catch (const verify::tape::Unread&) {
        return fallback;
    }
}

}  // namespace

class TestTapeReadbackProbe : public QObject {
    Q_OBJECT

private slots:
    void evaluatesExpressions()
    {
        verify::tape::Params p(false);
        p.set("<x0>", 10.0);
        p.set("5070", 1.0);
        QCOMPARE(p.evaluate("[#<x0> - 32]"), -22.0);
        QCOMPARE(p.evaluate("[[#<x0> + 6] / 2]"), 8.0);
        QCOMPARE(p.evaluate("[2 + 3 * 4 - 6 / 3]"), 12.0);
        QCOMPARE(p.evaluate("[7 MOD 3]"), 1.0);
        QCOMPARE(p.evaluate("[2 ** 3 ** 2]"), 512.0);
        QCOMPARE(p.evaluate("[-#<x0> + 1]"), -9.0);
        QCOMPARE(p.evaluate("[#5070 EQ 0]"), 0.0);
        QCOMPARE(p.evaluate("[#5070 NE 0 AND 3 GT 2]"), 1.0);
        QCOMPARE(p.evaluate("[1 LT 1 OR 2 LE 2]"), 1.0);
        QCOMPARE(p.evaluate("[3 GE 4]"), 0.0);
        QCOMPARE(p.evaluate("SQRT[16]"), 4.0);
        QCOMPARE(p.evaluate("ABS[-2.5]"), 2.5);
        QCOMPARE(p.evaluate("ATAN[1]/[1]"), 45.0);
        QVERIFY(std::abs(p.evaluate("[COS[60] + SIN[30]]") - 1.0) < 1e-12);
        QCOMPARE(p.evaluate("#<X0>"), 10.0);  // names are case-blind
        const auto [name, value] = p.assignment("#<top> = [#<x0> * 2]");
        QCOMPARE(name, std::string("<top>"));
        QCOMPARE(value, 20.0);

        verify::tape::Params f(true);
        f.set("100", 5.0);
        f.set("5061", 4.9998);
        QCOMPARE(f.evaluate("[#100 / 2.]"), 2.5);
        QCOMPARE(f.evaluate("[ABS[#5061 - #100] LT 0.0005]"), 1.0);
        const auto words = f.words("G31 X#100 F150.");
        QCOMPARE(words.size(), std::size_t(3));
        QCOMPARE(words[1].value, 5.0);
        QVERIFY(words[1].computed);
    }

    void refusesWhatItCannotEvaluate_data()
    {
        QTest::addColumn<bool>("fanuc");
        QTest::addColumn<QString>("expression");
        QTest::newRow("division by zero") << false << "[1 / [2 - 2]]";
        QTest::newRow("MOD zero") << false << "[1 MOD 0]";
        QTest::newRow("unset") << false << "[#<nothing> + 1]";
        QTest::newRow("unset number") << true << "#130";
        QTest::newRow("unclosed") << false << "[1 + 2";
        QTest::newRow("dangling") << false << "[1 +]";
        QTest::newRow("unknown operator") << false << "[1 FOO 2]";
        QTest::newRow("unknown function") << false << "BOGUS[1]";
        QTest::newRow("square root of a negative") << false << "SQRT[-1]";
        QTest::newRow("name on FANUC") << true << "#<x0>";
        QTest::newRow("trailing") << false << "[1] 2";
    }
    void refusesWhatItCannotEvaluate()
    {
        QFETCH(bool, fanuc);
        QFETCH(QString, expression);
        verify::tape::Params p(fanuc);
        p.set("<x0>", 1.0);
        QCOMPARE(refusedOr(-12345.0, [&] { return p.evaluate(expression.toStdString()); }), -12345.0);
    }

    void samplesReadBack_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("inch");
        for (const char* s : {"probe-bore.taiwa", "probe-flange.taiwa", "probe-vise-block.taiwa"})
            for (const char* d : {"linuxcnc", "fanuc", "haas"})
                for (const bool inch : {false, true})
                    QTest::newRow(qPrintable(QString("%1 %2 %3").arg(s, d, inch ? "inch" : "mm"))) << s << d << inch;
    }
    void samplesReadBack()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        QFETCH(bool, inch);
        const Plan plan = test::planOf(sample);
        QVERIFY(!plan.setups.empty());
        const PostOptions o = postOptions(plan, dialect.toStdString(), inch ? LengthUnit::Inch : LengthUnit::Millimetre);
        const post::Dialect& d = post::dialectNamed(o.dialect);
        const PostedProgram posted = postProcess(plan.steps, plan.tools, o);
        verify::Report r;
        verify::readBack(r, plan, posted, d, o);
        QCOMPARE(test::tapeFindings(r, plan), QString());
        // It was read: five touches, each on the part, and the program ran to its end.
        for (const WorkSetup& w : plan.setups) {
            const std::string cycle = probingProgram(w, o);
            int touched = 0;
            const auto reading = verify::readProbingProgram(cycle, d, {0, 0, w.clearance}, [&](const Point3& a, const Point3& b) {
                (void)b;
                ++touched;
                return std::optional<Point3>(a);  // every touch where it starts: the arithmetic still runs
            });
            QCOMPARE(reading.tape.error, std::string());
            QCOMPARE(reading.stop, std::string());
            QCOMPARE(touched, 5);
            if (w.measured) QVERIFY(verify::settingFindings(w, plan.mmJob.stock.height, settingProgram(w, o), d, "s").empty());
        }
    }

    // "G0 Z-50" planted after the tool change: down into the part (or, in
    // the bore, through the stock onto the table), fatal on its line.
    void plantedMoveFound_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        for (const char* s : {"probe-bore.taiwa", "probe-flange.taiwa", "probe-vise-block.taiwa"})
            for (const char* d : {"linuxcnc", "fanuc"}) QTest::newRow(qPrintable(QString("%1 %2").arg(s, d))) << s << d;
    }
    void plantedMoveFound()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        const Plan plan = test::planOf(sample);
        const PostOptions o = postOptions(plan, dialect.toStdString(), LengthUnit::Millimetre);
        const post::Dialect& d = post::dialectNamed(o.dialect);
        const WorkSetup& w = plan.setups.front();
        const std::string change = " M6\n";
        const std::string cycle = replaced(probingProgram(w, o), change, " M6 G0 Z-50.\n");
        const int line = lineOf(cycle, "G0 Z-50.");
        QVERIFY(line > 0);
        const auto found = verify::probingFindings(w, plan.mmJob.stock.height, cycle, d, "x.u1.probe.nc");
        QVERIFY2(!found.empty(), qPrintable(described(found, plan)));
        QCOMPARE(found.front().line, line);
        QVERIFY2(found.front().fatal(), qPrintable(described(found, plan)));
        QCOMPARE(found.front().program, std::string("x.u1.probe.nc"));
        QVERIFY(described(found, plan).startsWith(QString("the job: the tape has a rapid the plan does not")));
        // The block 25 mm high on the table: the ball's centre 48 mm down, 40 mm inside the block's sides.
        if (sample == "probe-vise-block.taiwa" && dialect == "linuxcnc")
            QVERIFY2(described(found, plan).startsWith("the job: the tape has a rapid the plan does not, to X0.000 Y0.000 "
                                                       "Z-50.000, 42.000 mm into stock, in x.u1.probe.nc at line 7\n"),
                     qPrintable(described(found, plan)));
    }

    // A shop's program-number line that moves, from a dialect built in
    // memory: found through verify::readBack, on its line, fatal.
    void movingDialectWordFoundByReadBack()
    {
        const Plan plan = test::planOf("probe-flange.taiwa");
        post::Dialect shop = post::dialectNamed("fanuc");
        shop.name = "fanuc-shop";
        shop.programNumberLine = "G0 Z-50. (O{number:04d})";
        PostOptions o = postOptions(plan, "fanuc", LengthUnit::Millimetre, 1000, "flange");
        const PostedProgram posted = postProcess(plan.steps, plan.tools, o);
        verify::Report r;
        verify::readBack(r, plan, posted, shop, o);
        const QString found = test::tapeFindings(r, plan);
        QVERIFY2(found.contains(", in flange.u1.setting.nc at line 2\n") && found.contains(", in flange.u1.probe.nc at line 2\n"), qPrintable(found));
        QVERIFY2(found.contains("G0 Z-50"), qPrintable(found));
        QVERIFY(r.fatal());
    }

    // The programs handed over (postJob, as `taiwa export` and the station
    // post them before the export writes them) are the ones read back, not
    // programs posted again: the job's are clean, with the export's
    // O-numbers (after the tape's), and a cycle altered after posting is
    // found on its line of flange.u1.probe.nc.
    void theHandedProgramsAreReadBack()
    {
        const Plan plan = test::planOf("probe-flange.taiwa");
        const WorkSetup& w = plan.setups.front();
        QVERIFY(w.measured);
        const PostOptions o = postOptions(plan, "linuxcnc", LengthUnit::Millimetre, 1000, "flange");
        const post::Dialect& d = post::dialectNamed(o.dialect);
        PostedJob posted = postJob(plan, o);
        QCOMPARE(posted.probing.size(), std::size_t{1});
        PostOptions setting = o, cycle = o;
        setting.programNumber = 1001, cycle.programNumber = 1002;
        QCOMPARE(posted.probing.front().setting, settingProgram(w, setting));
        QCOMPARE(posted.probing.front().probe, probingProgram(w, cycle));
        verify::Report clean;
        verify::readBack(clean, plan, posted, d, o);
        QCOMPARE(test::tapeFindings(clean, plan), QString());

        std::string& text = posted.probing.front().probe;
        text = replaced(text, " M6\n", " M6 G0 Z-50.\n");
        const int line = lineOf(text, "G0 Z-50.");
        QVERIFY(line > 0);
        verify::Report r;
        verify::readBack(r, plan, posted, d, o);
        QVERIFY2(!r.findings.empty() && r.fatal(), qPrintable(test::tapeFindings(r, plan)));
        QCOMPARE(r.findings.front().program, std::string("flange.u1.probe.nc"));
        QCOMPARE(r.findings.front().line, line);
        // Posted again by the read-back itself (`taiwa verify`'s way): the unaltered ones.
        verify::Report again;
        verify::readBack(again, plan, posted.tape, d, o);
        QCOMPARE(test::tapeFindings(again, plan), QString());
    }

    // A search shortened so that it stops short of the side, and a target
    // moved further in: each found at its probing move's line.
    void changedSearchFound_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("move");  // the probing move's text
        QTest::addColumn<QString>("what");
        QTest::newRow("linuxcnc short") << "linuxcnc" << "G38.3 X[#<x0> - 52]" << "G38.3 X[#<x0> - 63]" << "G38.3 X[#<x0> - 63]"
                                        << "probing move that touches nothing";
        QTest::newRow("linuxcnc target") << "linuxcnc" << "G38.3 Y[#<y0> + 32]" << "G38.3 Y[#<y0> + 30]" << "G38.3 Y[#<y0> + 30]"
                                         << "probing move";
        QTest::newRow("fanuc short") << "fanuc" << "#105 = [#100 + 52.]" << "#105 = [#100 + 63.]" << "G31 X#105 F150.\nN270"
                                     << "probing move that touches nothing";
        QTest::newRow("fanuc top") << "fanuc" << "#105 = [#102 - 14.]" << "#105 = [#102 - 20.]" << "G31 Z#105" << "probing move";
        // Right from the centre, wrong from a start off it: the centre found as the sum, not the mean.
        QTest::newRow("linuxcnc centre") << "linuxcnc" << "#<cx> = [[#<xm> + #<xp>] / 2]" << "#<cx> = [#<xm> + #<xp>]"
                                         << "G55 G0 X0 Y0" << "rapid";
    }
    void changedSearchFound()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, move);
        QFETCH(QString, what);
        const Plan plan = test::planOf("probe-vise-block.taiwa");
        const PostOptions o = postOptions(plan, dialect.toStdString(), LengthUnit::Millimetre);
        const WorkSetup& w = plan.setups.front();
        const std::string original = probingProgram(w, o);
        QVERIFY(original.find(from.toStdString()) != std::string::npos);
        const std::string cycle = replaced(original, from.toStdString(), to.toStdString());
        const int line = lineOf(cycle, move.toStdString());
        const auto found = verify::probingFindings(w, plan.mmJob.stock.height, cycle, post::dialectNamed(o.dialect), "p");
        QVERIFY2(!found.empty(), qPrintable(QString::fromStdString(cycle)));
        QCOMPARE(found.front().line, line);
        QCOMPARE(QString::fromStdString(found.front().part), what);
        QVERIFY(verify::probingFindings(w, plan.mmJob.stock.height, original, post::dialectNamed(o.dialect), "p").empty());
    }
};

QTEST_GUILESS_MAIN(TestTapeReadbackProbe)
#include "test_tape_readback_probe.moc"
