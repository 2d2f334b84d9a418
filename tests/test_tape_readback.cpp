// The posted tape read back against the plan (verify/tape_readback.h):
// every shipped milling sample's tape, in every dialect, reads back with no
// finding; a dialect word that moves (the loader refuses it now, so it is
// built in memory here, as a shop file that got past an older loader would
// be) is a finding at its tape line, fatal when it goes into stock; a word
// the loader still lets through (a retract) makes `taiwa verify` report it
// and `taiwa export` refuse the tape (nothing written); a tape the reader cannot follow is a
// fatal finding at its line. Lathe tapes are read back by their own
// reader: tests/test_tape_readback_lathe.cpp.
#include "support/readback.h"
#include "support/support.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "tools/tool_library.h"
#include "verify/tape_readback.h"
#include "verify/tape_reader.h"
#include "verify/verify.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace taiwa;
using namespace taiwa::test;

namespace {


// The tape `hostile` writes for the plan: the linuxcnc tape with its
// coolantOn word in place of "M8" (the writer writes the word as a block
// of its own, post/gcode_writer.cpp coolant()).
std::string withCoolantWord(const std::string& tape, const std::string& word)
{
    std::string out;
    std::size_t from = 0;
    while (from < tape.size()) {
        std::size_t end = tape.find('\n', from);
        if (end == std::string::npos) end = tape.size();
        const std::string line = tape.substr(from, end - from);
        out += (line == "M8" ? word : line) + "\n";
        from = end + 1;
    }
    return out;
}

int lineHolding(const std::string& tape, const std::string& text)
{
    const QStringList lines = QString::fromStdString(tape).split('\n');
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].contains(QString::fromStdString(text))) return i + 1;
    return 0;
}

}  // namespace

class TestTapeReadback : public QObject {
    Q_OBJECT

private slots:
    void everySampleReadsBackInEveryDialect_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        const QStringList samples = QDir(sourcePath("resources/samples")).entryList({"*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(samples.size() > 20);
        for (const QString& s : samples) {
            if (s.startsWith("lathe-")) continue;  // test_tape_readback_lathe.cpp
            for (const QString& d : shippedDialectsWriting(DialectWrites::MillingTapes))
                QTest::newRow(qPrintable(s + " " + d)) << s << d;
        }
    }
    void everySampleReadsBackInEveryDialect()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        const Plan plan = planOf(sample);
        QVERIFY2(plan.ok(), qPrintable(sample));
        if (plan.steps.empty()) QSKIP("probing only: no milling tape");
        QVERIFY(!plan.mmJob.bar);
        for (const auto units : {LengthUnit::Millimetre, LengthUnit::Inch}) {
            const PostOptions po = postOptions(plan, dialect.toStdString(), units);
            PostedProgram posted;
            try {
                posted = postProcess(plan.steps, plan.tools, po);
            } catch (const Refusal& r) {
                QSKIP(qPrintable(dialect + " does not post " + sample + ": " + r.what()));
            }
            // Every motion read; some motion there is.
            const auto reading = verify::readTape(posted.nc, post::dialectNamed(po.dialect));
            QVERIFY2(reading.error.empty(), reading.error.c_str());
            QVERIFY(reading.motions.size() > 2);
            verify::Report r;  // no height field: the stock block judges depth
            verify::readBack(r, plan, posted, post::dialectNamed(po.dialect), po);
            const QString found = tapeFindings(r, plan);
            QVERIFY2(found.isEmpty(), qPrintable(found));
        }
    }

    // A word that moves: the loader refuses it, so the dialect is built in
    // memory; its tape read back has the rapid into the part at the line
    // that writes it, a fatal finding.
    void aCoolantWordThatMovesIsFoundAtItsLine()
    {
        const std::string word = "M8 G0 Z-100";
        std::string file = readFile(sourcePath("resources/dialects/linuxcnc.json"));
        const auto coolant = file.find("\"coolantOn\": \"M8\"");
        QVERIFY(coolant != std::string::npos);
        file.replace(coolant, 17, "\"coolantOn\": \"" + word + "\"");
        const auto loaded = post::readDialect(file, "evil.json");
        QVERIFY(!loaded);  // the loader's own refusal (why the dialect is built here)
        QVERIFY2(QString::fromStdString(loaded.error()).contains("must be M words only"), loaded.error().c_str());
        post::Dialect hostile = post::linuxcncDialect();
        hostile.coolantOn = word;

        const Plan plan = planOf("m4-standard.taiwa");
        QVERIFY(plan.ok());
        const PostOptions po = postOptions(plan, "linuxcnc");
        const PostedProgram clean = postProcess(plan.steps, plan.tools, po);
        verify::Options o;
        o.resolution = 0.5;
        const verify::Report plain = verify::verifyPlan(plan, o);
        QVERIFY(!plain.fatal());

        // Negative control: the linuxcnc tape itself.
        verify::Report good = plain;
        verify::readBack(good, plan, clean, post::linuxcncDialect(), po);
        QCOMPARE(tapeFindings(good, plan), QString());

        PostedProgram bad = clean;
        bad.nc = withCoolantWord(clean.nc, word);
        QVERIFY(bad.nc != clean.nc);
        const int line = lineHolding(bad.nc, word);
        QVERIFY(line > 0);
        verify::Report r = plain;
        verify::readBack(r, plan, bad, hostile, po);
        QVERIFY(r.fatal());
        const verify::Finding* first = nullptr;
        for (const auto& f : r.findings)
            if (f.kind == verify::FindingKind::UnplannedMove && !first) first = &f;
        QVERIFY2(first, qPrintable(tapeFindings(r, plan)));
        QCOMPARE(first->line, line);
        QCOMPARE(first->part, std::string("rapid"));
        QCOMPARE(first->position.z, -100.0);
        QVERIFY(first->size > 5.0);  // into the pocket's floor and through the block
        QVERIFY(first->fatal());
        const QString words = QString::fromStdString(verify::describe(*first, plan));
        QVERIFY2(words.contains(QString("tape line %1").arg(line)) && words.contains("into stock"), qPrintable(words));
    }

    // A move that stays clear of the stock is reported, not fatal; a line
    // the reader cannot follow is fatal and named.
    void aHarmlessMoveIsReportedAndAnUnreadLineIsFatal()
    {
        const Plan plan = planOf("m4-standard.taiwa");
        const PostOptions po = postOptions(plan, "linuxcnc");
        PostedProgram p = postProcess(plan.steps, plan.tools, po);
        p.nc = withCoolantWord(p.nc, "M8 G0 Z50");
        verify::Report r;
        verify::readBack(r, plan, p, post::linuxcncDialect(), po);
        QVERIFY(r.count(verify::FindingKind::UnplannedMove) > 0);
        QVERIFY2(!r.fatal(), qPrintable(tapeFindings(r, plan)));

        PostedProgram q = postProcess(plan.steps, plan.tools, po);
        q.nc = withCoolantWord(q.nc, "M8 G18");
        verify::Report u;
        verify::readBack(u, plan, q, post::linuxcncDialect(), po);
        QCOMPARE(u.count(verify::FindingKind::UnreadTape), 1);
        QVERIFY(u.fatal());
        QCOMPARE(u.findings.back().line, lineHolding(q.nc, "M8 G18"));
        QVERIFY(u.findings.back().part.find("G18 is not understood") != std::string::npos);
    }

    // A shop's retract word the loader lets through goes 50 mm down: `taiwa
    // verify` names its tape line, `taiwa export` writes nothing.
    void exportRefusesATapeWhoseWordGoesIntoStock()
    {
        QTemporaryDir home;
        // m4-standard.taiwa posted in that dialect (`taiwa verify` takes the job's).
        const auto [job, env] = shopDialectJob(home, "sinking", "\"retract\": [\"G53 G0 Z0\"]",
                                               "\"retract\": [\"G53 G0 Z0\", \"G0 Z-50\"]", "m4-standard.taiwa");
        QVERIFY(!job.isEmpty());

        const RunResult v = runTaiwa({"verify", job, "--resolution", "1", "--json"}, env);
        QCOMPARE(v.exitCode, 3);
        const QJsonArray findings = QJsonDocument::fromJson(v.out.toUtf8()).object()["findings"].toArray();
        int unplanned = 0;
        for (const auto& f : findings) {
            const QJsonObject o = f.toObject();
            if (o["kind"].toString() != "unplanned-move") continue;
            ++unplanned;
            QVERIFY(o["line"].toInt() > 0);
            QVERIFY2(o["message"].toString().contains("into stock"), qPrintable(o["message"].toString()));
        }
        QVERIFY2(unplanned >= 2, qPrintable(v.out + v.err));  // at the first tool change and at the end

        QTemporaryDir out;
        const RunResult e = runTaiwa({"export", job, "--resolution", "1", "--no-pictures", "--out", out.path()}, env);
        QCOMPARE(e.exitCode, 3);
        QVERIFY2(e.err.contains("tape line") && e.err.contains("the plan does not"), qPrintable(e.err));
        QVERIFY(QDir(out.path()).entryList(QDir::Files).isEmpty());

        // Negative control: the shipped linuxcnc dialect's tape verifies clean.
        const RunResult ok = runTaiwa({"verify", sourcePath("resources/samples/m4-standard.taiwa"), "--resolution", "1"}, env);
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.out + ok.err));
        QVERIFY2(ok.out.contains(", 0 on the tape read back"), qPrintable(ok.out));
    }
};

QTEST_GUILESS_MAIN(TestTapeReadback)
#include "test_tape_readback.moc"
