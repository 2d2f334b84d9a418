// One verification per export (export/verification_cache.h): `taiwa export`
// after `taiwa verify` of the same job, plan and resolution reuses the
// stored report and says so; another resolution, an edit of the job or
// --no-cache verify again; the findings of a reused report are placed on
// the tape as a fresh one's are; a damaged or foreign cache file is a miss
// that is written anew; the folder keeps the newest kCachedVerifications;
// the stored report reads back as it was written.
#include "export/verification_cache.h"
#include "support/support.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <filesystem>

using namespace taiwa;
using namespace taiwa::test;
using nlohmann::json;

namespace {

const QString kReused = QStringLiteral("of this job and plan was reused");

QStringList cacheFiles(const QString& folder) { return QDir(folder).entryList({"*.json"}, QDir::Files); }

// The lines of `text` that name a finding ("… step 3 …" or "the job: …"), in order.
QStringList findingLines(const QString& text, const QString& name)
{
    QStringList lines;
    for (const auto& l : text.split('\n'))
        if (l.startsWith(name + ": ") && !l.contains("verified at")) lines << l;
    return lines;
}

}  // namespace

class TestCliVerifyCache : public QObject {
    Q_OBJECT
private slots:
    void exportReusesTheVerification()
    {
        QTemporaryDir dir;
        const QString cache = dir.filePath("cache");
        const QStringList env{"TAIWA_CACHE_DIR=" + cache};
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const auto v = runTaiwa({"verify", job, "--resolution", "0.25"}, env);
        QCOMPARE(v.exitCode, 0);
        QCOMPARE(cacheFiles(cache).size(), 1);
        const auto e = runTaiwa({"export", job, "--out", dir.filePath("a"), "--resolution", "0.25", "--no-pictures"}, env);
        QCOMPARE(e.exitCode, 0);
        QVERIFY2(e.out.contains("taiwa: the verification at 0.25 mm " + kReused), qPrintable(e.out));
        // A second verify reuses it too, and prints what the first printed.
        QCOMPARE(runTaiwa({"verify", job, "--resolution", "0.25"}, env).out, v.out);
        // --no-cache verifies afresh; another cell size is another report.
        const auto fresh =
            runTaiwa({"export", job, "--out", dir.filePath("b"), "--resolution", "0.25", "--no-pictures", "--no-cache"}, env);
        QCOMPARE(fresh.exitCode, 0);
        QVERIFY2(!fresh.out.contains(kReused), qPrintable(fresh.out));
        const auto coarser = runTaiwa({"export", job, "--out", dir.filePath("c"), "--resolution", "0.5", "--no-pictures"}, env);
        QCOMPARE(coarser.exitCode, 0);
        QVERIFY2(!coarser.out.contains(kReused), qPrintable(coarser.out));
        QCOMPARE(cacheFiles(cache).size(), 2);
        // The tapes are the same whichever way the verification came.
        QCOMPARE(readFile(QDir(dir.filePath("a")).filePath("m4-standard.nc")),
                 readFile(QDir(dir.filePath("b")).filePath("m4-standard.nc")));
        QCOMPARE(runTaiwa({"check", job, "--no-cache"}).exitCode, 2);  // not an option of check
    }

    void anEditIsAnotherKey()
    {
        QTemporaryDir dir;
        const QStringList env{"TAIWA_CACHE_DIR=" + dir.filePath("cache")};
        json doc = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        const QString job = dir.filePath("m4.taiwa");
        writeFile(job, doc.dump(2));
        QCOMPARE(runTaiwa({"verify", job, "--resolution", "0.25"}, env).exitCode, 0);
        doc["units"][0]["depth"] = doc["units"][0]["depth"].get<double>() + 1.0;
        writeFile(job, doc.dump(2));
        const auto e = runTaiwa({"export", job, "--out", dir.filePath("out"), "--resolution", "0.25", "--no-pictures"}, env);
        QCOMPARE(e.exitCode, 0);
        QVERIFY2(!e.out.contains(kReused), qPrintable(e.out));
        QCOMPARE(cacheFiles(dir.filePath("cache")).size(), 2);
    }

    // A reused report's findings are the verify's, placed on the export's
    // tape at the same lines; the refusal is the same.
    void findingsReusedOnTheTape()
    {
        QTemporaryDir dir;
        const QStringList env{"TAIWA_CACHE_DIR=" + dir.filePath("cache")};
        const QString job = writeWideJob(dir.path());
        const auto v = runTaiwa({"verify", job, "--resolution", "0.2"}, env);
        QCOMPARE(v.exitCode, 3);
        const QStringList found = findingLines(v.out, "wide.taiwa");
        QVERIFY2(!found.isEmpty() && found.join('\n').contains("more along x"), qPrintable(v.out));
        const auto e = runTaiwa({"export", job, "--out", dir.filePath("out"), "--resolution", "0.2"}, env);
        QCOMPARE(e.exitCode, 3);
        QVERIFY2(e.out.contains(kReused), qPrintable(e.out));
        QCOMPARE(findingLines(e.err, "wide.taiwa"), found);
        const auto fresh = runTaiwa({"export", job, "--out", dir.filePath("out"), "--resolution", "0.2", "--no-cache"}, env);
        QCOMPARE(findingLines(fresh.err, "wide.taiwa"), found);
    }

    void damagedFilesAreMisses()
    {
        QTemporaryDir dir;
        const QString cache = dir.filePath("cache");
        const QStringList env{"TAIWA_CACHE_DIR=" + cache};
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const auto first = runTaiwa({"verify", job, "--resolution", "0.25", "--json"}, env);
        QCOMPARE(first.exitCode, 0);
        const QString file = QDir(cache).filePath(cacheFiles(cache).value(0));
        const std::string good = readFile(file);
        for (const std::string& bad : {std::string("{\"format\": \"taiwa verification cache 0\"}"), std::string("\x00\xff garbage", 10),
                                      good.substr(0, good.size() / 2),
                                      std::string(R"({"format":"taiwa verification cache 2","resolution":0.25,"columns":1,)"
                                                  R"("rows":1,"removed":[],"cellVisits":0,"skipped":"","coarsened":"",)"
                                                  R"("findings":[{"kind":99,"step":0,"move":0,"position":[0,0,0],)"
                                                  R"("size":1,"area":0,"part":""}]})")}) {
            writeFile(file, bad);
            const auto again = runTaiwa({"verify", job, "--resolution", "0.25", "--json"}, env);
            QCOMPARE(again.exitCode, 0);
            QCOMPARE(again.out, first.out);
            QVERIFY(json::parse(readFile(file))["format"] == "taiwa verification cache 2");  // written anew
        }
    }

    void storedReportReadsBack()
    {
        QTemporaryDir dir;
        qputenv("TAIWA_CACHE_DIR", dir.filePath("cache").toUtf8());
        verify::Report r;
        r.resolution = 0.05;
        r.columns = 4000;
        r.rows = 3000;
        r.removed = {1.0 / 3.0, 12345.678};
        r.cellVisits = 9.5e6;
        r.coarsened = "verified at 0.1 mm, not 0.05 mm";
        verify::Finding g;
        g.kind = verify::FindingKind::Collision;
        g.step = 2;
        g.move = 57;
        g.line = 312;
        g.position = {12.3 + 1e-12, -4.1, 0.1 + 0.2};
        g.size = 0.52;
        g.area = 1.75;
        g.part = "holder";
        r.findings = {g, verify::Finding{}};
        const std::string key(64, 'a');
        QVERIFY(storeVerification(key, r));
        const auto back = loadVerification(key);
        QVERIFY(back.has_value());
        g.line = 0;  // placed again on the tape of the export
        QCOMPARE(back->findings, (std::vector<verify::Finding>{g, verify::Finding{}}));
        QCOMPARE(back->removed, r.removed);
        QCOMPARE(back->resolution, r.resolution);
        QCOMPARE(back->columns, r.columns);
        QCOMPARE(back->rows, r.rows);
        QCOMPARE(back->cellVisits, r.cellVisits);
        QCOMPARE(back->coarsened, r.coarsened);
        // No key names a file outside the folder.
        QVERIFY(!storeVerification("../escape", r));
        QVERIFY(!loadVerification("../" + key).has_value());
        QVERIFY(!loadVerification(std::string(64, 'b')).has_value());
    }

    void theFolderKeepsTheNewest()
    {
        QTemporaryDir dir;
        const QString cache = dir.filePath("cache");
        qputenv("TAIWA_CACHE_DIR", cache.toUtf8());
        QDir().mkpath(cache);
        const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
        for (int i = 0; i < kCachedVerifications + 10; ++i) {
            const QString f = QDir(cache).filePath(QString("%1.json").arg(i, 64, 16, QChar('0')));
            writeFile(f, "{}");
            std::filesystem::last_write_time(f.toStdString(), old + std::chrono::seconds(i));
        }
        QVERIFY(storeVerification(std::string(64, 'f'), verify::Report{}));
        const QStringList left = cacheFiles(cache);
        QCOMPARE(left.size(), kCachedVerifications);
        QVERIFY(left.contains(QString(64, 'f') + ".json"));
        QVERIFY(!left.contains(QString("%1.json").arg(0, 64, 16, QChar('0'))));  // the oldest went first
    }
};

QTEST_GUILESS_MAIN(TestCliVerifyCache)
#include "test_cli_verify_cache.moc"
