// One fit tolerance (docs/tools.md "One rule for every fit"): a job typed in
// inch as an inch user types it — every length to five decimals, up to
// 0.13 µm off the mm value — plans the same steps with the same tools as the
// same job in mm, for every sample that holds no figure text (a figure's
// text keeps its own numbers).
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QtTest>

#include <cmath>

using namespace taiwa;

namespace {

double fiveDecimalInch(double mm) { return std::round(mm / kMillimetresPerInch * 1e5) / 1e5; }

// "unit 2 Roughing I: T27" for every step, in order.
QStringList toolsOf(const Plan& p)
{
    QStringList out;
    for (const Step& s : p.steps)
        out << QString("unit %1 %2: T%3").arg(s.unit + 1).arg(QString::fromStdString(s.label())).arg(s.tool ? s.tool->toolId : 0);
    return out;
}

}  // namespace

class TestFitTolerance : public QObject {
    Q_OBJECT

private slots:
    void fiveDecimalInchPlansTheToolsOfMm_data()
    {
        QTest::addColumn<QString>("sample");
        const QStringList samples = QDir(test::sourcePath("resources/samples")).entryList({"*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(samples.size() > 20);
        for (const QString& s : samples) QTest::newRow(qPrintable(s)) << s;
    }

    void fiveDecimalInchPlansTheToolsOfMm()
    {
        QFETCH(QString, sample);
        const auto read = readJobFile(test::sourcePath("resources/samples/" + sample).toStdString());
        QVERIFY(read.job);
        if (!read.job->figure.empty()) QSKIP("a figure's text keeps its own numbers");
        const Job mm = toMillimetres(*read.job);
        const Job inch = withLengths(mm, LengthUnit::Inch, fiveDecimalInch);
        const auto library = defaultToolLibrary();
        const Plan a = planJob(mm, TechnologyTable::builtIn(), library);
        const Plan b = planJob(inch, TechnologyTable::builtIn(), library);
        QVERIFY2(a.ok(), qPrintable(sample));
        QVERIFY2(b.ok(), qPrintable(QString::fromStdString(b.diagnostics.empty() ? "" : b.diagnostics.front().message)));
        QVERIFY2(toolsOf(b) == toolsOf(a),
                 qPrintable("in mm:\n" + toolsOf(a).join('\n') + "\nin inch:\n" + toolsOf(b).join('\n')));
    }
};

QTEST_APPLESS_MAIN(TestFitTolerance)
#include "test_fit_tolerance.moc"
