// An export as a set that is never half-replaced (docs/command-line.md): a
// write that fails part-way (a file size limit the PDF exceeds) leaves the
// old set whole, says so and exits non-zero; a link planted where temporaries
// or the old fixed-name partial PDF go is never followed; 30 exports of two
// jobs into one folder at once leave one job's set; temporaries of a killed
// export are gone after the next one; no lock file is left in the folder.
#include "support/support.h"
#include "tools/tool_library.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <csignal>

using namespace taiwa::test;
using nlohmann::json;

namespace {

const QStringList kSuffixes{".nc", ".tape.txt", ".sheet.html", ".sheet.pdf", ".steps.json"};

// The files of set `stem` in `dir`, suffix -> bytes.
std::map<QString, std::string> setOf(const QString& dir, const QString& stem)
{
    std::map<QString, std::string> out;
    for (const QString& s : kSuffixes)
        if (QFile::exists(QDir(dir).filePath(stem + s))) out[s] = readFile(QDir(dir).filePath(stem + s));
    return out;
}

// Hidden leftovers of an export: temporaries, partial files, a journal,
// and any lock file (the lock lives in the user's runtime folder).
QStringList leftovers(const QString& dir)
{
    QStringList out;
    for (const QString& f : QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::System))
        if (f.contains(".tmp-") || f.endsWith(".partial") || f.endsWith(".lock") || f.endsWith(".set")) out << f;
    return out;
}

// A copy of a sample under another name (so that both export to one stem).
QString sampleAs(const QString& dir, const QString& sample, const QString& as)
{
    const QString path = QDir(dir).filePath(as);
    QDir().mkpath(QFileInfo(path).absolutePath());
    writeFile(path, readFile(sourcePath("resources/samples/" + sample)));
    return path;
}

// Verified on a coarse grid and without the sheet's pictures: both have
// tests of their own (test_verify, test_cli_verify).
QStringList exportArgs(const QString& job, const QString& out)
{
    return {"export", job, "--out", out, "--resolution", "0.25", "--no-pictures"};
}

}  // namespace

class TestExportSafety : public QObject {
    Q_OBJECT

private slots:
    void aWriteThatFailsLeavesTheOldSetWhole()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const QString job = sampleAs(dir.path(), "m2d-standard.taiwa", "a/part.taiwa");
        QCOMPARE(runTaiwa(exportArgs(job, out)).exitCode, 0);
        const auto before = setOf(out, "part");
        QCOMPARE(before.size(), std::size_t{5});

        // Another job into the same set, with a file size limit only its PDF
        // exceeds: the disk is "full" for the PDF alone, as on the 200 KB tmpfs.
        const QString other = sampleAs(dir.path(), "m4-standard.taiwa", "b/part.taiwa");
        QCOMPARE(runTaiwa(exportArgs(other, dir.filePath("sizes"))).exitCode, 0);
        const auto sizes = setOf(dir.filePath("sizes"), "part");
        std::size_t biggestText = 0;
        for (const auto& [suffix, bytes] : sizes)
            if (suffix != ".sheet.pdf") biggestText = std::max(biggestText, bytes.size());
        QVERIFY2(sizes.at(".sheet.pdf").size() > biggestText + 4096, "the PDF must be the largest file for this test");
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("TAIWA_TOOL_DB", testToolDb());
        p.setProcessEnvironment(env);
        p.start("prlimit", QStringList{"--fsize=" + QString::number(biggestText + 2048), taiwaBinary()} +
                               exportArgs(other, out));
        QVERIFY(p.waitForFinished(60000));
        const QString said = QString::fromUtf8(p.readAll());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(said.contains("part.sheet.pdf") && said.contains("nothing was changed"), qPrintable(said));
        QVERIFY2(!said.contains("wrote"), qPrintable(said));
        QVERIFY(setOf(out, "part") == before);  // the old set, whole
        QVERIFY2(leftovers(out).isEmpty(), qPrintable(leftovers(out).join(' ')));
    }

    void plantedLinksAreNeverFollowed()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        QDir().mkpath(out);
        const QString victim = dir.filePath("victim.txt");
        writeFile(victim, "precious\n");
        // Where earlier versions wrote the PDF, and where a temporary of this
        // process would go if names were predictable.
        QVERIFY(QFile::link(victim, QDir(out).filePath("job.sheet.pdf.partial")));
        for (int pid = 1; pid < 64; ++pid)
            for (int n = 1; n < 4; ++n)
                QFile::link(victim, QDir(out).filePath(QString(".job.nc.tmp-%1-%2").arg(pid).arg(n)));
        const QString job = sampleAs(dir.path(), "m4-standard.taiwa", "job.taiwa");
        const auto r = runTaiwa(exportArgs(job, out));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(readFile(victim), std::string("precious\n"));
        QCOMPARE(setOf(out, "job").size(), std::size_t{5});
        QVERIFY(readFile(QDir(out).filePath("job.sheet.pdf")).starts_with("%PDF"));
    }

    void concurrentExportsOfOneStemLeaveOneJobsSet()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const QString a = sampleAs(dir.path(), "m4-standard.taiwa", "a/part.taiwa");
        const QString b = sampleAs(dir.path(), "m2d-standard.taiwa", "b/part.taiwa");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("TAIWA_TOOL_DB", testToolDb());
        for (int round = 0; round < 15; ++round) {  // 30 exports, two at a time
            QProcess pa, pb;
            for (QProcess* p : {&pa, &pb}) p->setProcessEnvironment(env);
            pa.start(taiwaBinary(), exportArgs(a, out));
            pb.start(taiwaBinary(), exportArgs(b, out));
            QVERIFY(pa.waitForFinished(60000) && pb.waitForFinished(60000));
            QCOMPARE(pa.exitCode(), 0);
            QCOMPARE(pb.exitCode(), 0);
            const auto set = setOf(out, "part");
            QCOMPARE(set.size(), std::size_t{5});
            // One job's set: the tape, the sheet and the steps all name the same job.
            const std::string nameA = "Cover plate: standard pocket", nameB = "Chute: both end walls at 10 degrees";
            const bool isA = set.at(".nc").starts_with("(Program " + nameA + ")");
            QVERIFY(isA || set.at(".nc").starts_with("(Program " + nameB + ")"));
            const std::string& mine = isA ? nameA : nameB;
            const std::string& theirs = isA ? nameB : nameA;
            for (const char* s : {".sheet.html", ".steps.json", ".tape.txt"}) {
                QVERIFY2(set.at(s).find(mine) != std::string::npos, s);
                QVERIFY2(set.at(s).find(theirs) == std::string::npos, s);
            }
            QVERIFY(set.at(".sheet.pdf").starts_with("%PDF"));
            QVERIFY(set.at(".sheet.pdf").find("%%EOF") != std::string::npos);
        }
        QVERIFY2(leftovers(out).isEmpty(), qPrintable(leftovers(out).join(' ')));
        // The folder holds the set and nothing else.
        QCOMPARE(QDir(out).entryList(QDir::Files | QDir::Hidden | QDir::System).size(), qsizetype{5});
    }

    void controlCharactersAndPercentStayInert()
    {
        // Text from the job reaches terminals, tapes and documents: a newline
        // must not forge a message line, an ESC must not reach the terminal, a
        // '%' must not end a FANUC tape inside its comments, a ')' must not
        // end a comment, NUL/ESC must not reach the tape image or the sheet.
        QTemporaryDir dir;
        json job = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        job["name"] = std::string("Plate %1 (rev\x1b[31mB)\nJOB: unit 9 (M4) depth: forged") + '\0' + "end";
        job["units"][0]["name"] = "Pocket\x1b]0;title\x07 %";
        const QString file = dir.filePath("ctl.taiwa");
        writeFile(file, job.dump());
        // A tool named with the same characters, in a library of this test's own.
        const QString db = dir.filePath("tools.sqlite");
        {
            auto lib = taiwa::ToolLibrary::open(db.toStdString());
            QVERIFY(lib);
            auto tools = lib->tools();
            QVERIFY(tools);
            for (taiwa::Tool t : *tools) {
                t.name += " %) \x1b[0m";
                QVERIFY(lib->save(t));
            }
        }
        const QStringList env{"TAIWA_TOOL_DB=" + db};
        const QString out = dir.filePath("out");
        for (const char* dialect : {"fanuc", "linuxcnc"}) {
            const auto r = runTaiwa({"export", file, "--out", out, "--dialect", dialect, "--resolution", "0.25", "--no-pictures"}, env);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const std::string nc = readFile(QDir(out).filePath("ctl.nc"));
            std::size_t percents = 0, from = 0;
            while ((from = nc.find('%', from)) != std::string::npos) ++percents, ++from;
            QCOMPARE(percents, std::string(dialect) == "fanuc" ? std::size_t{2} : std::size_t{0});  // leader and trailer only
            for (const QString& line : QString::fromStdString(nc).split('\n')) {
                const auto open = line.indexOf('(');
                if (open < 0) continue;
                QVERIFY2(line.indexOf('(', open + 1) < 0 && line.indexOf(')') == line.size() - 1, qPrintable(line));
            }
            for (const char* s : {"ctl.nc", "ctl.tape.txt", "ctl.sheet.html", "ctl.steps.json"}) {
                const std::string text = readFile(QDir(out).filePath(s));
                QVERIFY2(text.find('\x1b') == std::string::npos && text.find('\0') == std::string::npos, s);
            }
        }
        // The messages of check: one line per diagnostic, no escape reaching the terminal.
        job["material"] = "alu\nJOB: unit 9 (M4) depth: forged\x1b[2J";
        writeFile(file, job.dump());
        const auto r = runTaiwa({"check", file}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(!r.err.contains(QChar(0x1b)), qPrintable(r.err));
        const QStringList lines = r.err.trimmed().split('\n');
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines.front().startsWith("ctl.taiwa: job material:") && lines.front().contains("alu\\nJOB"),
                 qPrintable(lines.front()));
    }

    void temporariesOfAKilledExportAreRemovedByTheNext()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const QString job = sampleAs(dir.path(), "plate.taiwa", "plate.taiwa");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("TAIWA_TOOL_DB", testToolDb());
        bool sawLeftover = false;
        for (int i = 0; i < 12; ++i) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(taiwaBinary(), exportArgs(job, out));
            QVERIFY(p.waitForStarted());
            QTest::qSleep(40 + 15 * i);  // into planning, painting, writing
            ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
            p.waitForFinished();
            sawLeftover |= !leftovers(out).isEmpty();
        }
        // A leftover planted as a dead writer's, in case no kill landed mid-write.
        QDir().mkpath(out);
        writeFile(QDir(out).filePath(".plate.nc.tmp-999999-1"), "half a tape");
        writeFile(QDir(out).filePath("plate.sheet.pdf.partial"), "half a PDF");
        const auto r = runTaiwa(exportArgs(job, out));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(leftovers(out).isEmpty(), qPrintable(leftovers(out).join(' ')));
        QCOMPARE(setOf(out, "plate").size(), std::size_t{5});
        qDebug("a kill left temporaries at least once: %s", sawLeftover ? "yes" : "no");
    }
};

QTEST_GUILESS_MAIN(TestExportSafety)
#include "test_export_safety.moc"
