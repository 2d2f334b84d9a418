// A two-path lathe's programs read back (verify/tape_readback_two_path.h):
// both two-path samples' programs, in every dialect that writes two-path
// programs, mm and inch, read back with no finding, their waits read and
// paired; a coolant word that moves (a dialect built in memory) planted in
// either program is found on its line of that program, fatal; a wait taken
// out of one program is an unpaired wait; a pass made deeper on path 2 is
// found on its line.
#include "support/readback.h"
#include "support/support.h"

#include "machine/machine.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "verify/tape_readback.h"
#include "verify/tape_readback_two_path.h"
#include "verify/tape_reader.h"
#include "verify/verify.h"

#include <QRegularExpression>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// Every finding, in words, with its program and line.
QString allFindings(const verify::Report& r, const Plan& plan)
{
    QString s;
    for (const auto& f : r.findings) s += QString::fromStdString(verify::describe(f, plan)) + "\n";
    return s;
}

QStringList linesOf(const std::string& nc) { return QString::fromStdString(nc).split('\n'); }

// The 1-based line of the first line of `lines` that `match` holds, from `from`.
int firstLine(const QStringList& lines, const QRegularExpression& match, int from = 0)
{
    for (int i = from; i < lines.size(); ++i)
        if (match.match(lines[i]).hasMatch()) return i + 1;
    return 0;
}

struct Posted {
    Plan plan;
    PostOptions po;
    verify::TwoPathPrograms programs;
};

Posted posted(const QString& sample, const QString& dialect, LengthUnit units = LengthUnit::Millimetre)
{
    Posted p;
    p.plan = planOf(sample);
    p.po = postOptions(p.plan, dialect.toStdString(), units);
    if (auto programs = verify::twoPathPrograms(p.plan, p.po)) p.programs = std::move(*programs);
    return p;
}

}  // namespace

class TestTapeReadbackTwoPath : public QObject {
    Q_OBJECT

private slots:
    void bothSamplesReadBackInEveryDialect_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("inch");
        const QStringList dialects = shippedDialectsWriting(DialectWrites::TwoPathPrograms);
        QVERIFY(dialects.contains("fanuc") && dialects.contains("linuxcnc"));
        for (const QString s : {"lathe-two-path-cylinder.taiwa", "lathe-two-path-taper.taiwa"})
            for (const QString& d : dialects)
                for (const bool inch : {false, true}) QTest::newRow(qPrintable(s + " " + d + (inch ? " inch" : " mm"))) << s << d << inch;
    }
    void bothSamplesReadBackInEveryDialect()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        QFETCH(bool, inch);
        const Posted p = posted(sample, dialect, inch ? LengthUnit::Inch : LengthUnit::Millimetre);
        QVERIFY(p.plan.ok());
        QCOMPARE(p.programs.programs.size(), std::size_t{2});
        const Machine* machine = findMachine(p.plan.mmJob.machine);
        QVERIFY(machine && machine->layout.multiPath);
        const post::Dialect& d = post::dialectNamed(p.po.dialect);
        std::vector<std::vector<verify::TapeWait>> waits;
        for (const auto& program : p.programs.programs) {
            const auto reading = verify::readLatheTape(program.nc, d, &machine->layout.multiPath->waitCodes);
            QVERIFY2(reading.error.empty(), reading.error.c_str());
            QCOMPARE(reading.inches, inch);
            QVERIFY(reading.motions.size() > 5);
            QVERIFY(reading.waits.size() >= 2);
            waits.push_back(reading.waits);
            // Without the wait codes the program is not read through (its waits and dwells are refused or taken for switches).
            if (dialect == "linuxcnc") QVERIFY(!verify::readLatheTape(program.nc, d).error.empty());
        }
        QCOMPARE(waits[0].size(), waits[1].size());
        for (std::size_t i = 0; i < waits[0].size(); ++i) {
            QCOMPARE(waits[0][i].code, waits[1][i].code);
            QVERIFY(waits[0][i].code > 0);
        }
        verify::Report r;  // no section: the bar judges depth
        verify::readBackTwoPath(r, p.plan, p.programs, d, p.po);
        QVERIFY2(r.findings.empty(), qPrintable(allFindings(r, p.plan)));
        // readBack of the job posts and reads the same programs.
        const verify::Report plain = verify::verifyPlan(p.plan);
        verify::Report whole = plain;
        verify::readBack(whole, p.plan, postProcess(p.plan.steps, p.plan.tools, p.po), d, p.po);
        QCOMPARE(whole.findings.size(), plain.findings.size());
    }

    // A coolant word that rapids into the bar, in path 1's or path 2's program (X mirrored there).
    void aCoolantWordIntoTheBarIsFoundOnItsProgramsLine_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<int>("program");
        QTest::addColumn<QString>("word");
        QTest::newRow("linuxcnc p1") << "linuxcnc" << 1 << "M8 G0 X10 Z-20";
        QTest::newRow("linuxcnc p2") << "linuxcnc" << 2 << "M8 G0 X-10 Z-20";
        QTest::newRow("fanuc p1") << "fanuc" << 1 << "M8 G0 X10. Z-20.";
        QTest::newRow("fanuc p2") << "fanuc" << 2 << "M8 G0 X-10. Z-20.";
    }
    void aCoolantWordIntoTheBarIsFoundOnItsProgramsLine()
    {
        QFETCH(QString, dialect);
        QFETCH(int, program);
        QFETCH(QString, word);
        Posted p = posted("lathe-two-path-cylinder.taiwa", dialect);
        QCOMPARE(p.programs.programs.size(), std::size_t{2});
        post::Dialect hostile = post::dialectNamed(dialect.toStdString());
        hostile.coolantOn = word.toStdString();
        std::string& nc = p.programs.programs[static_cast<std::size_t>(program - 1)].nc;
        QStringList lines = linesOf(nc);
        static const QRegularExpression coolant(R"(^(N\d+ )?M8$)");
        const int line = firstLine(lines, coolant);
        QVERIFY(line > 0);
        for (QString& l : lines)
            if (const auto m = coolant.match(l); m.hasMatch()) l = m.captured(1) + word;
        nc = lines.join('\n').toStdString();

        const verify::Report plain = verify::verifyPlan(p.plan);
        QVERIFY(!plain.fatal());
        verify::Report r = plain;
        verify::readBackTwoPath(r, p.plan, p.programs, hostile, p.po);
        QVERIFY(r.fatal());
        const verify::Finding* first = nullptr;
        for (const auto& f : r.findings)
            if (!first && f.kind == verify::FindingKind::UnplannedMove) first = &f;
        QVERIFY2(first, qPrintable(allFindings(r, p.plan)));
        QCOMPARE(first->program, program);
        QCOMPARE(first->line, line);
        QCOMPARE(first->part, std::string("rapid"));
        QVERIFY2(first->size > 1.0, qPrintable(QString::number(first->size)));
        QVERIFY(first->fatal());
        const QString words = QString::fromStdString(verify::describe(*first, p.plan));
        QVERIFY2(words.contains(QString("program p%1 line %2").arg(program).arg(line)) && words.contains("into stock"), qPrintable(words));
        for (const auto& f : r.findings) QVERIFY(f.kind != verify::FindingKind::UnpairedWait);
    }

    // The second meeting taken out of path 2's program: its waits no longer pair with path 1's.
    void aWaitTakenOutIsADeadlock_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("fanuc") << "fanuc";
        QTest::newRow("haas") << "haas";
        QTest::newRow("linuxcnc") << "linuxcnc";
    }
    void aWaitTakenOutIsADeadlock()
    {
        QFETCH(QString, dialect);
        for (const QString sample : {"lathe-two-path-cylinder.taiwa", "lathe-two-path-taper.taiwa"}) {
            Posted p = posted(sample, dialect);
            QCOMPARE(p.programs.programs.size(), std::size_t{2});
            std::string& nc = p.programs.programs[1].nc;
            QStringList lines = linesOf(nc);
            const bool fanuc = dialect != "linuxcnc";
            const int at = firstLine(lines, QRegularExpression(fanuc ? "^M102$" : R"(^\(wait M102)"));
            QVERIFY(at > 0);
            const int count = fanuc ? 1 : firstLine(lines, QRegularExpression("^o202 endif$")) - at + 1;
            QVERIFY(count > 0);
            for (int k = 0; k < count; ++k) lines[at - 1 + k].clear();  // the lines kept (their sources stay in step)
            nc = lines.join('\n').toStdString();

            verify::Report r;
            verify::readBackTwoPath(r, p.plan, p.programs, post::dialectNamed(p.po.dialect), p.po);
            QCOMPARE(r.findings.size(), std::size_t{1});
            const verify::Finding& f = r.findings.front();
            QCOMPARE(f.kind, verify::FindingKind::UnpairedWait);
            QVERIFY(f.fatal());
            // FANUC: path 1's M102 meets path 2's M103 (or nothing); LinuxCNC: path 2's
            // next wait is at meeting 3's level, or path 1's second has none to meet.
            QVERIFY(f.program == 1 || f.program == 2);
            const QStringList on = linesOf(p.programs.programs[static_cast<std::size_t>(f.program - 1)].nc);
            QVERIFY(f.line > 0 && f.line <= on.size());
            if (fanuc) {
                QCOMPARE(f.program, 1);
                QCOMPARE(on[f.line - 1], QString("M102"));
            } else {
                QVERIFY2(on[f.line - 1].startsWith("M66 P0 L") && (f.program == 1 || f.line > at), qPrintable(on[f.line - 1]));
            }
            const QString words = QString::fromStdString(verify::describe(f, p.plan));
            QVERIFY2(words.contains("deadlock") && words.contains(QString("program p%1 line %2").arg(f.program).arg(f.line)),
                     qPrintable(words));
        }
    }

    // Path 2's second pass 2 mm deeper (its X 4 mm nearer the axis): the infeed and the cut found on their lines.
    void aDeeperPassIsFound_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("fanuc") << "fanuc";
        QTest::newRow("linuxcnc") << "linuxcnc";
    }
    void aDeeperPassIsFound()
    {
        QFETCH(QString, dialect);
        Posted p = posted("lathe-two-path-taper.taiwa", dialect);
        QCOMPARE(p.programs.programs.size(), std::size_t{2});
        std::string& nc = p.programs.programs[1].nc;
        QStringList lines = linesOf(nc);
        const bool fanuc = dialect == "fanuc";
        const int wait = firstLine(lines, QRegularExpression(fanuc ? "^M102$" : R"(^\(wait M102)"));
        QVERIFY(wait > 1);
        static const QRegularExpression infeed(R"(^(N\d+ )?X(-\d+\.?\d*)$)");
        const auto m = infeed.match(lines[wait - 2]);
        QVERIFY2(m.hasMatch(), qPrintable(lines[wait - 2]));
        lines[wait - 2] = m.captured(1) + "X" + QString::number(m.captured(2).toDouble() + 4.0, 'f', 3);
        nc = lines.join('\n').toStdString();

        verify::Report r;
        verify::readBackTwoPath(r, p.plan, p.programs, post::dialectNamed(p.po.dialect), p.po);
        QVERIFY2(!r.findings.empty(), "the deeper pass is not found");
        const verify::Finding& f = r.findings.front();
        QCOMPARE(f.kind, verify::FindingKind::UnplannedMove);
        QCOMPARE(f.program, 2);
        QCOMPARE(f.line, wait - 1);
        QCOMPARE(f.part, std::string("rapid"));
        // The cut after it, from the deeper X, is no planned move either.
        QVERIFY2(r.findings.size() >= 2 && r.findings[1].program == 2 && r.findings[1].line > wait, qPrintable(allFindings(r, p.plan)));
    }
};

QTEST_GUILESS_MAIN(TestTapeReadbackTwoPath)
#include "test_tape_readback_two_path.moc"
