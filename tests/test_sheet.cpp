// The machining instruction sheet of a planned sample job: every step's row
// with its numbers, the tool list, escaping of job text, and a PDF that
// poppler reads as A4 landscape pages.
#include "io/job_io.h"
#include "pipeline/pipeline.h"
#include "sheet/sheet.h"
#include "support/support.h"
#include "tools/cutting.h"
#include "tools/tool_library.h"

#include <QGuiApplication>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <fmt/format.h>

using namespace taiwa;

namespace {
Plan samplePlan(const std::string& name)
{
    auto read = readJobFile(test::sourcePath("resources/samples/m4-standard.taiwa").toStdString());
    read.job->name = name;
    return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
}
}  // namespace

class TestSheet : public QObject {
    Q_OBJECT
private slots:
    void htmlHasEveryStepWithItsNumbers()
    {
        const Plan plan = samplePlan("Cover <A&B>");
        QVERIFY(plan.ok() && !plan.steps.empty());
        const QString html = QString::fromStdString(sheetHtml(plan, {}));
        QVERIFY(html.contains("Cover &lt;A&amp;B&gt;"));
        QVERIFY(!html.contains("<A&B>"));
        for (std::size_t i = 0; i < plan.steps.size(); ++i) {
            const Step& s = plan.steps[i];
            const Tool& t = *plan.tool(s.tool->toolId);
            const auto sf = speedsFeeds(t, plan.mmJob.material);
            const QString row = QString::fromStdString(fmt::format(
                "<tr><td class=n>{}</td><td class=n>{}</td><td>{}</td><td>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td>"
                "<td class=n>{:.0f}</td><td class=n>{:.0f}</td><td class=n>{:.3f}</td><td class=n>{:.3f}</td>",
                i + 1, s.unit + 1, s.module, s.label(), t.id, t.id, t.name, sf->rpm, sf->feed, s.startDepth, s.cutDepth));
            QVERIFY2(html.contains(row), qPrintable(row));
        }
        for (const auto& t : plan.tools) QVERIFY(html.contains(QString::fromStdString(t.holder)));
        QVERIFY(html.contains(QString::fromStdString(fmt::format("{:.1f} min including {} tool changes", plan.totalMinutes, plan.toolChanges))));
    }

    void inchSheetShowsInches()
    {
        SheetOptions o;
        o.units = LengthUnit::Inch;
        const QString html = QString::fromStdString(sheetHtml(samplePlan("x"), o));
        QVERIFY(html.contains("Depth in"));
        QVERIFY(html.contains("F in/min"));
    }

    void pdfIsA4LandscapeAndReadable()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("sheet.pdf");
        QVERIFY(!writeSheetPdf(samplePlan("Cover"), {}, pdf.toStdString()));
        QProcess info;
        info.start("pdfinfo", {pdf});
        QVERIFY(info.waitForFinished());
        const QString out = QString::fromUtf8(info.readAllStandardOutput());
        QVERIFY2(out.contains("842 x 595 pts (A4)"), qPrintable(out));
        QVERIFY(QRegularExpression("Pages:\\s+1\\n").match(out).hasMatch());
        QProcess text;
        text.start("pdftotext", {"-layout", pdf, "-"});
        QVERIFY(text.waitForFinished());
        const QString words = QString::fromUtf8(text.readAllStandardOutput());
        QVERIFY2(words.contains("Machining instruction sheet") && words.contains("Roughing I") && words.contains("Pilot hole"),
                 qPrintable(words.left(400)));
    }
};

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestSheet t;
    return QTest::qExec(&t, argc, argv);
}
#include "test_sheet.moc"
