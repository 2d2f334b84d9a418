// A two-path lathe's programs read back (verify/tape_readback_two_path.h):
// both two-path samples' programs, in every dialect that writes two-path
// programs, mm and inch, read back with no finding, their waits read and
// paired; a coolant word that moves (a dialect built in memory) planted in
// either program is found on its line of that program, fatal; a wait taken
// out of one program is an unpaired wait; a pass made deeper on path 2 is
// found on its line; the programs handed to the read-back (post/posted_job.h,
// as the export posts them) are the ones it judges. A finding names its
// program by the file the export writes ("in part.p2.nc at line 14"), in
// `taiwa verify --json` and `taiwa export` too.
#include "support/readback.h"
#include "support/support.h"

#include "machine/machine.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "post/posted_job.h"
#include "verify/tape_readback.h"
#include "verify/tape_readback_two_path.h"
#include "verify/tape_reader.h"
#include "verify/verify.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QStringList>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

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
    p.po = postOptions(p.plan, dialect.toStdString(), units, 1000, "part");
    if (auto programs = verify::twoPathPrograms(p.plan, p.po)) p.programs = std::move(*programs);
    return p;
}

// Program `n`'s file (Finding::program): "part.p1.nc", "part.p2.nc".
std::string fileOf(int n) { return "part.p" + std::to_string(n) + ".nc"; }

// Path 2's second pass 2 mm deeper (its X 4 mm nearer the axis) in `nc`;
// the 1-based line of path 2's second wait (0: not found).
int deepened(std::string& nc, bool fanuc)
{
    QStringList lines = linesOf(nc);
    const int wait = firstLine(lines, QRegularExpression(fanuc ? "^M102$" : R"(^\(wait M102)"));
    if (wait < 2) return 0;
    static const QRegularExpression infeed(R"(^(N\d+ )?X(-\d+\.?\d*)$)");
    const auto m = infeed.match(lines[wait - 2]);
    if (!m.hasMatch()) return 0;
    lines[wait - 2] = m.captured(1) + "X" + QString::number(m.captured(2).toDouble() + 4.0, 'f', 3);
    nc = lines.join('\n').toStdString();
    return wait;
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
        QCOMPARE(first->program, fileOf(program));
        QCOMPARE(first->line, line);
        QCOMPARE(first->part, std::string("rapid"));
        QVERIFY2(first->size > 1.0, qPrintable(QString::number(first->size)));
        QVERIFY(first->fatal());
        const QString words = QString::fromStdString(verify::describe(*first, p.plan));
        QVERIFY2(words.endsWith(QString(", in part.p%1.nc at line %2").arg(program).arg(line)) && words.contains("into stock"), qPrintable(words));
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
            QVERIFY(f.program == fileOf(1) || f.program == fileOf(2));
            const int n = f.program == fileOf(1) ? 1 : 2;
            const QStringList on = linesOf(p.programs.programs[static_cast<std::size_t>(n - 1)].nc);
            QVERIFY(f.line > 0 && f.line <= on.size());
            if (fanuc) {
                QCOMPARE(n, 1);
                QCOMPARE(on[f.line - 1], QString("M102"));
            } else {
                QVERIFY2(on[f.line - 1].startsWith("M66 P0 L") && (n == 1 || f.line > at), qPrintable(on[f.line - 1]));
            }
            const QString words = QString::fromStdString(verify::describe(f, p.plan));
            QVERIFY2(words.contains("deadlock") && words.endsWith(QString(", in part.p%1.nc at line %2").arg(n).arg(f.line)),
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
        const int wait = deepened(p.programs.programs[1].nc, dialect == "fanuc");
        QVERIFY(wait > 1);

        verify::Report r;
        verify::readBackTwoPath(r, p.plan, p.programs, post::dialectNamed(p.po.dialect), p.po);
        QVERIFY2(!r.findings.empty(), "the deeper pass is not found");
        const verify::Finding& f = r.findings.front();
        QCOMPARE(f.kind, verify::FindingKind::UnplannedMove);
        QCOMPARE(f.program, fileOf(2));
        QCOMPARE(f.line, wait - 1);
        QCOMPARE(f.part, std::string("rapid"));
        // The cut after it, from the deeper X, is no planned move either.
        QVERIFY2(r.findings.size() >= 2 && r.findings[1].program == fileOf(2) && r.findings[1].line > wait, qPrintable(allFindings(r, p.plan)));
    }

    // The programs handed over (postJob, as `taiwa export` and the station
    // post them before the export writes them) are the ones read back, not
    // programs posted again: the job's are clean, and path 2's altered after
    // posting is found on its line of part.p2.nc.
    void theHandedProgramsAreReadBack_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("fanuc") << "fanuc";
        QTest::newRow("linuxcnc") << "linuxcnc";
    }
    void theHandedProgramsAreReadBack()
    {
        QFETCH(QString, dialect);
        const Posted p = posted("lathe-two-path-taper.taiwa", dialect);
        const post::Dialect& d = post::dialectNamed(p.po.dialect);
        PostedJob job = postJob(p.plan, p.po);
        QVERIFY(job.twoPath && *job.twoPath);
        QCOMPARE((*job.twoPath)->programs.size(), std::size_t{2});
        for (std::size_t k = 0; k < 2; ++k) QCOMPARE((*job.twoPath)->programs[k].nc, p.programs.programs[k].nc);
        const verify::Report plain = verify::verifyPlan(p.plan);
        verify::Report clean = plain;
        verify::readBack(clean, p.plan, job, d, p.po);
        QVERIFY2(clean.findings.size() == plain.findings.size(), qPrintable(allFindings(clean, p.plan)));

        const int wait = deepened((*job.twoPath)->programs[1].nc, dialect == "fanuc");
        QVERIFY(wait > 1);
        verify::Report r = plain;
        verify::readBack(r, p.plan, job, d, p.po);
        const auto found = std::find_if(r.findings.begin(), r.findings.end(),
                                        [](const verify::Finding& f) { return f.kind == verify::FindingKind::UnplannedMove; });
        QVERIFY2(found != r.findings.end(), qPrintable(allFindings(r, p.plan)));
        QCOMPARE(found->program, fileOf(2));
        QCOMPARE(found->line, wait - 1);
        // The same job's programs posted again by the read-back itself (`taiwa verify`'s way) are the unaltered ones.
        verify::Report again = plain;
        verify::readBack(again, p.plan, job.tape, d, p.po);
        QCOMPARE(again.findings.size(), plain.findings.size());
    }

    // A shop's program end that leaves a subprogram (M99) stops each
    // program's reading: `taiwa verify --json` names each program by its
    // file ("p1.nc" without an export's stem), in its words and its
    // "program"; `taiwa export` by the file it would write.
    void theCommandsNameTheProgramsFile()
    {
        QTemporaryDir home;
        const auto [job, env] = test::shopDialectJob(home, "looping", "\"programEnd\": \"M30\"", "\"programEnd\": \"M99\"",
                                                     "lathe-two-path-cylinder.taiwa");
        QVERIFY(!job.isEmpty());
        const test::RunResult v = test::runTaiwa({"verify", job, "--json"}, env);
        QVERIFY2(v.exitCode == 3, qPrintable(v.out + v.err));
        QStringList named;
        for (const auto& f : QJsonDocument::fromJson(v.out.toUtf8()).object()["findings"].toArray()) {
            const QJsonObject o = f.toObject();
            QCOMPARE(o["kind"].toString(), QString("unread-tape"));
            QVERIFY2(o["message"].toString().endsWith(QString(", in %1 at line %2").arg(o["program"].toString()).arg(o["line"].toInt())),
                     qPrintable(o["message"].toString()));
            named << o["program"].toString();
        }
        QCOMPARE(named, QStringList({"p1.nc", "p2.nc"}));

        QTemporaryDir out;
        const test::RunResult e = test::runTaiwa({"export", job, "--no-pictures", "--out", out.path()}, env);
        QCOMPARE(e.exitCode, 3);
        QVERIFY2(e.err.contains(", in looping.p1.nc at line ") && e.err.contains(", in looping.p2.nc at line "), qPrintable(e.err));
    }
};

QTEST_GUILESS_MAIN(TestTapeReadbackTwoPath)
#include "test_tape_readback_two_path.moc"
