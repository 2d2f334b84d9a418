// The machining instruction sheet of a planned sample job: every step's row
// with its numbers, the tool list, escaping of job text, and a PDF that
// poppler reads as A4 landscape pages.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "export/sheet_pdf.h"
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
                "<tr><td class=n>{}</td><td class=n>{} {}</td><td>{}</td><td>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td>"
                "<td class=n>{:.0f}</td><td class=n>{:.0f}</td><td class=n>{:.3f}</td><td class=n>{:.3f}</td>",
                i + 1, s.unit + 1, plan.job.units[static_cast<std::size_t>(s.unit)].name, s.module, s.label(), t.id, t.id,
                t.name, sf->rpm, sf->feed, s.startDepth, s.cutDepth));
            QVERIFY2(html.contains(row), qPrintable(row));
        }
        for (const auto& t : plan.tools) QVERIFY(html.contains(QString::fromStdString(t.holder)));
        // A mill has no turret (the lathe's table was once shown for every job),
        // and a tape verified clean has no faults shown.
        QVERIFY(!html.contains("<h2>Turret</h2>"));
        QVERIFY(!html.contains("class=\"fault\""));
        SheetOptions forced;
        forced.faults = {"step 3 (Roughing I, unit 1): gouge 0.500 mm deep <here>"};
        const QString red = QString::fromStdString(sheetHtml(plan, forced));
        QVERIFY(red.contains("<ul class=\"fault\"><li>step 3 (Roughing I, unit 1): gouge 0.500 mm deep &lt;here&gt;</li></ul>"));
        double cutting = 0;
        for (const auto& s : plan.steps) cutting += *s.minutes;
        QVERIFY(html.contains(QString::fromStdString(fmt::format("{:.1f} min of machining, {} tool changes, {:.1f} min in all",
                                                                 cutting, plan.toolChanges, plan.totalMinutes))));
    }

    void handBuiltPlanShowsEveryFieldEscaped()
    {
        Plan plan;
        plan.job.name = "Jig <rev B> & spare";
        plan.mmJob = plan.job;
        plan.mmJob.material = "steel-s45c";
        plan.mmJob.stock.width = 120;
        plan.mmJob.stock.length = 80;
        plan.mmJob.stock.height = 25;
        const auto library = defaultToolLibrary();
        Tool t = *std::find_if(library.begin(), library.end(), [](const Tool& x) { return x.id == 27; });  // 10 mm, 3 flutes
        t.name = "End mill <10> & co";
        t.holder = "ER32 \"short\"";
        t.usedMinutes = 30;
        plan.tools = {t};
        Step s;
        s.unit = 2;
        s.module = "M4";
        s.kind = StepKind::Roughing;
        s.number = 2;
        s.startDepth = 4;
        s.cutDepth = 7.5;
        s.wallAllowance = 0.3;
        s.floorAllowance = 0.2;
        s.tool = ToolChoice{27, "why"};
        ToolPath path;
        path.start = {0, 0, 5};
        path.moves = {{MoveKind::Feed, {0, 0, -2}}, {MoveKind::Feed, {30, 0, -2}}, {MoveKind::Rapid, {30, 0, 5}}};
        s.path = path;
        s.minutes = 12.5;
        s.machineMinutes = 13.25;
        plan.steps = {s};
        plan.diagnostics.push_back({Severity::Warning, 1, "M4", "tools.roughing", "T27 <worn> & chipped"});
        plan.toolChanges = 1;
        plan.totalMinutes = 12.63;
        plan.totalMachineMinutes = 13.38;
        plan.job.machine = "vmc";
        SheetOptions o;
        o.jobFile = "jig&fixture.taiwa";
        o.date = "2026-11-23";
        o.programNumber = 1234;
        o.dialect = "fanuc";
        const QString html = QString::fromStdString(sheetHtml(plan, o));
        for (const char* text : {"Jig &lt;rev B&gt; &amp; spare", "jig&amp;fixture.taiwa", "2026-11-23", "O1234", "fanuc",
                                 "steel-s45c", "120.000 x 80.000 x 25.000 mm", "G54",
                                 "origin X0 Y0 at the stock's front-left corner, Z0 on the top face",
                                 "End mill &lt;10&gt; &amp; co", "ER32 &quot;short&quot;", "T27 &lt;worn&gt; &amp; chipped",
                                 "12.5 min of machining, 1 tool changes, 12.6 min in all (13.4 min as the machine 'vmc' moves"})
            QVERIFY2(html.contains(text), text);
        // The row: no. 1, unit 3, T/H 27, 3820 rpm (1000 x 120 / (pi x 10)), 573 mm/min (x 0.05 x 3 flutes),
        // depths 4 to 7.5, allowances, 37 mm of cutting path (7 down + 30 across), 12.5 min, as the machine moves 13.25.
        QVERIFY2(html.contains("<tr><td class=n>1</td><td class=n>3</td><td>M4</td><td>Roughing II</td><td class=n>27</td>"
                               "<td class=n>27</td><td>End mill &lt;10&gt; &amp; co</td><td class=n>3820</td>"
                               "<td class=n>573</td><td class=n>4.000</td><td class=n>7.500</td><td class=n>0.300</td>"
                               "<td class=n>0.200</td><td class=n>37.000</td><td class=n>12.50</td><td class=n>13.25</td></tr>"),
                 qPrintable(html));
        // The tool list: life 120, used 30, left 90.
        QVERIFY(html.contains("<td class=n>120</td><td class=n>30.0</td><td class=n>90.0</td>"));
        for (const char* raw : {"<rev B>", "<10>", "<worn>", "& spare", "& co"}) QVERIFY2(!html.contains(raw), raw);
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
        QVERIFY(writeSheetPdf(samplePlan("Cover"), {}, pdf.toStdString()));
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

    void longSheetsRepeatTheTableHeaderOnEveryPage()
    {
        Plan plan = samplePlan("Long");
        const auto one = plan.steps;
        for (int copy = 0; copy < 15; ++copy) plan.steps.insert(plan.steps.end(), one.begin(), one.end());
        QTemporaryDir dir;
        const QString pdf = dir.filePath("long.pdf");
        QVERIFY(writeSheetPdf(plan, {}, pdf.toStdString()));
        QProcess info;
        info.start("pdfinfo", {pdf});
        QVERIFY(info.waitForFinished());
        const auto pages = QRegularExpression("Pages:\\s+(\\d+)").match(QString::fromUtf8(info.readAllStandardOutput()));
        QVERIFY(pages.hasMatch() && pages.captured(1).toInt() >= 2);
        for (int page = 1; page <= pages.captured(1).toInt(); ++page) {
            QProcess text;
            text.start("pdftotext", {"-f", QString::number(page), "-l", QString::number(page), pdf, "-"});
            QVERIFY(text.waitForFinished());
            const QString words = QString::fromUtf8(text.readAllStandardOutput());
            QVERIFY2(words.contains("S rpm") && words.contains(QString("page %1").arg(page)), qPrintable(words.left(300)));
        }
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
