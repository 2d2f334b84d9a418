// A lathe job drawn (under Xvfb): `taiwa render` of every lathe sample, the
// part revolved about the spindle (front view: Z to the right, X up), the
// grinding stock in the machined colour, its silhouette as long and as
// thick as the part; and `--view profile`, the station's profile view
// painted offscreen, with the profile and the deformed profile in it.
#include "support/support.h"
#include "viz/palette.h"

#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <vector>

using namespace taiwa;
using namespace taiwa::test;

class TestRenderLathe : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QImage render(const QString& sample, const QStringList& extra)
    {
        const QString out = dir_.filePath(sample + extra.join("") + ".png");
        const auto r = runTaiwa(QStringList{"render", sourcePath("resources/samples/" + sample + ".taiwa"), "--out", out,
                                            "--tools", dir_.filePath("tools.sqlite")} + extra);
        if (r.exitCode != 0) qWarning("%s", qPrintable(r.err));
        return QImage(out);
    }

private slots:
    void everyLatheSampleRenders()
    {
        for (const QString& s : QDir(sourcePath("resources/samples")).entryList({"lathe-*.taiwa"})) {
            const QImage img = render(s.chopped(6), {});
            QVERIFY2(!img.isNull(), qPrintable(s));
            QCOMPARE(img.size(), QSize(800, 600));
        }
    }

    // The front view of the drive shaft: the ground seat (Ø30.6) in the
    // machined colour, the collar Ø46 the tallest part of the silhouette:
    // their heights in the picture as 46 to 30.6.
    void partIsRevolvedWithItsGrindingStockInColour()
    {
        const QImage img = render("lathe-shaft-grinding", {"--view", "front"});
        QVERIFY(!img.isNull());
        int green = 0, tallest = 0;
        std::vector<int> seat;  // lit heights of the columns through the ground seat
        for (int x = 0; x < img.width(); ++x) {
            int lit = 0, greens = 0;
            for (int y = 0; y < img.height(); ++y) {
                const QColor c = img.pixelColor(x, y);
                const bool isGreen = c.green() > c.red() + 30 && c.green() > c.blue() + 10;
                greens += isGreen;
                if (isGreen || c.lightness() > 110) ++lit;  // background and the glass bar are darker
            }
            green += greens;
            tallest = std::max(tallest, lit);
            if (lit > 0 && greens > lit * 3 / 4) seat.push_back(lit);
        }
        QVERIFY2(green > img.width() * img.height() / 50, qPrintable(QString::number(green)));
        QVERIFY2(seat.size() > 50, qPrintable(QString::number(seat.size())));
        std::nth_element(seat.begin(), seat.begin() + seat.size() / 2, seat.end());
        const double ratio = double(tallest) / seat[seat.size() / 2];
        QVERIFY2(ratio > 46 / 30.6 - 0.12 && ratio < 46 / 30.6 + 0.12, qPrintable(QString::number(ratio)));
    }

    // A selected turning step (front view): the bar as that step leaves it,
    // half revolved behind the section, and the step's path in the section
    // in the feed colour. After roughing (step 2) the silhouette is the
    // roughed stock; after grooving (step 4) the groove cuts a notch into it
    // and the blade's plunges are drawn in it.
    void selectedStepShowsTheStockAfterItAndItsPath()
    {
        const auto pixelsOf = [](const QImage& img, viz::Rgb colour) {
            int n = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x) {
                    const QColor c = img.pixelColor(x, y);
                    n += std::abs(c.red() - colour.r) < 40 && std::abs(c.green() - colour.g) < 40 &&
                         std::abs(c.blue() - colour.b) < 40;
                }
            return n;
        };
        const auto feedPixels = [&](const QImage& img) { return pixelsOf(img, viz::palette::kFeed); };
        const auto litHeight = [](const QImage& img, int x) {
            int lit = 0;
            for (int y = 0; y < img.height(); ++y) lit += img.pixelColor(x, y).lightness() > 110;
            return lit;
        };
        const QImage rough = render("lathe-grooved-shaft", {"--view", "front", "--step", "2"});
        const QImage groove = render("lathe-grooved-shaft", {"--view", "front", "--step", "4"});
        const QImage whole = render("lathe-grooved-shaft", {"--view", "front"});
        QVERIFY(!rough.isNull() && !groove.isNull() && !whole.isNull());
        QVERIFY2(feedPixels(rough) > 200, qPrintable(QString::number(feedPixels(rough))));  // the passes
        QVERIFY2(feedPixels(groove) > 20, qPrintable(QString::number(feedPixels(groove))));  // the plunges
        QVERIFY2(feedPixels(whole) < 20, qPrintable(QString::number(feedPixels(whole))));  // no step: the part alone
        // The step's tool in the section at the path's start: the blade over
        // the groove, the roughing insert; none with no step selected.
        QVERIFY2(pixelsOf(groove, viz::palette::kTool) > 300, qPrintable(QString::number(pixelsOf(groove, viz::palette::kTool))));
        QVERIFY2(pixelsOf(rough, viz::palette::kTool) > 100, qPrintable(QString::number(pixelsOf(rough, viz::palette::kTool))));
        QCOMPARE(pixelsOf(whole, viz::palette::kTool), 0);
        // The groove's notch: some column lit lower after grooving than after roughing.
        int notch = 0;
        for (int x = 0; x < groove.width(); ++x) notch = std::max(notch, litHeight(rough, x) - litHeight(groove, x));
        QVERIFY2(notch > 10, qPrintable(QString::number(notch)));
    }

    void profileViewIsPaintedOffscreen()
    {
        const QImage img = render("lathe-both-ground", {"--view", "profile", "--size", "900x400"});
        QVERIFY(!img.isNull());
        QCOMPARE(img.size(), QSize(900, 400));
        int profile = 0, deformed = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QColor c = img.pixelColor(x, y);
                if (c == QColor(0x1d, 0x35, 0x57)) ++profile;
                if (c.red() > 150 && c.green() < 90 && c.blue() < 90) ++deformed;
            }
        QVERIFY2(profile > 300, qPrintable(QString::number(profile)));
        QVERIFY2(deformed > 100, qPrintable(QString::number(deformed)));
        const auto r = runTaiwa({"render", sourcePath("resources/samples/plate.taiwa"), "--out", dir_.filePath("p.png"),
                                 "--view", "profile", "--tools", dir_.filePath("tools.sqlite")});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QString("taiwa: render: --view profile draws turned profiles; this job has none\n"));
    }
};

QTEST_MAIN(TestRenderLathe)
#include "test_render_lathe.moc"
