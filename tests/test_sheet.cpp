// The machining instruction sheet of a planned sample job: every step's row
// with its numbers, the tool list, escaping of job text, and a PDF that
// poppler reads as A4 landscape pages; the setup's clamping and picture and
// the tools' drawings (their geometry, the SVG and the PDF painted from it).
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "export/sheet_pdf.h"
#include "sheet/sheet.h"
#include "sheet/tool_drawing.h"
#include "support/support.h"
#include "tools/cutting.h"
#include "tools/tool_library.h"

#include <QBuffer>
#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <fmt/format.h>

#include <regex>

using namespace taiwa;

namespace {
Plan samplePlan(const std::string& name, std::optional<Clamping> clamping = std::nullopt)
{
    auto read = readJobFile(test::sourcePath("resources/samples/m4-standard.taiwa").toStdString());
    read.job->name = name;
    read.job->clamping = clamping;
    return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
}

// A stand-in for the setup picture: one colour, to be found again in the PDF.
constexpr QRgb kSetupColour = qRgb(255, 0, 220);
std::string setupPng()
{
    QImage image(320, 240, QImage::Format_RGB32);
    image.fill(kSetupColour);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return bytes.toStdString();
}

// The sheet's pages as pictures (pdftoppm, 50 dpi unless told).
std::vector<QImage> pages(const QString& pdf, int dpi = 50)
{
    QTemporaryDir dir;
    QProcess p;
    p.start("pdftoppm", {"-r", QString::number(dpi), "-png", pdf, dir.filePath("page")});
    p.waitForFinished();
    std::vector<QImage> out;
    for (const QString& f : QDir(dir.path()).entryList({"page*.png"}, QDir::Files, QDir::Name))
        out.push_back(QImage(dir.filePath(f)).convertToFormat(QImage::Format_RGB32));
    return out;
}

int pixelsOf(const QImage& image, QRgb colour)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            n += std::abs(qRed(p) - qRed(colour)) + std::abs(qGreen(p) - qGreen(colour)) + std::abs(qBlue(p) - qBlue(colour)) < 12;
        }
    return n;
}

// The extent of a drawing's shape in mm: its width along the tool and its height across.
std::pair<double, double> extentMm(const sheet::ToolDrawing& d, sheet::ToolDrawing::Part part)
{
    for (const auto& s : d.shapes) {
        if (s.part != part) continue;
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (const auto& p : s.points) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        return {(x1 - x0) / d.scale, (y1 - y0) / d.scale};
    }
    return {-1, -1};
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
                "<tr><td class=n>{}</td><td>{} {}</td><td>{}</td><td>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td>"
                "<td class=n>{:.0f}</td><td class=n>{:.0f}</td><td class=n>{:.3f}</td><td class=n>{:.3f}</td>",
                i + 1, s.unit + 1, plan.job.units[static_cast<std::size_t>(s.unit)].name, s.module, s.label(), t.id, t.id,
                t.name, sf->rpm, sf->feed, millingOf(s).startDepth, millingOf(s).cutDepth));
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
        editMilling(s).startDepth = 4;
        editMilling(s).cutDepth = 7.5;
        editMilling(s).wallAllowance = 0.3;
        editMilling(s).floorAllowance = 0.2;
        s.tool = ToolChoice{27, "why"};
        ToolPath path;
        path.start = {0, 0, 5};
        path.moves = {{MoveKind::Feed, {0, 0, -2}}, {MoveKind::Feed, {30, 0, -2}}, {MoveKind::Rapid, {30, 0, 5}}};
        s.path = path;
        s.minutes = 12.5;
        s.machineMinutes = 13.25;
        s.speeds = stepSpeedsFeeds(s, t, plan.mmJob.material);  // bound as planJob binds them
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
                                 "Carbon steel S45C / C45 (normalised)", "120.000 x 80.000 x 25.000 mm", "G54",
                                 "origin X0 Y0 at the stock's front-left corner, Z0 on the top face",
                                 "End mill &lt;10&gt; &amp; co", "ER32 &quot;short&quot;", "T27 &lt;worn&gt; &amp; chipped",
                                 "12.5 min of machining, 1 tool changes, 12.6 min in all (13.4 min as the machine 'vmc' moves"})
            QVERIFY2(html.contains(text), text);
        // The row: no. 1, unit 3, T/H 27, 3820 rpm (1000 x 120 / (pi x 10)), 573 mm/min (x 0.05 x 3 flutes),
        // depths 4 to 7.5, allowances, 37 mm of cutting path (7 down + 30 across), 12.5 min, as the machine moves 13.25.
        QVERIFY2(html.contains("<tr><td class=n>1</td><td>3</td><td>M4</td><td>Roughing II</td><td class=n>27</td>"
                               "<td class=n>27</td><td>End mill &lt;10&gt; &amp; co</td><td class=n>3820</td>"
                               "<td class=n>573</td><td class=n>4.000</td><td class=n>7.500</td><td class=n>0.300</td>"
                               "<td class=n>0.200</td><td class=n>37.000</td><td class=n>12.50</td><td class=n>13.25</td></tr>"),
                 qPrintable(html));
        // The tool list: life 120, used 30, left 90.
        QVERIFY(html.contains("<td class=n>120</td><td class=n>30.0</td><td class=n>90.0</td>"));
        for (const char* raw : {"<rev B>", "<10>", "<worn>", "& spare", "& co"}) QVERIFY2(!html.contains(raw), raw);
    }

    // A tool's drawing: the holder's nose as the library gives it (else as
    // its name says), the flutes, the stick-out dimensioned with its value;
    // the SVG has the same shapes; lathe tools have none.
    void toolDrawingHasTheLibrarysHolderAndStickOut()
    {
        const auto library = defaultToolLibrary();
        Tool t = *std::find_if(library.begin(), library.end(), [](const Tool& x) { return x.id == 27; });  // 10 mm end mill
        t.holderDiameter = 40;
        t.holderLength = 30;
        t.stickout = 45;
        t.fluteLength = 22;
        const auto len = [](double mm) { return fmt::format("{:.3f} mm", mm); };
        const auto d = sheet::toolDrawing(t, len);
        QVERIFY(d);
        using Part = sheet::ToolDrawing::Part;
        const auto near = [](std::pair<double, double> got, double w, double h) {
            return std::abs(got.first - w) < 1e-9 && std::abs(got.second - h) < 1e-9;
        };
        QVERIFY(near(extentMm(*d, Part::Holder), 30, 40));
        QVERIFY(near(extentMm(*d, Part::Shank), 45 - 22, 10));
        QVERIFY(near(extentMm(*d, Part::Flutes), 22, 10));
        // The dimension line: from the holder's face to the tip, 45 mm, and its text.
        const auto dimension = std::find_if(d->lines.begin(), d->lines.end(), [](const auto& l) {
            return !l.dashed && l.from.y == l.to.y;
        });
        QVERIFY(dimension != d->lines.end());
        QCOMPARE(dimension->from.x, 4 + 30 * d->scale);
        QVERIFY(std::abs((dimension->to.x - dimension->from.x) / d->scale - 45) < 1e-9);
        QCOMPARE(d->texts.size(), std::size_t{1});
        QCOMPARE(d->texts[0].text, std::string("stick-out 45.000 mm"));
        // Everything on the canvas.
        for (const auto& s : d->shapes)
            for (const auto& p : s.points)
                QVERIFY(p.x >= 0 && p.x <= sheet::ToolDrawing::kWidth && p.y >= 0 && p.y <= sheet::ToolDrawing::kHeight);
        // The SVG: the holder's polygon at the same points, the text.
        const std::string svg = sheet::toolDrawingSvg(*d);
        std::smatch m;
        const std::regex holderPolygon("<polygon points=\"([^\"]*)\" fill=\"#9aa3b2\"");
        QVERIFY(std::regex_search(svg, m, holderPolygon));
        std::string expected;
        for (const auto& p : d->shapes[0].points) expected += fmt::format("{}{:.2f},{:.2f}", expected.empty() ? "" : " ", p.x, p.y);
        QCOMPARE(m[1].str(), expected);
        QVERIFY(svg.find(">stick-out 45.000 mm</text>") != std::string::npos);
        QVERIFY(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\"") && svg.ends_with("</svg>"));
        // Without the library's measure, the holder's name: an ER32 collet nut is 50 mm across.
        t.holderDiameter = t.holderLength = 0;
        t.holder = "ER32 collet chuck";
        QVERIFY(near(extentMm(*sheet::toolDrawing(t, len), Part::Holder), 30, 50));
        t.type = ToolType::TurningInsert;
        QVERIFY(!sheet::toolDrawing(t, len));
    }

    // The setup: the clamping in words (or that the job does not say), the
    // picture inlined in the HTML and painted near the top of the PDF's
    // first page; every tool drawn in both.
    void sheetShowsTheSetupAndEveryToolDrawn()
    {
        const Plan loose = samplePlan("Loose");
        QVERIFY(QString::fromStdString(sheetHtml(loose, {})).contains("<p>Clamping not given.</p>"));
        const Plan plan = samplePlan("Held", Clamping{Clamping::Grip::X, 12});
        SheetOptions o;
        o.setupPicture = setupPng();
        const std::string html = sheetHtml(plan, o);
        QVERIFY(html.find("<p>Clamping: vice, the jaws on the stock's X faces (left and right), gripping 12.000 mm up from its "
                          "bottom.</p>") != std::string::npos);
        const std::string base64 = QByteArray::fromStdString(o.setupPicture).toBase64().toStdString();
        QVERIFY(html.find("<figure class=\"setup\"><img alt=\"The stock in the vice; G54 at the origin\" src=\"data:image/png;base64," +
                          base64 + "\"><figcaption>") != std::string::npos);
        QVERIFY(html.find("<figure class=\"setup\">") < html.find("<h2>Process steps</h2>"));
        std::size_t svgs = 0;
        for (std::size_t at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1)) ++svgs;
        QVERIFY(!plan.tools.empty());
        QCOMPARE(svgs, plan.tools.size());
        for (const auto& t : plan.tools) {
            const std::string figure = sheet::toolDrawingSvg(*sheet::toolDrawing(t, [](double mm) { return fmt::format("{:.3f} mm", mm); })) +
                                       fmt::format("<figcaption>T{} {}</figcaption>", t.id, t.name);
            QVERIFY2(html.find(figure) != std::string::npos, figure.c_str());
        }

        QTemporaryDir dir;
        const QString pdf = dir.filePath("held.pdf");
        QVERIFY(writeSheetPdf(plan, o, pdf.toStdString()));
        const std::vector<QImage> shown = pages(pdf);
        if (shown.empty()) QSKIP("pdftoppm is not installed");
        // The picture at a quarter of the page's width (A4 landscape at 50 dpi: 584 px wide), in its upper half.
        const int setup = pixelsOf(shown[0], kSetupColour);
        QVERIFY2(setup > 110 * 80 && setup < 140 * 105, qPrintable(QString::number(setup)));
        QVERIFY(pixelsOf(shown[0].copy(0, 0, shown[0].width(), shown[0].height() / 2), kSetupColour) == setup);
        // The tools' flutes, in the drawings' colour.
        int flutes = 0;
        for (const QImage& page : shown) flutes += pixelsOf(page, qRgb(0xf5, 0xa0, 0x3c));
        QVERIFY2(flutes > 20 * static_cast<int>(plan.tools.size()), qPrintable(QString::number(flutes)));
        // No picture given, none painted.
        QVERIFY(writeSheetPdf(loose, {}, dir.filePath("loose.pdf").toStdString()));
        QCOMPARE(pixelsOf(pages(dir.filePath("loose.pdf")).at(0), kSetupColour), 0);
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

    // Issue 34, item 10: the sheet an operator hangs at the machine reads
    // unit and tool names whole (wrapped in their columns, never cut as
    // "1 Locator po…"), and the material by its name, not its id.
    void pdfHoldsLongNamesWholeAndTheMaterialByName()
    {
        Plan plan = samplePlan("Names");
        const std::string unitName = "Locator pocket for the left-hand bearing seat, reworked after inspection";
        const std::string toolName = "Flat end mill 10 mm carbide, three flutes, long neck, coated AlTiN";
        plan.job.units.front().name = unitName;
        plan.mmJob.units.front().name = unitName;
        const int used = plan.steps.front().tool->toolId;
        for (Tool& t : plan.tools)
            if (t.id == used) t.name = toolName;
        QTemporaryDir dir;
        const QString pdf = dir.filePath("names.pdf");
        QVERIFY(writeSheetPdf(plan, {}, pdf.toStdString()));
        QProcess text;
        text.start("pdftotext", {"-raw", pdf, "-"});
        QVERIFY(text.waitForFinished());
        // The words in reading order, lines joined: a wrapped name reads whole
        // (the font's ligatures "ﬁ", "ﬂ" read as their letters).
        const QString words = QString::fromUtf8(text.readAllStandardOutput())
                                  .replace(QChar(0xFB01), "fi")
                                  .replace(QChar(0xFB02), "fl")
                                  .simplified();
        QVERIFY2(!words.contains(QChar(0x2026)), qPrintable(words.left(2000)));
        const QString unit = QString::fromStdString("1 " + unitName);
        QVERIFY2(words.count(unit) >= 2, qPrintable(words.left(2000)));  // every step of the unit
        QVERIFY2(words.count(QString::fromStdString(toolName)) >= 2, qPrintable(words.left(2000)));  // steps and tools tables
        const MaterialTechnology* material = TechnologyTable::builtIn().find(plan.mmJob.material);
        QVERIFY(material && !material->description.empty());
        QVERIFY2(words.contains("Material " + QString::fromStdString(material->description)), qPrintable(words.left(600)));
        QVERIFY2(!words.contains(QString::fromStdString(plan.mmJob.material)), qPrintable(words.left(600)));
        const QString html = QString::fromStdString(sheetHtml(plan, {}));
        QVERIFY(html.contains(QString::fromStdString("<td><b>Material</b></td><td>" + material->description + "</td>")));
        // A long sheet of such rows is painted alike by one writer and by two.
        const auto one = plan.steps;
        for (int copy = 0; copy < 40; ++copy) plan.steps.insert(plan.steps.end(), one.begin(), one.end());
        auto whole = sheetPdf(plan, {}, PdfParts::One), parts = sheetPdf(plan, {}, PdfParts::Two);
        QVERIFY(whole && parts);
        QVERIFY(*whole != *parts);
        const auto pdfText = [&](const std::string& bytes, const QString& name) {
            QFile f(dir.filePath(name));
            if (!f.open(QIODevice::WriteOnly) || f.write(bytes.data(), static_cast<qint64>(bytes.size())) != static_cast<qint64>(bytes.size()))
                return QString();
            f.close();
            QProcess p;
            p.start("pdftotext", {"-layout", f.fileName(), "-"});
            p.waitForFinished();
            return QString::fromUtf8(p.readAllStandardOutput());
        };
        const QString a = pdfText(*whole, "whole.pdf"), b = pdfText(*parts, "parts.pdf");
        QVERIFY(a.count('\f') >= 4);
        QCOMPARE(b.split('\f'), a.split('\f'));
    }

    // A large steps table is painted by two PDF writers at once, the second
    // from a page break near its middle, and the parts joined: the pages
    // must be those one writer paints, page numbers and headers included.
    void twoWritersPaintTheSamePagesAsOne()
    {
        Plan plan = samplePlan("Two writers");
        const auto one = plan.steps;
        for (int copy = 0; copy < 60; ++copy) plan.steps.insert(plan.steps.end(), one.begin(), one.end());
        QTemporaryDir dir;
        std::vector<QString> files;
        std::vector<std::string> bytes;
        for (const PdfParts parts : {PdfParts::One, PdfParts::Two}) {
            auto pdf = sheetPdf(plan, {}, parts);
            QVERIFY2(pdf, pdf ? "" : pdf.error().c_str());
            bytes.push_back(*pdf);
            files.push_back(dir.filePath(QString("parts-%1.pdf").arg(files.size() + 1)));
            QFile f(files.back());
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(pdf->data(), static_cast<qint64>(pdf->size())) == static_cast<qint64>(pdf->size()));
        }
        QVERIFY2(bytes[0] != bytes[1], "the two-writer sheet was painted by one");
        const auto text = [](const QString& pdf) {
            QProcess p;
            p.start("pdftotext", {"-layout", pdf, "-"});
            p.waitForFinished();
            return QString::fromUtf8(p.readAllStandardOutput());
        };
        const QString oneText = text(files[0]), twoText = text(files[1]);
        QVERIFY2(oneText.count('\f') >= 8, qPrintable(QString("%1 pages").arg(oneText.count('\f'))));
        QCOMPARE(twoText.split('\f'), oneText.split('\f'));
        const std::vector<QImage> a = pages(files[0], 40), b = pages(files[1], 40);
        if (a.empty()) QSKIP("pdftoppm is not installed");
        QCOMPARE(b.size(), a.size());
        for (std::size_t i = 0; i < a.size(); ++i) QVERIFY2(a[i] == b[i], qPrintable(QString("page %1 differs").arg(i + 1)));
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
        const auto count = QRegularExpression("Pages:\\s+(\\d+)").match(QString::fromUtf8(info.readAllStandardOutput()));
        QVERIFY(count.hasMatch() && count.captured(1).toInt() >= 2);
        for (int page = 1; page <= count.captured(1).toInt(); ++page) {
            QProcess text;
            text.start("pdftotext", {"-f", QString::number(page), "-l", QString::number(page), pdf, "-"});
            QVERIFY(text.waitForFinished());
            const QString words = QString::fromUtf8(text.readAllStandardOutput());
            QVERIFY2(words.contains(QString("page %1").arg(page)), qPrintable(words.left(300)));
            // Every page the steps reach has the header; the last may hold only
            // what follows the table (the rows grow with wrapped tool names).
            const bool steps = words.contains("Pilot hole") || words.contains("Roughing");
            QVERIFY2(words.contains("S rpm") == steps && (steps || page == count.captured(1).toInt()),
                     qPrintable(words.left(300)));
        }
        // Every page's table is ruled: a line under every row, and the table's
        // left and right rules run unbroken from the header to the last row
        // (the body's rules are drawn once per page, not cell by cell).
        const std::vector<QImage> shown = pages(pdf, 100);
        if (shown.empty()) QSKIP("pdftoppm is not installed");
        for (std::size_t page = 0; page < shown.size(); ++page) {
            const QImage& im = shown[page];
            const auto dark = [&](int x, int y) { return qGray(im.pixel(x, y)) < 160; };
            // Horizontal rules: rows dark over most of the page's width.
            std::vector<int> rules;
            for (int y = 0; y < im.height(); ++y) {
                int n = 0;
                for (int x = 0; x < im.width(); ++x) n += dark(x, y);
                if (n > im.width() * 3 / 4 && (rules.empty() || y > rules.back() + 1)) rules.push_back(y);
            }
            const auto rowsOn = [&](std::size_t p) {  // the step rows pdftotext reads on page p (from 0)
                QProcess text;
                text.start("pdftotext", {"-layout", "-f", QString::number(p + 1), "-l", QString::number(p + 1), pdf, "-"});
                text.waitForFinished();
                return QString::fromUtf8(text.readAllStandardOutput()).split('\n').filter(QRegularExpression("^\\s*\\d+\\s+\\d")).size();
            };
            const auto rows = rowsOn(page);
            if (rows == 0 && page + 1 == shown.size()) continue;  // after the table (checked above)
            QVERIFY2(rows > 0 && static_cast<int>(rules.size()) >= rows + 1,
                     qPrintable(QString("page %1: %2 step rows, %3 rules").arg(page + 1).arg(rows).arg(rules.size())));
            // The outer rules: on a page the steps fill (all but the last), a
            // column dark from the first horizontal rule to the last.
            if (page + 1 == shown.size() || rowsOn(page + 1) == 0) continue;
            const std::size_t last = rules.size() - 1;
            const auto unbroken = [&](int x) {
                for (int y = rules.front(); y <= rules[last]; ++y)
                    if (!dark(x, y) && !(x > 0 && dark(x - 1, y)) && !(x + 1 < im.width() && dark(x + 1, y))) return false;
                return true;
            };
            int left = -1, right = -1;
            for (int x = 0; x < im.width() && left < 0; ++x)
                if (unbroken(x)) left = x;
            for (int x = im.width() - 1; x >= 0 && right < 0; --x)
                if (unbroken(x)) right = x;
            QVERIFY2(left >= 0 && right - left > im.width() / 2,
                     qPrintable(QString("page %1: outer rules at %2 and %3 between y %4 and %5")
                                    .arg(page + 1).arg(left).arg(right).arg(rules.front()).arg(rules[last])));
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
