// Job files that are not jobs (interfaces.md "Job files"): every bad file of
// tests/data/bad-jobs gives exactly the lines of its .expected file; deep,
// huge, missing and unreadable files and the fuzzer's findings are refused
// without a crash; diagnostics are capped; writes are atomic.
// TAIWA_UPDATE_GOLDEN=1 rewrites the *.expected files (and fails: review the diff).
#include "io/job_io.h"
#include "job/job_file.h"
#include "support/support.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>

using namespace taiwa;
using namespace taiwa::test;

namespace {

QStringList filesIn(const QString& dir, const QString& pattern)
{
    QStringList out;
    for (const auto& f : QDir(dir).entryInfoList({pattern}, QDir::Files, QDir::Name)) out << f.absoluteFilePath();
    return out;
}

std::string diagnosticLines(const QString& fileName, const Diagnostics& ds)
{
    std::string out;
    for (const auto& d : ds) out += format(fileName.toStdString(), d) + "\n";
    return out;
}

// A valid job's text.
std::string sampleText() { return readFile(sourcePath("resources/samples/plate.taiwa")); }

}  // namespace

class TestJobRefusals : public QObject {
    Q_OBJECT
private slots:
    void badFilesGiveTheirExpectedMessages_data()
    {
        QTest::addColumn<QString>("file");
        const QStringList files = filesIn(dataPath("bad-jobs"), "*.taiwa");
        QVERIFY(files.size() >= 15);
        for (const auto& f : files) QTest::newRow(qPrintable(QFileInfo(f).fileName())) << f;
    }
    void badFilesGiveTheirExpectedMessages()
    {
        QFETCH(QString, file);
        const JobReadResult r = readJobFile(file.toStdString());
        QVERIFY(!r.job);
        QVERIFY(!r.diagnostics.empty());
        QVERIFY(r.diagnostics.size() <= 100);
        const std::string actual = diagnosticLines(QFileInfo(file).fileName(), r.diagnostics);
        const QString expectedFile = file.chopped(6) + ".expected";
        if (rewroteGolden(expectedFile, actual)) return;
        QVERIFY2(QFileInfo::exists(expectedFile), qPrintable(expectedFile + " is missing"));
        QCOMPARE(actual, readFile(expectedFile));
    }

    // The schema is a second reading of the format: it accepts every sample
    // and refuses every bad job that it can judge (JSON without repeated keys).
    void deepNestingIsRefusedWithoutCrash_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("message");  // the whole message: where the 65th level opens
        QTest::newRow("100k open arrays") << QByteArray(100000, '[')
                                          << "not a job file: arrays and objects nested more than 64 deep at byte 65 (line 1, column 65)";
        QTest::newRow("100k closed arrays") << QByteArray(100000, '[') + QByteArray(100000, ']')
                                            << "not a job file: arrays and objects nested more than 64 deep at byte 65 (line 1, column 65)";
        QByteArray objects;
        for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
        QTest::newRow("100k objects") << objects + "1" + QByteArray(100000, '}')
                                      << "not a job file: arrays and objects nested more than 64 deep at byte 321 (line 1, column 321)";
        const QByteArray head = R"({"format": "taiwa-job", "version": 1, "units": [{"module": "M4", "corners": )";
        QTest::newRow("deep in a unit") << head + QByteArray(100000, '[') + QByteArray(100000, ']') + "}]}"
                                        << QString("not a job file: arrays and objects nested more than 64 deep at byte %1 (line 1, column %1)")
                                               .arg(head.size() + 62);
    }
    void deepNestingIsRefusedWithoutCrash()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        const JobReadResult r = readJob(text.toStdString());
        QVERIFY(!r.job);
        QCOMPARE(r.diagnostics.size(), std::size_t{1});
        QCOMPARE(QString::fromStdString(r.diagnostics.front().message), message);
        QVERIFY(!r.diagnostics.front().unit);  // the file as a whole
    }

    void tooManyProblemsAreCapped()
    {
        std::string text = R"({"format": "taiwa-job", "version": 1, "units": [)";
        for (int i = 0; i < 500; ++i) text += std::string(i ? "," : "") + R"({"module": "M4", "depth": "x"})";
        const JobReadResult r = readJob(text + "]}");
        QCOMPARE(r.diagnostics.size(), std::size_t{100});
        QCOMPARE(format("j", r.diagnostics.front()), std::string("j: job lengthUnit: missing; it must be one of \"mm\", \"inch\""));
        QVERIFY2(r.diagnostics.back().message.starts_with("1904 more errors not listed"), r.diagnostics.back().message.c_str());
    }

    void hugeFileIsRefusedBySizeBeforeReading()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("huge.taiwa");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.resize(100LL * 1024 * 1024));  // sparse: nothing is really written
        f.close();
        const JobReadResult r = readJobFile(file.toStdString());
        QVERIFY(!r.job);
        QCOMPARE(diagnosticLines("huge.taiwa", r.diagnostics),
                 std::string("huge.taiwa: the file is 104857600 bytes (100.0 MB); a job file may be at most 67108864 bytes (64 MB)\n"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.resize(qint64(kMaxJobFileBytes) + 1));
        f.close();
        QVERIFY(readJobFile(file.toStdString()).diagnostics.at(0).message.starts_with("the file is 67108865 bytes"));
    }

    void missingAndUnreadableFiles()
    {
        const auto message = [](const QString& path) {
            const JobReadResult r = readJobFile(path.toStdString());
            return r.job || r.diagnostics.size() != 1 ? QString("read or not one line") : QString::fromStdString(format("f", r.diagnostics[0]));
        };
        QCOMPARE(message("/nonexistent/nothing.taiwa"), QString("f: cannot open: No such file or directory"));
        QTemporaryDir dir;
        QCOMPARE(message(dir.path()), QString("f: cannot open: Is a directory"));
        // A pipe could be endless: refused without reading (this would hang otherwise).
        const QString fifo = dir.filePath("pipe.taiwa");
        QVERIFY(::mkfifo(fifo.toLocal8Bit().constData(), 0600) == 0);
        QCOMPARE(message(fifo), QString("f: not a regular file; a job file is a JSON document"));
        if (::geteuid() != 0) {  // root reads anything
            const QString locked = dir.filePath("locked.taiwa");
            writeFile(locked, sampleText());
            QVERIFY(::chmod(locked.toLocal8Bit().constData(), 0) == 0);
            QCOMPARE(message(locked), QString("f: cannot open: Permission denied"));
        }
    }

    void fuzzRegressionsNeitherCrashNorHalfRead()
    {
        const QStringList files = filesIn(dataPath("fuzz-regressions"), "*");
        QVERIFY(!files.isEmpty());
        for (const auto& f : files) {
            const JobReadResult r = readJob(readFile(f));
            QVERIFY2(r.job.has_value() != !r.diagnostics.empty(), qPrintable(f));
            QVERIFY(r.diagnostics.size() <= 100);
            if (r.job) QVERIFY2(readJob(writeJob(*r.job)).job == r.job, qPrintable(f));
        }
    }

    void writeFileAtomicallyReplacesWholeFiles()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("job.taiwa");
        QVERIFY(writeFileAtomically(file.toStdString(), "first\n"));
        QCOMPARE(readFile(file), std::string("first\n"));
        QVERIFY(::chmod(file.toLocal8Bit().constData(), 0640) == 0);
        const std::string text = sampleText();
        QVERIFY(writeFileAtomically(file.toStdString(), text));
        QCOMPARE(readFile(file), text);
        struct stat st {};
        QVERIFY(::stat(file.toLocal8Bit().constData(), &st) == 0);
        QCOMPARE(st.st_mode & 0777, 0640u);                               // permissions kept
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"job.taiwa"});  // no temporary left
        const auto error = writeFileAtomically(dir.filePath("no/such/folder/x.taiwa").toStdString(), text);
        QVERIFY(!error);
        QVERIFY2(error.error().find("No such file or directory") != std::string::npos, error.error().c_str());
        if (::geteuid() != 0) {
            QVERIFY(::chmod(dir.path().toLocal8Bit().constData(), 0500) == 0);
            const auto denied = writeFileAtomically(file.toStdString(), "lost\n");
            QVERIFY(::chmod(dir.path().toLocal8Bit().constData(), 0700) == 0);
            QVERIFY(!denied);
            QVERIFY2(denied.error().find("Permission denied") != std::string::npos, denied.error().c_str());
            QCOMPARE(readFile(file), text);  // the old file is untouched
        }
    }};

QTEST_APPLESS_MAIN(TestJobRefusals)
#include "test_job_refusals.moc"
