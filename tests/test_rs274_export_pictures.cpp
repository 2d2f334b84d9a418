// The sheet's pictures without a display (issue 35 item 2, issue 34 item
// 1): `taiwa export` with no X display (DISPLAY unset, Qt offscreen) writes
// the setup picture and one picture per step into the sheet (HTML and PDF),
// its tape runs through LinuxCNC's rs274, and the export folder holds its
// files and nothing else (no lock file). The pictures themselves, drawn by
// the core: dark on light, the step's cut in its own colour, a lathe job's
// from its turned section.
#include "job/job_file.h"
#include "picture/image.h"
#include "picture/pictures.h"
#include "pipeline/pipeline.h"
#include "support/rs274.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QGuiApplication>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;

namespace {

Plan planOf(const QString& sample)
{
    auto read = readJobFile(test::sourcePath("resources/samples/" + sample).toStdString());
    if (!read.job) throw std::runtime_error("cannot read " + sample.toStdString());
    return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
}

// How many pixels of the picture are near `c` (each channel within 40).
int near(const picture::Image& im, picture::Colour c)
{
    int n = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const picture::Colour p = im.at(x, y);
            n += std::abs(p.r - c.r) < 40 && std::abs(p.g - c.g) < 40 && std::abs(p.b - c.b) < 40;
        }
    return n;
}

// Orange-ish: the colour of what a step removed, however lit.
int removedPixels(const picture::Image& im)
{
    int n = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const picture::Colour p = im.at(x, y);
            n += p.r > p.g + 30 && p.g > p.b + 30;
        }
    return n;
}

double meanLuminance(const picture::Image& im)
{
    double sum = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const picture::Colour p = im.at(x, y);
            sum += 0.3 * p.r + 0.59 * p.g + 0.11 * p.b;
        }
    return sum / (im.width * im.height);
}

}  // namespace

class TestExportPictures : public QObject {
    Q_OBJECT

private slots:
    void headlessExportHasTheFullSheet()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const auto r = test::runTaiwa({"export", test::sourcePath("resources/samples/plate.taiwa"), "--out", out},
                                      {"DISPLAY=", "QT_QPA_PLATFORM=offscreen", "XDG_RUNTIME_DIR=" + dir.filePath("run")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(!r.err.contains("pictures missing"), qPrintable(r.err));
        const Plan plan = planOf("plate.taiwa");
        const int steps = static_cast<int>(plan.steps.size());
        QVERIFY(steps >= 4);

        // The HTML sheet: the setup's picture and one per step, none missing.
        const QString html = QString::fromStdString(test::readFile(QDir(out).filePath("plate.sheet.html")));
        QCOMPARE(html.count("data:image/png;base64,"), 1 + steps);
        QVERIFY(!html.contains("No pictures"));
        // The PDF: the same pictures (pdfimages lists each image once), on more pages than the 2 without them.
        QProcess images;
        images.start("pdfimages", {"-list", QDir(out).filePath("plate.sheet.pdf")});
        QVERIFY(images.waitForFinished(30000));
        const QStringList rows = QString::fromUtf8(images.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.filter(QRegularExpression("^\\s*\\d+\\s+\\d+\\s+image\\s+320\\s+240")).size(), 1 + steps);
        QProcess info;
        info.start("pdfinfo", {QDir(out).filePath("plate.sheet.pdf")});
        QVERIFY(info.waitForFinished(30000));
        const auto pages = QRegularExpression("Pages:\\s+(\\d+)").match(QString::fromUtf8(info.readAllStandardOutput()));
        QVERIFY(pages.hasMatch());
        QVERIFY2(pages.captured(1).toInt() > 2, qPrintable(pages.captured(1)));

        // Nothing but the export's files: no lock file, no journal, no temporaries.
        const QStringList files = QDir(out).entryList(QDir::Files | QDir::Hidden | QDir::System);
        QCOMPARE(files, (QStringList{"plate.nc", "plate.sheet.html", "plate.sheet.pdf", "plate.steps.json", "plate.tape.txt"}));
        // The lock was taken in the runtime folder given.
        QVERIFY(!QDir(dir.filePath("run/taiwa-locks")).entryList({"export-*.lock"}, QDir::Files).isEmpty());

        // The tape it wrote, run through LinuxCNC's interpreter.
        const auto run = test::runRs274(test::readFile(QDir(out).filePath("plate.nc")));
        QVERIFY2(run.ok, qPrintable(run.errors));
    }

    void millingPicturesAreDarkOnLightAndShowTheCut()
    {
        const Plan plan = planOf("plate.taiwa");
        const auto pictures = picture::stepPictures(plan, picture::kSheetWidth, picture::kSheetHeight, 1000);
        QVERIFY2(pictures, pictures ? "" : pictures.error().c_str());
        QCOMPARE(pictures->size(), plan.steps.size());
        int showingCut = 0;
        for (std::size_t k = 0; k < pictures->size(); ++k) {
            const picture::Image& im = (*pictures)[k].image;
            QCOMPARE(im.width, 320);
            QCOMPARE(im.height, 240);
            QCOMPARE(im.at(0, 0), picture::colours::kBackground);  // the corner: off the stock
            QVERIFY2(meanLuminance(im) > 170, qPrintable(QString::number(meanLuminance(im))));
            // Its feed moves over the stock, in the path's colour.
            QVERIFY2(near(im, picture::colours::kPath) > 8, qPrintable(QString("step %1").arg(k + 1)));
            showingCut += removedPixels(im) > 20;
        }
        // What the steps cut, in the removed colour (a wall finish of a tenth
        // of a millimetre may stay within the picture's cells: nearly all, not all).
        QVERIFY2(showingCut >= static_cast<int>(pictures->size()) * 3 / 4, qPrintable(QString::number(showingCut)));
        // The stock changes from step to step.
        QVERIFY((*pictures)[0].image.rgba != (*pictures)[pictures->size() - 1].image.rgba);
        const picture::Picture setup = picture::setupPicture(plan, 320, 240);
        QVERIFY(near(setup.image, picture::colours::kStock) > 2000);   // the block, lit
        QVERIFY(setup.image.at(0, 0) == picture::colours::kBackground);
        QCOMPARE(setup.labels.size(), std::size_t{4});                  // X, Y, Z and the work offset
        QCOMPARE(setup.labels.back().text, plan.job.workOffset);
    }

    void lathePicturesComeFromTheTurnedSection()
    {
        const Plan plan = planOf("lathe-turned-shaft.taiwa");
        QVERIFY(plan.mmJob.bar);
        const auto pictures = picture::stepPictures(plan, 320, 240, 1000);
        QVERIFY(pictures);
        QCOMPARE(pictures->size(), plan.steps.size());
        int showingCut = 0;
        for (const auto& p : *pictures) {
            QVERIFY(meanLuminance(p.image) > 150);
            showingCut += removedPixels(p.image) > 20;
        }
        QVERIFY2(showingCut >= 2, qPrintable(QString::number(showingCut)));
        const picture::Picture setup = picture::setupPicture(plan, 320, 240);
        QCOMPARE(setup.labels.size(), std::size_t{3});  // Z, X and the work offset
        QVERIFY(meanLuminance(setup.image) > 120);
    }
};

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestExportPictures t;
    return QTest::qExec(&t, argc, argv);
}

#include "test_rs274_export_pictures.moc"
