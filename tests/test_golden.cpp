// Golden NC files: every sample exported through the real command line in
// every dialect that posts it (HEIDENHAIN no lathe jobs, neither it nor
// Siemens probing units),
// every NC file of the export compared byte for byte with
// tests/golden/STEM.DIALECT.EXT (the tape: .nc, .mpf for Siemens, .h for
// HEIDENHAIN) or tests/golden/STEM.uN.KIND.DIALECT.nc (a probing unit's
// setting program and probing cycle), reviewed by hand once. A mismatch writes STEM.DIALECT.nc.actual beside
// the golden file; TAIWA_UPDATE_GOLDEN=1 rewrites the golden files instead.
// A job on a two-path lathe writes STEM.p1.nc and STEM.p2.nc in place of
// the tape (docs/two-path-lathe.md), in the dialects that write two-path
// programs (the ISO ones): both compared, as STEM.p1.DIALECT.nc and
// STEM.p2.DIALECT.nc.
// Lathe jobs also have the turned profiles of
// STEM.steps.json (tests/golden/STEM.turned.json: profile, allowance rows,
// deformed profile), reviewed by hand against docs/turning.md.
#include "support/support.h"

#include <nlohmann/json.hpp>

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa::test;

namespace {
// The export verifies each tape first; at its default 0.05 mm that is most
// of an export's time, and the verification has tests of its own
// (test_verify): the goldens are exported verified on a coarser grid, and
// without the sheet's pictures (test_cli_verify draws those).
const QString kVerifyCell = QStringLiteral("0.25");
}  // namespace

class TestGolden : public QObject {
    Q_OBJECT
private slots:
    void tapeMatchesGolden_data()
    {
        QTest::addColumn<QString>("job");
        QTest::addColumn<QString>("dialect");
        const auto files = QDir(sourcePath("resources/samples")).entryInfoList({"*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(!files.isEmpty());
        for (const auto& f : files) {
            const std::string text = readFile(f.absoluteFilePath());
            const bool lathe = text.find("\"shape\": \"bar\"") != std::string::npos;
            const bool probing = text.find("\"module\": \"PROBE\"") != std::string::npos;
            const bool twoPath = text.find("\"machine\": \"lathe-two-path\"") != std::string::npos;
            if (lathe) QTest::newRow(qPrintable(f.completeBaseName() + "/turned")) << f.absoluteFilePath() << "turned";
            // Every shipped dialect; Klartext is a milling control's language
            // (no lathe tapes), the probing programs are written in ISO only.
            const QStringList dialects = shippedDialectsWriting(twoPath ? DialectWrites::TwoPathPrograms
                                                                : lathe ? DialectWrites::LatheTapes
                                                                : probing ? DialectWrites::ProbingPrograms
                                                                          : DialectWrites::MillingTapes);
            for (const QString& dialect : dialects)
                QTest::newRow(qPrintable(f.completeBaseName() + "/" + dialect)) << f.absoluteFilePath() << dialect;
        }
    }
    void tapeMatchesGolden()
    {
        QFETCH(QString, job);
        QFETCH(QString, dialect);
        QTemporaryDir out;
        if (dialect == "turned") {
            const auto r = runTaiwa({"export", job, "--out", out.path(), "--resolution", kVerifyCell, "--no-pictures"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QString stem = QFileInfo(job).completeBaseName();
            const auto steps = nlohmann::json::parse(readFile(QDir(out.path()).filePath(stem + ".steps.json")));
            const std::string actual = steps.at("turnedProfiles").dump(1) + "\n";
            const QString golden = sourcePath("tests/golden/" + stem + ".turned.json");
            if (rewroteGolden(golden, actual)) return;
            QVERIFY2(QFileInfo::exists(golden), qPrintable("no golden file " + golden + " (TAIWA_UPDATE_GOLDEN=1 writes it)"));
            if (actual != readFile(golden)) {
                writeFile(golden + ".actual", actual);
                QFAIL(qPrintable("turned profiles differ from " + golden + "; see " + golden + ".actual"));
            }
            return;
        }
        const auto r = runTaiwa({"export", job, "--out", out.path(), "--dialect", dialect, "--resolution", kVerifyCell, "--no-pictures"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString stem = QFileInfo(job).completeBaseName();
        const auto written = QDir(out.path()).entryList({"*.nc", "*.mpf", "*.h"}, QDir::Files, QDir::Name);
        const bool twoPath = readFile(job).find("\"machine\": \"lathe-two-path\"") != std::string::npos;
        const QString tape = stem + (twoPath ? ".p1" : "") + (dialect == "sinumerik" ? ".mpf" : dialect == "heidenhain" ? ".h" : ".nc");
        QVERIFY2(written.contains(tape), qPrintable(written.join(", ")));
        bool rewrote = false;
        for (const QString& name : written) {
            const std::string actual = readFile(QDir(out.path()).filePath(name));
            const QString ext = QFileInfo(name).suffix();
            const QString golden = sourcePath("tests/golden/" + name.chopped(ext.size() + 1) + "." + dialect + "." + ext);
            if (rewroteGolden(golden, actual)) {
                rewrote = true;
                continue;
            }
            QVERIFY2(QFileInfo::exists(golden), qPrintable("no golden file " + golden + " (TAIWA_UPDATE_GOLDEN=1 writes it)"));
            const std::string expected = readFile(golden);
            if (actual != expected) {
                writeFile(golden + ".actual", actual);
                QFAIL(qPrintable("NC file differs from " + golden + "; see " + golden + ".actual"));
            }
        }
        if (rewrote) return;
    }
};

QTEST_APPLESS_MAIN(TestGolden)
#include "test_golden.moc"
