// `taiwa figure-from-dxf`, run as a real process: a drawing's contours as
// figure text on stdout that reads back to them, the summary on stderr,
// layers chosen, inch units, a gap (exit 2, reported), a file that is no DXF
// and bad options refused.
#include "support/support.h"

#include "figure/figure_eval.h"
#include "figure/figure_text.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <string>

using namespace taiwa::test;

namespace {

std::string line(const char* layer, double x1, double y1, double x2, double y2)
{
    return "0\nLINE\n8\n" + std::string(layer) + "\n10\n" + std::to_string(x1) + "\n20\n" + std::to_string(y1) +
           "\n30\n0\n11\n" + std::to_string(x2) + "\n21\n" + std::to_string(y2) + "\n31\n0\n";
}

// A 100 × 60 outline with its top right corner rounded (R20), a circle on
// layer HOLES, and on layer OPEN two lines 0.2 mm apart.
std::string drawing(int insunits = 4)
{
    return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n" + std::to_string(insunits) +
           "\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + line("OUTLINE", 0, 0, 100, 0) + line("OUTLINE", 100, 0, 100, 40) +
           "0\nARC\n8\nOUTLINE\n10\n80\n20\n40\n30\n0\n40\n20\n50\n0\n51\n90\n" + line("OUTLINE", 80, 60, 0, 60) +
           line("OUTLINE", 0, 60, 0, 0) + "0\nCIRCLE\n8\nHOLES\n10\n50\n20\n30\n30\n0\n40\n5\n" +
           line("OPEN", 0, 100, 50, 100) + line("OPEN", 50.2, 100, 80, 120) + "0\nENDSEC\n0\nEOF\n";
}

QString write(const QTemporaryDir& dir, const std::string& text)
{
    const QString path = dir.filePath("part.dxf");
    writeFile(path, text);
    return path;
}

// The text parsed and evaluated: its contours, or the first refusal.
taiwa::figure::Evaluation evaluated(const QString& text)
{
    const auto read = taiwa::figure::parseFigure(text.toStdString());
    if (!read.ok()) qWarning("%s", read.error->text().c_str());
    return taiwa::figure::evaluate(read.definitions);
}

}  // namespace

class TestCliDxf : public QObject {
    Q_OBJECT
private slots:
    void layersToFigureText()
    {
        QTemporaryDir dir;
        const QString dxf = write(dir, drawing());
        const auto r = runTaiwa({"figure-from-dxf", dxf, "--layers", "outline,Holes"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("part.dxf: 2 contours (2 closed, 0 open) on layers HOLES, OUTLINE, drawn in mm, "
                                "written in mm; 0 gaps, 0 branches"),
                 qPrintable(r.err));
        QVERIFY2(r.out.contains("K1 = CONTOUR/L1, L2, CCLW, C1, L3, L4\n") && r.out.contains("K2 = CONTOUR/CCLW, C2\n"),
                 qPrintable(r.out));
        const auto ev = evaluated(r.out);
        QVERIFY(ev.ok());
        QCOMPARE(ev.contours.size(), std::size_t{2});
        QCOMPARE(ev.contours[0].contour.segments.size(), std::size_t{5});
        QVERIFY(std::abs(ev.contours[0].contour.segments[2].end.x - 80) < 1e-9);
    }

    void inchesAreWrittenInMm()
    {
        QTemporaryDir dir;
        const QString dxf = write(dir, drawing(0));
        const auto r = runTaiwa({"figure-from-dxf", dxf, "--layers", "HOLES", "--units", "inch"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("POINT/1270, 762\n") && r.out.contains("RADIUS, 127\n"), qPrintable(r.out));
        QVERIFY2(r.err.contains("drawn in inch, written in mm"), qPrintable(r.err));
    }

    void aGapIsReportedWithExit2()
    {
        QTemporaryDir dir;
        const QString dxf = write(dir, drawing());
        const auto r = runTaiwa({"figure-from-dxf", dxf, "--layers", "OPEN"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("gap of 0.2 mm at (50.000, 100.000)"), qPrintable(r.err));
        QVERIFY2(r.err.contains("2 contours (0 closed, 2 open)"), qPrintable(r.err));
        QCOMPARE(evaluated(r.out).contours.size(), std::size_t{2});  // written all the same
        // A tolerance that spans it: one open contour, exit 0.
        const auto wide = runTaiwa({"figure-from-dxf", dxf, "--layers", "OPEN", "--gap", "0.5"});
        QCOMPARE(wide.exitCode, 0);
        QVERIFY2(wide.out.contains("K1 = CONTOUR/P1, L1, L2, P"), qPrintable(wide.out));
    }

    void refusals()
    {
        QTemporaryDir dir;
        const QString bad = dir.filePath("notes.dxf");
        writeFile(bad, "hello\nworld\n");
        const auto r = runTaiwa({"figure-from-dxf", bad});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("notes.dxf: "), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        const QString dxf = write(dir, drawing());
        const auto none = runTaiwa({"figure-from-dxf", dxf, "--layers", "NOSUCH"});
        QCOMPARE(none.exitCode, 2);
        QVERIFY2(none.err.contains("NOSUCH"), qPrintable(none.err));
        for (const QStringList& args :
             {QStringList{"figure-from-dxf"}, QStringList{"figure-from-dxf", dxf, "--gap", "wide"},
              QStringList{"figure-from-dxf", dxf, "--gap", "50"}, QStringList{"figure-from-dxf", dxf, "--layers", "A,,B"},
              QStringList{"figure-from-dxf", dxf, "--out", "x"}, QStringList{"figure-from-dxf", dxf, "--units", "m"}}) {
            const auto e = runTaiwa(args);
            QVERIFY2(e.exitCode == 2 && !e.err.isEmpty() && e.out.isEmpty(), qPrintable(args.join(' ') + ": " + e.err));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliDxf)
#include "test_cli_dxf.moc"
