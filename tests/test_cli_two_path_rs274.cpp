// `taiwa export` and `taiwa verify` of a job on a two-path lathe, run as real
// processes (docs/two-path-lathe.md "The export"): the export writes
// STEM.p1.nc and STEM.p2.nc (no STEM.nc), the tape image lists both, and
// for LinuxCNC each path's tool table, both programs passing rs274 in lathe
// mode with their table; FANUC's pair carries the same wait codes on both
// paths, the dwells on path 2, and the sheet covers both paths; verify runs
// the timeline and reports it clean. The job's two-path settings (a
// version 6 job: two revolutions, waits everywhere) reach both programs,
// which still pass rs274, and verify; a dwell below half a revolution is
// refused at its field. A job on the gang-tool lathe exports one tape
// whose tool changes are the gang change (Z clear before each T word, X
// after it), passing rs274 with its table.
// Holds the rs274 lock (its name says rs274: tests/CMakeLists.txt).
#include "support/rs274.h"
#include "support/support.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace taiwa;
using namespace taiwa::test;
using nlohmann::json;

namespace {

QString sample(const QString& stem) { return sourcePath("resources/samples/" + stem + ".taiwa"); }

int count(const std::string& text, const QString& pattern)
{
    return static_cast<int>(QString::fromStdString(text).count(QRegularExpression(pattern, QRegularExpression::MultilineOption)));
}

}  // namespace

class TestCliTwoPathRs274 : public QObject {
    Q_OBJECT
private slots:
    void exportWritesBothPathsForLinuxcnc_data()
    {
        QTest::addColumn<QString>("stem");
        QTest::newRow("cylinder") << "lathe-two-path-cylinder";
        QTest::newRow("taper") << "lathe-two-path-taper";
    }
    void exportWritesBothPathsForLinuxcnc()
    {
        QFETCH(QString, stem);
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const auto r = runTaiwa({"export", sample(stem), "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QDir d(out);
        QVERIFY2(!QFileInfo::exists(d.filePath(stem + ".nc")), "a two-path job has no single tape");
        QVERIFY(!QFileInfo::exists(d.filePath(stem + ".tbl")));
        const std::string image = readFile(d.filePath(stem + ".tape.txt"));
        for (int p = 1; p <= 2; ++p) {
            const QString nc = d.filePath(QString("%1.p%2.nc").arg(stem).arg(p));
            const QString tbl = d.filePath(QString("%1.p%2.tbl").arg(stem).arg(p));
            QVERIFY2(QFileInfo::exists(nc) && QFileInfo::exists(tbl), qPrintable(r.out));
            const std::string program = readFile(nc);
            QVERIFY(QString::fromStdString(program).startsWith(QString("(Program Path %1 ").arg(p)));
            const Rs274Result run = runRs274(program, readFile(tbl));
            QVERIFY2(run.ok, qPrintable(QString("path %1: %2").arg(p).arg(run.errors)));
            QVERIFY(run.moves.size() > 10);
            if (p == 2) QVERIFY(run.dwells > 0);  // the follower's dwells
            // Meeting before the first cut and after the last at least.
            QVERIFY(count(program, R"(^M66 P0 L[34] Q60$)") >= 2);
            QVERIFY2(image.find(QString("==== %1.p%2.nc ====").arg(stem).arg(p).toStdString()) != std::string::npos,
                     image.substr(0, 400).c_str());
        }
        // The same number of handshakes on both paths.
        QCOMPARE(count(readFile(d.filePath(stem + ".p1.nc")), R"(^M66 P0)"), count(readFile(d.filePath(stem + ".p2.nc")), R"(^M66 P0)"));
    }

    void exportWritesFanucPair()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const auto r = runTaiwa({"export", sample("lathe-two-path-taper"), "--out", out, "--dialect", "fanuc"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QDir d(out);
        const std::string p1 = readFile(d.filePath("lathe-two-path-taper.p1.nc")), p2 = readFile(d.filePath("lathe-two-path-taper.p2.nc"));
        QVERIFY(!QFileInfo::exists(d.filePath("lathe-two-path-taper.p1.tbl")));
        QVERIFY(count(p1, "^M1[0-9][0-9]$") > 2);
        QCOMPARE(count(p1, "^M1[0-9][0-9]$"), count(p2, "^M1[0-9][0-9]$"));
        QVERIFY(count(p2, R"(^G04 X\d)") > 0);
        QCOMPARE(count(p1, R"(^G04 X\d)"), 0);
        // One sheet for both paths: each step's path, the roughing's timeline.
        const std::string html = readFile(d.filePath("lathe-two-path-taper.sheet.html"));
        QVERIFY(html.find("<h2>Paths</h2>") != std::string::npos);
        QVERIFY(html.find("<h2>Balanced roughing on the timeline</h2>") != std::string::npos);
        QVERIFY2(html.find("M101 met") != std::string::npos || html.find("M101 wait") != std::string::npos, "the first wait marked");
    }

    void jobSettingsReachTheExportAndVerify()
    {
        QTemporaryDir dir;
        json job = json::parse(readFile(sample("lathe-two-path-cylinder")));
        const auto handshakes = [&](const json& j, const QString& name) {
            const QString file = dir.filePath(name + ".taiwa");
            writeFile(file, j.dump(2));
            const auto r = runTaiwa({"export", file, "--out", dir.filePath(name)});
            if (r.exitCode != 0) qWarning("%s", qPrintable(r.err));
            std::vector<int> out;
            for (int p = 1; p <= 2; ++p) {
                const std::string program = readFile(dir.filePath(QString("%1/%1.p%2.nc").arg(name).arg(p)));
                const Rs274Result run = runRs274(program, readFile(dir.filePath(QString("%1/%1.p%2.tbl").arg(name).arg(p))));
                if (!run.ok) qWarning("%s", qPrintable(run.errors));
                out.push_back(run.ok ? count(program, R"(^M66 P0)") : -1);
            }
            return out;
        };
        const std::vector<int> plain = handshakes(job, "plain");
        job["version"] = 6;
        job["twoPath"] = {{"dwellRevolutions", 2}, {"waitsEverywhere", true}};
        const std::vector<int> everywhere = handshakes(job, "everywhere");
        qInfo("handshakes per path: %d by default, %d with waits everywhere", plain[0], everywhere[0]);
        QVERIFY(plain[0] >= 2 && plain[0] == plain[1]);
        QVERIFY(everywhere[0] > plain[0] && everywhere[0] == everywhere[1]);  // a cylinder waits only at the ends unless asked
        const auto v = runTaiwa({"verify", dir.filePath("everywhere.taiwa"), "--json"});
        QCOMPARE(v.exitCode, 0);
        QVERIFY(json::parse(v.out.toStdString())["twoPath"]["leastLag"].get<double>() >= 2.0 - 1e-6);
        job["twoPath"]["dwellRevolutions"] = 0.4;
        writeFile(dir.filePath("slow.taiwa"), job.dump(2));
        const auto r = runTaiwa({"check", dir.filePath("slow.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("twoPath.dwellRevolutions: the follower's dwell is 0.4 spindle revolutions"), qPrintable(r.err));
    }

    void gangToolExportPassesRs274()
    {
        QTemporaryDir dir;
        const auto r = runTaiwa({"export", dataPath("gang/lathe-gang-shaft.taiwa"), "--out", dir.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const std::string nc = readFile(dir.filePath("lathe-gang-shaft.nc"));
        // Each of the three tool calls after a Z clear, and followed by X with Z held.
        QCOMPARE(count(nc, R"(^G0 Z[0-9.]+\nT\d M6 G43\nG0 X[0-9.]+ Z[0-9.]+$)"), 3);
        const Rs274Result run = runRs274(nc, readFile(dir.filePath("lathe-gang-shaft.tbl")));
        QVERIFY2(run.ok, qPrintable(run.errors));
        QVERIFY(run.moves.size() > 20);
    }

    void verifyRunsTheTimeline()
    {
        for (const QString stem : {"lathe-two-path-cylinder", "lathe-two-path-taper"}) {
            const auto r = runTaiwa({"verify", sample(stem)});
            QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
            QVERIFY2(r.out.contains("two-path timeline: 0 findings"), qPrintable(r.out));
            const auto j = runTaiwa({"verify", sample(stem), "--json"});
            QCOMPARE(j.exitCode, 0);
            const json doc = json::parse(j.out.toStdString());
            QVERIFY(doc["twoPath"]["findings"].empty());
            QVERIFY(doc["twoPath"]["leastLag"].get<double>() >= 1.0 - 1e-6);
            QVERIFY(doc["twoPath"]["seconds"].get<double>() > 0);
        }
        // A one-path lathe job has no timeline.
        const auto one = runTaiwa({"verify", sourcePath("resources/samples/lathe-turned-shaft.taiwa")});
        QVERIFY(!one.out.contains("two-path timeline"));
    }
};

QTEST_APPLESS_MAIN(TestCliTwoPathRs274)
#include "test_cli_two_path_rs274.moc"
