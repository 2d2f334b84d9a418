// Which dialects write a probing unit's programs, and that the others refuse
// them saying why. The SINUMERIK and HEIDENHAIN probing programs stay
// refused (docs/probing.md: the manual pages at hand do not confirm MEAS's
// edges and $AC_MEA on a SINUMERIK, nor what TCH PROBE 0 does when nothing
// is touched and how a program writes a preset on a TNC): every probing
// sample, planned, is refused for both by the setting program, the cycle
// and the export (nothing written), and the sentence names the constructs
// not confirmed. The rule follows the language, not the name: a shop's own
// dialect in Siemens syntax is refused the same way. The ISO dialects
// (fanuc, haas, linuxcnc) write both programs.
#include "export/export.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/probe_program.h"
#include "tools/tool_library.h"
#include "support/support.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <stdexcept>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// Every probing sample's plan (each has one PROBE unit).
std::vector<std::pair<QString, Plan>> probingSamples()
{
    std::vector<std::pair<QString, Plan>> plans;
    const auto files = QDir(sourcePath("resources/samples")).entryInfoList({"probe-*.taiwa"}, QDir::Files, QDir::Name);
    for (const QFileInfo& f : files) {
        const auto job = readJobFile(f.absoluteFilePath().toStdString());
        if (!job.job) continue;
        plans.emplace_back(f.fileName(), planJob(*job.job, TechnologyTable::builtIn(), defaultToolLibrary()));
    }
    return plans;
}

// The message of the Refusal `f` throws; empty when it writes.
template <typename F>
QString refusal(F&& f)
{
    try {
        f();
    } catch (const Refusal& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

}  // namespace

class TestProbeDialects : public QObject {
    Q_OBJECT
private slots:
    void refusedWithTheirReason_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QStringList>("names");
        QTest::newRow("sinumerik") << "sinumerik" << QStringList{"MEAS=1", "$AC_MEA", "STOPRE", "$AA_MW"};
        QTest::newRow("heidenhain") << "heidenhain" << QStringList{"TCH PROBE 0", "FN 17: SYSWRITE", "code number"};
    }
    void refusedWithTheirReason()
    {
        QFETCH(QString, dialect);
        QFETCH(QStringList, names);
        const auto samples = probingSamples();
        QVERIFY(samples.size() >= 3);
        const QString head = "the " + dialect + " dialect writes no probing unit's programs; " +
                             test::shippedDialectsWriting(test::DialectWrites::ProbingPrograms).join(", ") + " can (";
        // Empty when `message` is the refusal naming every construct; else what is wrong.
        const auto wrong = [&](const QString& message, const QString& what) -> QString {
            bool right = message.startsWith(head) && message.contains("docs/probing.md");
            for (const QString& name : names) right = right && message.contains(name);
            return right ? QString() : what + ": '" + message + "'";
        };
        int measured = 0;
        for (const auto& [name, plan] : samples) {
            QVERIFY2(plan.ok(), qPrintable(name));
            QCOMPARE(plan.setups.size(), std::size_t(1));
            const WorkSetup& w = plan.setups.front();
            PostOptions o;
            o.dialect = dialect.toStdString();
            o.workOffset = plan.job.workOffset;
            QString problem = wrong(refusal([&] { probingProgram(w, o); }), name + " cycle");
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
            if (w.measured) {
                ++measured;
                problem = wrong(refusal([&] { settingProgram(w, o); }), name + " setting program");
                QVERIFY2(problem.isEmpty(), qPrintable(problem));
            }
            QTemporaryDir out;
            ExportOptions e;
            e.dialect = o.dialect;
            const auto written = exportPlan(plan, out.filePath("x").toStdString(), "x", e);
            QVERIFY2(!written.ok(), qPrintable(name));
            problem = wrong(QString::fromStdString(written.error()), name + " export");
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
            QVERIFY(QString::fromStdString(written.error()).endsWith("; nothing was written"));
            QVERIFY2(!QFileInfo::exists(out.filePath("x")), qPrintable(name));
        }
        QVERIFY(measured >= 2);  // the setting program is refused where there is one to write
    }

    // A shop's own dialect in Siemens syntax under another name: refused the
    // same way, naming itself.
    void theRuleFollowsTheLanguage()
    {
        auto def = nlohmann::json::parse(readFile(sourcePath("resources/dialects/sinumerik.json")));
        def["name"] = "shop840d";
        const auto d = post::readDialect(def.dump(2), "shop840d.json");
        QVERIFY2(d.ok(), d.ok() ? "" : d.error().c_str());
        const auto can = post::canPost(d.value(), post::Task::ProbingPrograms);
        QVERIFY(!can);
        QVERIFY2(can.error().starts_with("the shop840d dialect writes no probing unit's programs;") &&
                     can.error().find("MEAS=1") != std::string::npos,
                 can.error().c_str());
    }

    // The ISO dialects write both programs for every sample; every other
    // dialect in the library is refused with a reason of its own.
    void isoDialectsWriteTheRestSayWhy()
    {
        const auto samples = probingSamples();
        int iso = 0;
        for (const post::Dialect& d : post::dialectLibrary()) {
            const auto can = post::canPost(d, post::Task::ProbingPrograms);
            if (d.syntax != post::Syntax::Iso) {
                QVERIFY2(!can && can.error().find("manual pages at hand") != std::string::npos, d.name.c_str());
                continue;
            }
            ++iso;
            QVERIFY2(can, can ? "" : can.error().c_str());
            for (const auto& [name, plan] : samples) {
                const WorkSetup& w = plan.setups.front();
                PostOptions o;
                o.dialect = d.name;
                o.workOffset = plan.job.workOffset;
                QVERIFY2(!probingProgram(w, o).empty(), qPrintable(name));
                if (w.measured) QVERIFY2(!settingProgram(w, o).empty(), qPrintable(name));
            }
        }
        QCOMPARE(iso, 3);
    }

    // A rectangle touched once per side has no rotation measured: its
    // setting program says so in words that survive a comment (parentheses
    // inside one become spaces: " not measured " was the tape's text).
    void settingProgramSaysRotationNotMeasured()
    {
        WorkSetup w;
        w.round = false;
        w.measured = WorkSetup::Measured{};
        w.measured->centre = {100, 50};
        w.measured->width = 60;
        w.measured->length = 40;
        w.measured->residuals = {0, 0, 0, 0};
        for (const char* dialect : {"linuxcnc", "fanuc", "haas"}) {
            PostOptions o;
            o.dialect = dialect;
            const QString text = QString::fromStdString(settingProgram(w, o));
            QVERIFY2(text.contains("4 touches: 60.0000 x 40.0000 mm, rotation not measured: one touch per side, worst residual",
                                   Qt::CaseInsensitive),
                     qPrintable(text));
            QVERIFY2(!text.contains(" not measured ,"), qPrintable(text));
            w.measured->rotationMeasured = true;
            w.measured->rotation = 1.5;
            QVERIFY2(QString::fromStdString(settingProgram(w, o)).contains("turned 1.5000 deg", Qt::CaseInsensitive), dialect);
            w.measured->rotationMeasured = false;
            w.measured->rotation = 0;
        }
    }
};

QTEST_GUILESS_MAIN(TestProbeDialects)
#include "test_probe_dialects.moc"
