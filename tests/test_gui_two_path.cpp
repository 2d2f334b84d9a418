// A two-path lathe job in the station (QTest on the offscreen platform,
// docs/two-path-lathe.md "In the station"): the sample
// lathe-two-path-taper.taiwa opened; the steps listed under the path that
// runs them (path 1 every step, path 2 the balanced roughing), each with its
// tool and time, each path's blocks under its roughing row; the timeline
// chart with both paths' cuts in their own lane and the waits as core's
// timeline has them (the code, the time the paths go on, the wait's colour
// drawn there in both lanes, not in the middle of a cut); both tapes in
// tabs, byte for byte the export's two programs; a block clicked in the
// chart chosen in the list and in path 2's tape, a path 2 line chosen in
// the tape chosen in the chart. A one-path lathe job shows none of it. The
// turrets' names in Japanese in a Japanese station (in English as the
// machine file has them). Both turrets' tools in the 3-D view, which this
// offscreen test has not: test_render_two_path.
// With TAIWA_SCREENSHOTS_DIR set (under xvfb-run, for the 3-D view) it
// writes docs/screenshots/two-path-station.png.
#include "export/two_path_export.h"
#include "machine/machine.h"
#include "post/dialect.h"
#include "support/speak.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "turning/balanced_roughing.h"
#include "ui/file_actions.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/station_window.h"
#include "ui/two_path_chart.h"
#include "ui/two_path_views.h"
#include "verify/two_path_timeline.h"

#include <QDir>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QTabWidget>
#include <QTextBlock>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <map>
#include <set>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

constexpr auto kTaper = "resources/samples/lathe-two-path-taper.taiwa";

// Whether the picture has the chart's wait colour within a pixel of the
// column x (a line at a fraction of a pixel), within the lane's height.
bool waitColourAt(const QImage& image, double x, const QRectF& lane)
{
    for (int column = static_cast<int>(std::floor(x)) - 1; column <= static_cast<int>(std::ceil(x)) + 1; ++column)
        for (int y = static_cast<int>(lane.top()) + 1; y < static_cast<int>(lane.bottom()); ++y) {
            const QColor c = image.pixelColor(std::clamp(column, 0, image.width() - 1), y);
            if (c.red() > 190 && c.green() < 100 && c.blue() < 100) return true;
        }
    return false;
}

}  // namespace

class TestGuiTwoPath : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void bothPathsInTheStation()
    {
        // Relative paths: the title and the picture name the sample as the project does.
        QDir::setCurrent(test::sourcePath(""));
        StationWindow w;
        w.resize(1600, 1000);
        w.show();
        QVERIFY(w.fileActions()->openPath(kTaper));
        test::settle(w);
        const std::shared_ptr<const Plan> plan = w.planRunner()->fullPlan();
        QVERIFY(plan);

        // What core computes, as the export and the sheet do.
        const Machine* machine = findMachine(plan->mmJob.machine);
        QVERIFY(machine && machine->layout.multiPath);
        std::size_t rough = plan->steps.size();
        for (std::size_t k = 0; k < plan->steps.size() && rough == plan->steps.size(); ++k)
            if (plan->steps[k].machiningType == MachiningType::TurnRoughing) rough = k;
        QVERIFY(rough < plan->steps.size());
        const auto cut = turning::balanceRoughing(turnOf(plan->steps[rough])->path, turnOf(plan->steps[rough])->cutting,
                                                  *machine, turning::balanceSettings(plan->mmJob.twoPath, true));
        QVERIFY(cut);
        QCOMPARE(cut->paths.size(), std::size_t(2));
        const Timeline timeline = runTimeline(*cut, *machine);
        QVERIFY(timeline.deadlocks.empty());

        // (1) The steps by path, shown.
        auto* byPath = w.findChild<QTreeWidget*>("paths.steps");
        QVERIFY2(byPath, "no step list by path");
        QVERIFY(byPath->isVisibleTo(&w));
        QCOMPARE(byPath->topLevelItemCount(), 2);
        for (int p = 0; p < 2; ++p) {
            QTreeWidgetItem* path = byPath->topLevelItem(p);
            QVERIFY2(path->text(0).contains(QString::fromStdString(machine->layout.multiPath->paths[static_cast<std::size_t>(p)].name)),
                     qPrintable(path->text(0)));
            QVERIFY2(path->text(0).contains(QStringLiteral("T%1").arg(plan->steps[rough].tool->toolId)), qPrintable(path->text(0)));
            std::vector<int> steps;
            for (int r = 0; r < path->childCount(); ++r) {
                QTreeWidgetItem* row = path->child(r);
                const int step = row->data(0, TwoPathSteps::kStepRole).toInt();
                steps.push_back(step);
                const Step& s = plan->steps[static_cast<std::size_t>(step)];
                QCOMPARE(row->text(TwoPathSteps::ToolName), QStringLiteral("T%1").arg(s.tool->toolId));
                QVERIFY2(!row->text(TwoPathSteps::Time).isEmpty(), qPrintable(row->text(0)));
                // The roughing's blocks of this path, and no other.
                std::vector<int> blocks, expected;
                for (int b = 0; b < row->childCount(); ++b) blocks.push_back(row->child(b)->data(0, TwoPathSteps::kBlockRole).toInt());
                if (step == static_cast<int>(rough))
                    for (const BalancedBlock& b : cut->paths[static_cast<std::size_t>(p)].blocks) expected.push_back(b.number);
                QCOMPARE(blocks, expected);
            }
            std::vector<int> expected;
            if (p == 0)
                for (int k = 0; k < static_cast<int>(plan->steps.size()); ++k) expected.push_back(k);
            else
                expected.push_back(static_cast<int>(rough));
            QCOMPARE(steps, expected);
        }
        auto* stepTabs = w.findChild<QTabWidget*>("steps.tabs");
        QVERIFY(stepTabs && stepTabs->tabBar()->isVisibleTo(&w));
        QCOMPARE(stepTabs->currentWidget(), byPath);

        // (2) The chart: each path's cuts in its lane, the waits where core has them.
        auto* chart = w.findChild<TwoPathChart*>("paths.chart");
        QVERIFY2(chart && chart->isVisibleTo(&w), "no timeline chart");
        std::map<int, std::size_t> cutLane;
        std::map<int, double> dwellOf;
        for (const TwoPathChart::Bar& b : chart->bars()) {
            QVERIFY(chart->laneOf(b.path).contains(b.rect.center()));
            if (b.stretch.kind == TimelineStretch::Cut) cutLane[b.stretch.block] = b.path;
            if (b.stretch.kind == TimelineStretch::In && b.stretch.dwell > 0) dwellOf[b.stretch.block] = b.stretch.dwell;
        }
        int followers = 0;
        for (const BalancedPath& p : cut->paths)
            for (const BalancedBlock& b : p.blocks) {
                QCOMPARE(cutLane.at(b.number), b.path);
                if (b.dwellSeconds > 0) {
                    ++followers;
                    QCOMPARE(dwellOf.at(b.number), b.dwellSeconds);
                }
            }
        QVERIFY(followers > 0);
        QCOMPARE(cutLane.size(), static_cast<std::size_t>(cut->blockCount));
        // The waits: each code where the paths go on from it on core's timeline.
        std::map<int, double> waits;
        for (const TimelineBlock& b : timeline.blocks)
            if (b.wait) waits[*b.wait] = std::max(waits[*b.wait], b.waitTo);
        QVERIFY(cut->paths[0].endWait);
        waits[*cut->paths[0].endWait] = *std::max_element(timeline.pathEnd.begin(), timeline.pathEnd.end());
        QVERIFY2(waits.size() >= 3, "the taper waits between the first and the last meeting");
        const auto lines = chart->waitLines();
        QCOMPARE(lines.size(), waits.size());
        const QImage image = chart->grab().toImage();
        for (const auto& l : lines) {
            QVERIFY2(waits.count(l.code), qPrintable(QStringLiteral("M%1").arg(l.code)));
            QVERIFY2(std::abs(l.seconds - waits.at(l.code)) < 1e-9,
                     qPrintable(QStringLiteral("M%1 at %2 s, core %3 s").arg(l.code).arg(l.seconds).arg(waits.at(l.code))));
            for (std::size_t p = 0; p < 2; ++p)
                QVERIFY2(waitColourAt(image, l.x, chart->laneOf(p)),
                         qPrintable(QStringLiteral("M%1 not drawn on path %2").arg(l.code).arg(p + 1)));
        }
        // The negative control: the middle of a cut has no wait drawn.
        const TimelineBlock& first = *std::find_if(timeline.blocks.begin(), timeline.blocks.end(), [](const auto& b) { return b.number == 1; });
        QVERIFY(!waitColourAt(image, chart->xOf((first.cutStart + first.cutEnd) / 2), chart->laneOf(0)));

        // (4) Both tapes, as the export writes them.
        auto* tapes = w.findChild<QTabWidget*>("nc.tapes");
        QVERIFY2(tapes && tapes->count() == 2 && tapes->isTabVisible(1) && tapes->tabBar()->isVisibleTo(&w), "no tab per path");
        const auto files = twoPathTapes(*plan, w.planRunner()->dialect().toStdString(), std::nullopt, 1000,
                                        w.fileActions()->stem().toStdString());
        QVERIFY(files && *files);
        std::map<std::string, std::string> byName((**files).begin(), (**files).end());
        const std::string ext = "." + post::findDialect(w.planRunner()->dialect().toStdString())->fileExtension;
        auto* path2 = w.findChild<NcView*>("paths.tape");
        QVERIFY(path2);
        QCOMPARE(tapes->widget(0), static_cast<QWidget*>(w.ncView()));
        QCOMPARE(tapes->widget(1), static_cast<QWidget*>(path2));
        QCOMPARE(w.ncView()->text()->toPlainText().trimmed(), QString::fromStdString(byName.at(".p1" + ext)).trimmed());
        QCOMPARE(path2->text()->toPlainText().trimmed(), QString::fromStdString(byName.at(".p2" + ext)).trimmed());

        // A block clicked in the chart: chosen in the list and in path 2's tape.
        const BalancedBlock& second = cut->paths[1].blocks.front();
        for (const TwoPathChart::Bar& b : chart->bars())
            if (b.stretch.kind == TimelineStretch::Cut && b.stretch.block == second.number)
                QTest::mouseClick(chart, Qt::LeftButton, {}, b.rect.center().toPoint());
        QCOMPARE(chart->selectedBlock(), second.number);
        QCOMPARE(tapes->currentIndex(), 1);
        QCOMPARE(byPath->currentItem()->data(0, TwoPathSteps::kBlockRole).toInt(), second.number);
        QCOMPARE(path2->currentSource().step, static_cast<int>(rough));
        // The block's first line of its cut: its wait, its dwell (path 2 follows), then the cut's feed.
        QCOMPARE(path2->currentSource().move, w.twoPathViews()->shown()->cutMoveOf(second.number));
        QString upToCut;
        for (QTextBlock b = path2->text()->textCursor().block(); b.isValid() && !b.text().contains("G1"); b = b.next()) upToCut += b.text() + "\n";
        QVERIFY2(upToCut.contains("M66 P0") && upToCut.contains(QStringLiteral("G4 P%1").arg(second.dwellSeconds)), qPrintable(upToCut));
        // A line of path 2's next block chosen in its tape: that block in the chart.
        const BalancedBlock& fourth = cut->paths[1].blocks.at(1);
        const QStringList p2 = path2->text()->toPlainText().split('\n');
        int line = -1;
        for (int i = 0; i < p2.size() && line < 0; ++i) {
            QTextCursor c(path2->text()->document()->findBlockByNumber(i));
            path2->text()->setTextCursor(c);
            const BlockSource s = path2->currentSource();
            if (s.step == static_cast<int>(rough) && chart->selectedBlock() == fourth.number) line = i;
        }
        QVERIFY2(line >= 0, "no line of path 2's second block chose it in the chart");
        QCOMPARE(byPath->currentItem()->data(0, TwoPathSteps::kBlockRole).toInt(), fourth.number);

        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (!out.isEmpty()) {
            QTest::mouseClick(chart, Qt::LeftButton, {}, [&] {
                for (const TwoPathChart::Bar& b : chart->bars())
                    if (b.stretch.kind == TimelineStretch::Cut && b.stretch.block == second.number) return b.rect.center().toPoint();
                return QPoint();
            }());
            QCoreApplication::processEvents();
            QDir().mkpath(out);
            QVERIFY(grabWithPreview(&w).save(QDir(out).filePath("two-path-station.png")));
        }

        // A one-path lathe job: none of it.
        QVERIFY(w.fileActions()->openPath("resources/samples/lathe-turned-shaft.taiwa"));
        test::settle(w);
        QVERIFY(!chart->isVisibleTo(&w));
        QVERIFY(!tapes->tabBar()->isVisibleTo(&w));
        QVERIFY(!tapes->isTabVisible(1));
        QVERIFY(!stepTabs->isTabVisible(1));
        QCOMPARE(stepTabs->currentIndex(), 0);
    }

    // The turrets' names from the machine file, in the station's language
    // where the catalogue knows them (the shipped machine's), in the steps by
    // path and the chart's lanes; in English as the file has them; a shop's
    // own name as it is.
    void turretNamesInTheStationsLanguage()
    {
        const auto names = [](StationWindow& w) {
            QStringList out;
            auto* byPath = w.findChild<QTreeWidget*>("paths.steps");
            auto* chart = w.findChild<TwoPathChart*>("paths.chart");
            for (int p = 0; p < byPath->topLevelItemCount(); ++p)
                out << byPath->topLevelItem(p)->text(0) << chart->laneLabel(static_cast<std::size_t>(p));
            return out;
        };
        test::speak("ja");
        {
            StationWindow w;
            QVERIFY(test::showSettled(w, kTaper));
            const QStringList ja = names(w);
            QCOMPARE(ja.size(), 4);
            for (int i : {0, 1}) QVERIFY2(ja[i].contains(QStringLiteral("上タレット")) && !ja[i].contains("turret"), qPrintable(ja[i]));
            for (int i : {2, 3}) QVERIFY2(ja[i].contains(QStringLiteral("下タレット")) && !ja[i].contains("turret"), qPrintable(ja[i]));
            QCOMPARE(localPathName("front slide"), QString("front slide"));
        }
        test::speak("en");
        StationWindow w;
        QVERIFY(test::showSettled(w, kTaper));
        const QStringList en = names(w);
        QCOMPARE(en.size(), 4);
        for (int i : {0, 1}) QVERIFY2(en[i].contains("(upper turret)"), qPrintable(en[i]));
        for (int i : {2, 3}) QVERIFY2(en[i].contains("(lower turret)"), qPrintable(en[i]));
    }
};

QTEST_MAIN(TestGuiTwoPath)
#include "test_gui_two_path.moc"
