// `taiwa verify` and the verification in `taiwa export`, run as real
// processes: a clean sample (words and JSON), a job beyond the machine's
// travel (exit 3, the export refused with nothing written, written with
// --force and the faults red on the sheet), options refused, a lathe job
// verified clean.
#include "support/support.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace taiwa::test;
using nlohmann::json;

namespace {

// m4-standard.taiwa with a second pocket 850 mm along X on a 1,000 mm
// plate: its paths span more than the vmc's 800 mm of X travel.
QString writeWideJob(const QTemporaryDir& dir)
{
    json job = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
    job["stock"]["width"] = 1000;
    json far = job["units"][0];
    far["name"] = "far";
    for (auto& c : far["corners"]) c[0] = c[0].get<double>() + 850;
    job["units"].push_back(far);
    const QString path = dir.filePath("wide.taiwa");
    writeFile(path, job.dump(2));
    return path;
}

}  // namespace

class TestCliVerify : public QObject {
    Q_OBJECT
private slots:
    void cleanSampleInWordsAndJson()
    {
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const auto r = runTaiwa({"verify", job});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("m4-standard.taiwa: verified at 0.05 mm") && r.out.contains("0 gouges, 0 collisions"),
                 qPrintable(r.out));
        const auto j = runTaiwa({"verify", job, "--json", "--resolution", "0.1"});
        QCOMPARE(j.exitCode, 0);
        const json doc = json::parse(j.out.toStdString());
        QCOMPARE(doc["resolution"].get<double>(), 0.1);
        QVERIFY(doc["findings"].empty());
        QCOMPARE(doc["fatal"].get<bool>(), false);
        QVERIFY(doc["grid"][0].get<int>() > 1000);
    }

    void travelLimitStopsTheExport()
    {
        QTemporaryDir dir;
        const QString job = writeWideJob(dir);
        const auto v = runTaiwa({"verify", job, "--resolution", "0.2"});
        QCOMPARE(v.exitCode, 3);
        QVERIFY2(v.out.contains("more along x than the machine 'vmc' travels"), qPrintable(v.out));
        const auto j = runTaiwa({"verify", job, "--resolution", "0.2", "--json"});
        QCOMPARE(j.exitCode, 3);
        const json doc = json::parse(j.out.toStdString());
        QCOMPARE(doc["findings"].size(), std::size_t{1});
        QCOMPARE(doc["findings"][0]["kind"].get<std::string>(), std::string("travel-limit"));
        QCOMPARE(doc["fatal"].get<bool>(), true);

        const QString out = dir.filePath("out");
        const auto e = runTaiwa({"export", job, "--out", out, "--resolution", "0.2"});
        QCOMPARE(e.exitCode, 3);
        QVERIFY2(e.err.contains("nothing was written"), qPrintable(e.err));
        QVERIFY(!QFileInfo::exists(out) || QDir(out).isEmpty());

        const auto f = runTaiwa({"export", job, "--out", out, "--resolution", "0.2", "--force"});
        QCOMPARE(f.exitCode, 0);
        const std::string sheet = readFile(QDir(out).filePath("wide.sheet.html"));
        QVERIFY(sheet.find("<ul class=\"fault\"><li>the job: the paths span") != std::string::npos);
        QVERIFY(sheet.find(".fault { color: #c00000; }") != std::string::npos);
        QVERIFY(QFileInfo(QDir(out).filePath("wide.nc")).size() > 0);
        QVERIFY(QFileInfo(QDir(out).filePath("wide.sheet.pdf")).size() > 0);
    }

    // A large stock is verified on the finest grid within 16 M cells unless
    // the operator asks for one: the 1,000 x 90 mm plate at 0.08 mm; a
    // --resolution whose grid would pass 100 M cells is an input error
    // (exit 2), nothing written.
    void largeStockOnACoarserGrid()
    {
        QTemporaryDir dir;
        const QString job = writeWideJob(dir);
        const auto v = runTaiwa({"verify", job});
        QCOMPARE(v.exitCode, 3);
        QVERIFY2(v.out.contains("verified at 0.08 mm (12500 x 1125 cells)"), qPrintable(v.out));
        const auto fine = runTaiwa({"verify", job, "--resolution", "0.005"});
        QCOMPARE(fine.exitCode, 2);
        QVERIFY2(fine.err.contains("taiwa: verify: a 0.005000 mm grid over this stock has 3600000000 cells, more than "
                                   "100000000: choose a coarser resolution"),
                 qPrintable(fine.err));
        const QString out = dir.filePath("out");
        const auto e = runTaiwa({"export", job, "--out", out, "--resolution", "0.005", "--force"});
        QCOMPARE(e.exitCode, 2);
        QVERIFY2(e.err.contains("taiwa: export: a 0.005000 mm grid"), qPrintable(e.err));
        QVERIFY(!QFileInfo::exists(out) || QDir(out).isEmpty());
    }

    // The sheet shows the setup and each step's stock in a picture, in the
    // HTML inlined and in the PDF, with or without a display; none at all
    // with --no-pictures.
    void sheetHasAPictureOfEveryStep()
    {
        QTemporaryDir dir;
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const QString out = dir.filePath("pics");
        const auto r = runTaiwa({"export", job, "--out", out, "--resolution", "0.25"});
        QCOMPARE(r.exitCode, 0);
        const std::string html = readFile(QDir(out).filePath("m4-standard.sheet.html"));
        const json steps = json::parse(readFile(QDir(out).filePath("m4-standard.steps.json")));
        const std::size_t n = steps["steps"].size();
        QVERIFY(n >= 4);
        std::size_t images = 0;
        for (std::size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1)) ++images;
        // Drawn by the core on the processor: with a display or without.
        QCOMPARE(images, n + 1);  // and the setup's
        QVERIFY(html.find("src=\"data:image/png;base64,iVBORw0KGgo") != std::string::npos);  // PNG's signature
        QVERIFY(html.find("<figure class=\"setup\"><img alt=\"The stock; G54 at the origin\" src=\"data:image/png;base64,iVBORw0KGgo") !=
                std::string::npos);
        QVERIFY(html.find("<figcaption>3. Floor finishing I, unit 1 Pocket A</figcaption>") != std::string::npos);
        QVERIFY(html.find("No pictures") == std::string::npos);
        const auto bare = runTaiwa({"export", job, "--out", dir.filePath("bare"), "--resolution", "0.25", "--no-pictures"});
        QCOMPARE(bare.exitCode, 0);
        const std::string plain = readFile(QDir(dir.filePath("bare")).filePath("m4-standard.sheet.html"));
        QVERIFY(plain.find("The steps in pictures") == std::string::npos);
        QVERIFY(QFileInfo(QDir(out).filePath("m4-standard.sheet.pdf")).size() >
                QFileInfo(QDir(dir.filePath("bare")).filePath("m4-standard.sheet.pdf")).size() + 10000);
    }

    void optionsRefused()
    {
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        const auto fine = runTaiwa({"verify", job, "--resolution", "0.001"});
        QCOMPARE(fine.exitCode, 2);
        QVERIFY2(fine.err.contains("--resolution wants a cell size in mm from 0.005 to 5, not '0.001'"), qPrintable(fine.err));
        QCOMPARE(runTaiwa({"verify", job, "--resolution", "abc"}).exitCode, 2);
        const auto force = runTaiwa({"verify", job, "--force"});
        QCOMPARE(force.exitCode, 2);
        QVERIFY(force.err.contains("option --force does not go with this command"));
        QCOMPARE(runTaiwa({"check", job, "--json"}).exitCode, 2);
        QCOMPARE(runTaiwa({"verify"}).exitCode, 2);
        QCOMPARE(runTaiwa({"verify", job, "--no-pictures"}).exitCode, 2);
    }

    void latheJobVerified()
    {
        const auto r = runTaiwa({"verify", sourcePath("resources/samples/lathe-turned-shaft.taiwa")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("lathe-turned-shaft.taiwa: verified at 0.05 mm (half-section)"), qPrintable(r.out));
        QVERIFY2(r.out.contains("0 gouges") && !r.out.contains("not verified"), qPrintable(r.out));
    }
};

QTEST_GUILESS_MAIN(TestCliVerify)
#include "test_cli_verify.moc"
