// A LinuxCNC lathe tape runs as exported: `taiwa export` of a lathe job for
// linuxcnc writes STEM.tbl beside STEM.nc (core/post/tool_table.h), the
// tape's header names it, its stations, nose diameters and orientations are
// those of the tape's header (and of the table the turning oracle builds,
// support/turning_oracle.h), and LinuxCNC's rs274 runs the exported tape
// with the exported table, its moves passing the oracle. The FANUC export of
// the same job writes no table (its offsets are set on the control).
#include "support/rs274.h"
#include "support/support.h"
#include "support/turning_oracle.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <map>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// "T<station> … D<d> Q<q>" of each line of a LinuxCNC tool table, by station.
std::map<int, std::pair<double, int>> stations(const QString& table)
{
    static const QRegularExpression line(R"(^T(\d+) P(\d+) X0 Z0 D([0-9.]+) Q(\d+) ;)");
    std::map<int, std::pair<double, int>> out;
    for (const QString& l : table.split('\n')) {
        const auto m = line.match(l);
        if (m.hasMatch() && m.captured(1) == m.captured(2)) out[m.captured(1).toInt()] = {m.captured(3).toDouble(), m.captured(4).toInt()};
    }
    return out;
}

}  // namespace

class TestRs274LatheExport : public QObject {
    Q_OBJECT
private slots:
    void exportedTapeRunsWithItsTable_data()
    {
        QTest::addColumn<QString>("stem");
        for (const char* stem : {"lathe-bushing", "lathe-threaded-shaft", "lathe-grooved-shaft"}) QTest::newRow(stem) << QString(stem);
    }
    void exportedTapeRunsWithItsTable()
    {
        QFETCH(QString, stem);
        const QString job = sourcePath("resources/samples/" + stem + ".taiwa");
        QTemporaryDir out;
        const auto r = runTaiwa({"export", job, "--out", out.path(), "--dialect", "linuxcnc", "--resolution", "0.25", "--no-pictures"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString tbl = QDir(out.path()).filePath(stem + ".tbl");
        QVERIFY2(QFileInfo::exists(tbl), qPrintable(QDir(out.path()).entryList().join(", ")));
        const std::string nc = readFile(QDir(out.path()).filePath(stem + ".nc"));
        const std::string table = readFile(tbl);
        QVERIFY2(nc.find("(Tool table " + stem.toStdString() + ".tbl: ") != std::string::npos, nc.substr(0, 600).c_str());

        // The stations, D (2 x nose radius, inch) and Q of the tape's header and of the oracle's table.
        const auto read = readJobFile(job.toStdString());
        QVERIFY(read.job);
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok());
        const auto exported = stations(QString::fromStdString(table));
        const auto expected = stations(QString::fromStdString(latheToolTable(plan)));
        QVERIFY(!expected.empty());
        QCOMPARE(exported.size(), expected.size());
        for (const auto& [station, dq] : expected) {
            QVERIFY2(exported.count(station), qPrintable(QString("station %1 missing").arg(station)));
            QVERIFY2(std::abs(exported.at(station).first - dq.first) < 1e-6, qPrintable(QString::fromStdString(table)));
            QCOMPARE(exported.at(station).second, dq.second);
            const auto header = QRegularExpression(QString(R"(\(T%1 = library T\d+ .* orientation (\d+)\))").arg(station, 2, 10, QChar('0')))
                                    .match(QString::fromStdString(nc));
            QVERIFY2(header.hasMatch() && header.captured(1).toInt() == dq.second, qPrintable(QString("station %1").arg(station)));
        }

        // As exported: rs274 with the exported table, judged by the oracle.
        const Rs274Result run = runRs274(nc, table);
        QVERIFY2(run.ok, qPrintable("rs274 refuses the exported tape: " + run.errors));
        const LatheVerdict v = judgeLatheTape(plan, run);
        QVERIFY2(v.problems.isEmpty(), qPrintable(QStringList(v.problems.mid(0, 8)).join('\n')));

        // FANUC: the offsets are the control's; no table.
        QTemporaryDir fanuc;
        const auto f = runTaiwa({"export", job, "--out", fanuc.path(), "--dialect", "fanuc", "--resolution", "0.25", "--no-pictures"});
        QVERIFY2(f.exitCode == 0, qPrintable(f.err));
        QVERIFY(QDir(fanuc.path()).entryList({"*.tbl"}, QDir::Files).isEmpty());
    }
};

QTEST_APPLESS_MAIN(TestRs274LatheExport)
#include "test_rs274_lathe_export.moc"
