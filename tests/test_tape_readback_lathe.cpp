// The lathe tape read back against the plan (verify/tape_readback.h,
// verify/tape_reader_lathe.h): every shipped lathe sample's tape (and a
// gang-tool lathe's job), in every dialect that writes lathe tapes, mm and
// inch, reads back with no finding
// and its G71 and G76 read as the cycles the plan has; a dialect word that
// moves (the loader refuses it, so the dialect is built in memory) is a
// rapid into the bar at its tape line, fatal; a cycle on the tape unlike
// the plan's is fatal; a line the reader does not follow is fatal and
// named; a shop dialect whose program end the reader cannot follow (M99)
// makes `taiwa export` of a lathe job write nothing. Two-path lathes'
// programs are read back in test_tape_readback_two_path.
#include "support/readback.h"
#include "support/support.h"

#include "job/job_file.h"
#include "machine/machine.h"
#include "model/turn_path.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "tools/tool_library.h"
#include "verify/tape_readback.h"
#include "verify/tape_reader.h"
#include "verify/verify.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// Each line whose words (after its N number) are `from` with `to` in their place.
std::string replaced(const std::string& tape, const QString& from, const QString& to)
{
    QStringList lines = QString::fromStdString(tape).split('\n');
    static const QRegularExpression number(R"(^(N\d+ )?(.*)$)");
    for (QString& l : lines) {
        const auto m = number.match(l);
        if (m.captured(2) == from) l = m.captured(1) + to;
    }
    return lines.join('\n').toStdString();
}

int lineHolding(const std::string& tape, const QString& text)
{
    const QStringList lines = QString::fromStdString(tape).split('\n');
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].contains(text)) return i + 1;
    return 0;
}

const verify::Finding* firstUnplanned(const verify::Report& r)
{
    for (const auto& f : r.findings)
        if (f.kind == verify::FindingKind::UnplannedMove) return &f;
    return nullptr;
}

// The steps whose control cycle the tape of `po` calls (G71, G76).
int cyclesOf(const Plan& plan, const PostOptions& po)
{
    if (post::dialectNamed(po.dialect).syntax == post::Syntax::Sinumerik) return 0;
    int n = 0;
    for (const auto& s : plan.steps)
        if (const TurnStep* t = turnOf(s)) n += (t->path.cycle && po.turningCycles) || t->thread ? 1 : 0;
    return n;
}

}  // namespace

class TestTapeReadbackLathe : public QObject {
    Q_OBJECT

private slots:
    void everyLatheSampleReadsBackInEveryDialect_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        const QStringList samples = QDir(sourcePath("resources/samples")).entryList({"lathe-*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(samples.size() >= 10);
        const QStringList dialects = shippedDialectsWriting(DialectWrites::LatheTapes);
        QVERIFY(dialects.size() >= 4);
        for (const QString& s : samples + QStringList{"gang/lathe-gang-shaft.taiwa"})
            for (const QString& d : dialects) QTest::newRow(qPrintable(s + " " + d)) << s << d;
    }
    void everyLatheSampleReadsBackInEveryDialect()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        const Plan plan = planOf(sample);
        QVERIFY2(plan.ok(), qPrintable(sample));
        QVERIFY(plan.mmJob.bar);
        const Machine* machine = findMachine(plan.mmJob.machine);
        QVERIFY(machine);
        if (machine->layout.multiPath) QSKIP("a two-path lathe: its programs are read back in test_tape_readback_two_path");
        for (const auto units : {LengthUnit::Millimetre, LengthUnit::Inch}) {
            const PostOptions po = postOptions(plan, dialect.toStdString(), units);
            const PostedProgram posted = postProcess(plan.steps, plan.tools, po);
            const auto reading = verify::readLatheTape(posted.nc, post::dialectNamed(po.dialect));
            QVERIFY2(reading.error.empty(), reading.error.c_str());
            QVERIFY(reading.motions.size() > 5);
            QCOMPARE(reading.inches, units == LengthUnit::Inch);
            const auto cycles = std::count_if(reading.motions.begin(), reading.motions.end(),
                                              [](const verify::TapeMotion& m) { return m.kind == verify::TapeMotion::Cycle; });
            QCOMPARE(static_cast<int>(cycles), cyclesOf(plan, po));
            verify::Report r;  // no section: the bar judges depth
            verify::readBack(r, plan, posted, post::dialectNamed(po.dialect), po);
            const QString found = tapeFindings(r, plan);
            QVERIFY2(found.isEmpty(), qPrintable(found));
        }
    }

    // The work offsets each lathe dialect writes, the extended ones too.
    void everyWorkOffsetReadsBack_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("offset");
        QTest::addColumn<QString>("words");
        QTest::newRow("fanuc G54.1") << "fanuc" << "G54.1 P7" << "G54.1 P7";
        QTest::newRow("haas G154") << "haas" << "G54.1 P7" << "G154 P7";
        QTest::newRow("linuxcnc G59.1") << "linuxcnc" << "G59.1" << "G59.1";
        QTest::newRow("sinumerik G505") << "sinumerik" << "G505" << "G505";
    }
    void everyWorkOffsetReadsBack()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, offset);
        QFETCH(QString, words);
        const Plan plan = planOf("lathe-turned-shaft.taiwa");
        PostOptions po = postOptions(plan, dialect.toStdString());
        po.workOffset = offset.toStdString();
        const PostedProgram posted = postProcess(plan.steps, plan.tools, po);
        QVERIFY(lineHolding(posted.nc, " " + words + " ") > 0);
        verify::Report r;
        verify::readBack(r, plan, posted, post::dialectNamed(po.dialect), po);
        QCOMPARE(tapeFindings(r, plan), QString());
    }

    // A coolant word that rapids into the bar: the finding at its line, how
    // deep inside the bar's half-section, fatal.
    void aCoolantWordIntoTheBarIsFoundAtItsLine_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("word");
        QTest::newRow("linuxcnc") << "linuxcnc" << "M8 G0 X10 Z-20";
        QTest::newRow("fanuc") << "fanuc" << "M8 G0 X10. Z-20.";
        QTest::newRow("sinumerik") << "sinumerik" << "M8 G0 X10 Z-20";
    }
    void aCoolantWordIntoTheBarIsFoundAtItsLine()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, word);
        post::Dialect hostile = post::dialectNamed(dialect.toStdString());
        hostile.coolantOn = word.toStdString();
        QVERIFY(!post::readDialect("{\"name\": \"evil\", \"coolantOn\": \"" + word.toStdString() + "\"}", "evil.json"));

        const Plan plan = planOf("lathe-turned-shaft.taiwa");
        QVERIFY(plan.ok());
        const PostOptions po = postOptions(plan, dialect.toStdString());
        const PostedProgram clean = postProcess(plan.steps, plan.tools, po);
        const verify::Report plain = verify::verifyPlan(plan);
        QVERIFY(!plain.fatal());
        QVERIFY(!plain.section.empty());
        verify::Report good = plain;
        verify::readBack(good, plan, clean, post::dialectNamed(po.dialect), po);
        QCOMPARE(tapeFindings(good, plan), QString());

        PostedProgram bad = clean;
        bad.nc = replaced(clean.nc, "M8", word);
        QVERIFY(bad.nc != clean.nc);
        const int line = lineHolding(bad.nc, word);
        QVERIFY(line > 0);
        verify::Report r = plain;
        verify::readBack(r, plan, bad, hostile, po);
        QVERIFY(r.fatal());
        const verify::Finding* first = firstUnplanned(r);
        QVERIFY2(first, qPrintable(tapeFindings(r, plan)));
        QCOMPARE(first->line, line);
        QCOMPARE(first->part, std::string("rapid"));
        QCOMPARE(first->position.x, 10.0);  // a diameter, as the tape writes it
        QCOMPARE(first->position.z, -20.0);
        // r = 5 at Z-20: 10 mm under the finished Ø30 there, about 7.2 mm
        // from the nearest surface (the Ø20 shoulder's corner at Z-15).
        QVERIFY2(first->size > 7.0 && first->size < 7.5, qPrintable(QString::number(first->size)));
        QVERIFY(first->fatal());
        const QString words = QString::fromStdString(verify::describe(*first, plan));
        QVERIFY2(words.contains("X10.000 Z-20.000") && words.contains(QString("tape line %1").arg(line)) && words.contains("into stock"),
                 qPrintable(words));
    }

    // A move clear of the bar is reported, not fatal; the approach that
    // follows a move the plan does not have must stay out of the bar too (a
    // shop's "G0 X0" at the change point is harmless, the diagonal approach
    // from there through the bar is not); a line the reader does not follow
    // is fatal and named.
    void aHarmlessMoveIsReportedAndAnUnreadLineIsFatal()
    {
        const Plan plan = planOf("lathe-turned-shaft.taiwa");
        const PostOptions po = postOptions(plan, "linuxcnc");
        PostedProgram p = postProcess(plan.steps, plan.tools, po);
        const std::string clean = p.nc;
        const verify::Report plain = verify::verifyPlan(plan);
        p.nc = replaced(clean, "M8", "M8 G0 X200");  // further out from the change point
        verify::Report r = plain;
        verify::readBack(r, plan, p, post::linuxcncDialect(), po);
        QVERIFY(r.count(verify::FindingKind::UnplannedMove) > 0);
        QVERIFY2(!r.fatal(), qPrintable(tapeFindings(r, plan)));

        p.nc = replaced(clean, "M8", "M8 G0 X0");  // at the change point's Z, in front of the bar
        verify::Report x0 = plain;
        verify::readBack(x0, plan, p, post::linuxcncDialect(), po);
        const verify::Finding* first = firstUnplanned(x0);
        QVERIFY(first && !first->fatal());
        QCOMPARE(first->line, lineHolding(p.nc, "M8 G0 X0"));
        const verify::Finding* fatal = nullptr;
        for (const auto& f : x0.findings)
            if (f.fatal() && !fatal) fatal = &f;
        QVERIFY2(fatal, qPrintable(tapeFindings(x0, plan)));
        const QStringList lines = QString::fromStdString(p.nc).split('\n');
        QCOMPARE(lines[fatal->line - 2], QString("M8 G0 X0"));  // the approach right after it
        QVERIFY(lines[fatal->line - 1].startsWith("G0 "));
        QCOMPARE(fatal->part, std::string("rapid"));

        p.nc = replaced(clean, "M8", "M8 G8");  // radius mode: X would be read as a radius
        verify::Report u;
        verify::readBack(u, plan, p, post::linuxcncDialect(), po);
        QCOMPARE(u.count(verify::FindingKind::UnreadTape), 1);
        QVERIFY(u.fatal());
        QCOMPARE(u.findings.back().line, lineHolding(p.nc, "M8 G8"));
        QVERIFY2(u.findings.back().part.find("G8 is not understood") != std::string::npos, u.findings.back().part.c_str());
    }

    // A cycle on the tape that is not the plan's (its contour, its depth of
    // cut, a thread's depth) is a fatal finding at its line: the control
    // would cut what the verification never saw.
    void aCycleUnlikeThePlansIsFatal_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::newRow("linuxcnc contour") << "lathe-turned-shaft.taiwa" << "linuxcnc" << "  G1 Z-35" << "  G1 Z-38";
        QTest::newRow("fanuc depth") << "lathe-turned-shaft.taiwa" << "fanuc" << "G71 U2. R0.5" << "G71 U3. R0.5";
        QTest::newRow("haas contour") << "lathe-bushing.taiwa" << "haas" << "G1 Z-20." << "G1 Z-22.";
        QTest::newRow("linuxcnc thread") << "lathe-threaded-shaft.taiwa" << "linuxcnc"
                                         << "G76 P2.5 Z-26.25 I-4 J0.97 R2 K3.067 Q29.5 H1"
                                         << "G76 P2.5 Z-26.25 I-4 J0.97 R2 K5.067 Q29.5 H1";
        QTest::newRow("fanuc thread") << "lathe-threaded-shaft.taiwa" << "fanuc" << "G76 X16.933 Z-26.25 P1534 Q485 F2.5"
                                      << "G76 X14.933 Z-26.25 P2534 Q485 F2.5";
    }
    void aCycleUnlikeThePlansIsFatal()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        QFETCH(QString, from);
        QFETCH(QString, to);
        const Plan plan = planOf(sample);
        const PostOptions po = postOptions(plan, dialect.toStdString());
        PostedProgram p = postProcess(plan.steps, plan.tools, po);
        const std::string bad = replaced(p.nc, from, to);
        QVERIFY2(bad != p.nc, qPrintable(from));
        p.nc = bad;
        verify::Report r;
        verify::readBack(r, plan, p, post::dialectNamed(po.dialect), po);
        const verify::Finding* first = firstUnplanned(r);
        QVERIFY2(first && r.count(verify::FindingKind::UnreadTape) == 0, qPrintable(tapeFindings(r, plan)));
        QCOMPARE(first->part, std::string("cycle"));
        const QString cycleWord = to.contains("G76") ? "G76" : "G71";
        QVERIFY2(QString::fromStdString(p.nc).split('\n')[first->line - 1].contains(cycleWord), qPrintable(tapeFindings(r, plan)));
        QVERIFY2(first->fatal(), qPrintable(tapeFindings(r, plan)));
    }

    // A shop's program end the loader lets through (M99: run again, as a
    // bar feeder's program does) cannot be read back: `taiwa verify` names
    // the line, `taiwa export` of the lathe job writes nothing.
    void exportRefusesALatheTapeItCannotReadBack()
    {
        QTemporaryDir home;
        // lathe-turned-shaft.taiwa posted in that dialect (`taiwa verify` takes the job's).
        const auto [job, env] = shopDialectJob(home, "looping", "\"programEnd\": \"M30\"", "\"programEnd\": \"M99\"",
                                               "lathe-turned-shaft.taiwa");
        QVERIFY(!job.isEmpty());

        const RunResult v = runTaiwa({"verify", job, "--json"}, env);
        QCOMPARE(v.exitCode, 3);
        const QJsonArray findings = QJsonDocument::fromJson(v.out.toUtf8()).object()["findings"].toArray();
        int unread = 0;
        for (const auto& f : findings) {
            const QJsonObject o = f.toObject();
            if (o["kind"].toString() != "unread-tape") continue;
            ++unread;
            QVERIFY(o["line"].toInt() > 0 && o["fatal"].toBool());
            QVERIFY2(o["part"].toString().contains("M99"), qPrintable(o["part"].toString()));
        }
        QVERIFY2(unread == 1, qPrintable(v.out + v.err));
        QTemporaryDir out;
        const RunResult e = runTaiwa({"export", job, "--no-pictures", "--out", out.path()}, env);
        QCOMPARE(e.exitCode, 3);
        QVERIFY2(e.err.contains("M99") && e.err.contains("cannot be read back"), qPrintable(e.err));
        QVERIFY(QDir(out.path()).entryList(QDir::Files).isEmpty());

        // Negative control: the shipped dialect's export writes its files.
        const RunResult ok =
            runTaiwa({"export", sourcePath("resources/samples/lathe-turned-shaft.taiwa"), "--no-pictures", "--out", out.path()}, env);
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.out + ok.err));
        QVERIFY(!QDir(out.path()).entryList(QDir::Files).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestTapeReadbackLathe)
#include "test_tape_readback_lathe.moc"
