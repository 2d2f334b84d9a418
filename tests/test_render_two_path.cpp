// Both turrets' tools in the station's 3-D view (under X: xvfb-run, the xcb
// platform; docs/two-path-lathe.md "In the station"): the two-path cylinder
// sample opened, a block of the balanced roughing clicked in the timeline
// chart draws path 1's tool and path 2's where core's timeline has them at
// that block's cut (verify/two_path_timeline.h toolPlaces), path 2's below
// the spindle axis (its X mirrored) in its turret's colour, path 1's above
// in its own; another block moves both; a step only path 1 runs, and a
// one-path lathe job, show one tool and none in path 2's colour. The GUI
// tests (test_gui_*) run offscreen without OpenGL and have no 3-D view.
#include "export/two_path_sheet.h"
#include "machine/machine.h"
#include "support/images.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/preview_widget.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/two_path_chart.h"
#include "ui/two_path_views.h"
#include "viz/palette.h"
#include "viz/scene.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

// Pixels within `tol` of a colour above and below the image row `axis`.
struct Split {
    int above = 0, below = 0;
};
Split pixelsOf(const QImage& img, viz::Rgb colour, double axis, int tol = 40)
{
    Split s;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            if (test::near(img.pixel(x, y), colour, tol)) (y < axis ? s.above : s.below) += 1;
    return s;
}

bool near(const Point3& a, const Point3& b) { return std::abs(a.x - b.x) < 1e-6 && std::abs(a.y - b.y) < 1e-6 && std::abs(a.z - b.z) < 1e-6; }

}  // namespace

class TestRenderTwoPath : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::unique_ptr<StationWindow> w_;

    PreviewWidget* preview() const { return w_->preview(); }
    const viz::Scene& scene() const { return preview()->scene(); }
    QImage frame() const { return preview()->grabImage().convertToFormat(QImage::Format_RGB32); }
    // The image row of the spindle axis under the tools (front view: Z to the right, X up).
    double axisRow(const QImage& img, const Point3& at) const
    {
        return scene().toPixel({at.x, 0.0, 0.0}, img.width(), img.height())[1];
    }
    void clickCut(int block)
    {
        auto* chart = w_->findChild<TwoPathChart*>("paths.chart");
        QVERIFY(chart && chart->isVisibleTo(w_.get()));
        bool clicked = false;
        for (const TwoPathChart::Bar& b : chart->bars())
            if (b.stretch.kind == TimelineStretch::Cut && b.stretch.block == block && !clicked) {
                QTest::mouseClick(chart, Qt::LeftButton, {}, b.rect.center().toPoint());
                clicked = true;
            }
        QVERIFY(clicked);
        QCOMPARE(chart->selectedBlock(), block);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        w_ = std::make_unique<StationWindow>();
        w_->resize(1600, 1000);
        QVERIFY(test::showSettled(*w_, "resources/samples/lathe-two-path-cylinder.taiwa"));
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        QVERIFY2(preview(), "the station has no 3-D preview: OpenGL missing under this display?");
        preview()->setView(viz::ViewPreset::Front);
    }
    void cleanupTestCase() { w_.reset(); }

    void chosenBlockDrawsBothTurretsTools()
    {
        const Plan& plan = *w_->planRunner()->fullPlan();
        const auto balanced = balancedRoughing(plan);
        QVERIFY(balanced && balanced->cut && *balanced->cut);
        const BalancedCut& cut = **balanced->cut;
        const ToolPlaces places = toolPlaces(cut, *findMachine(plan.mmJob.machine));
        const auto& shown = w_->twoPathViews()->shown();
        QVERIFY(shown);
        // Where core has each path's tool when the block's path starts its cut, in the view (path 2's radius below the axis).
        const auto expected = [&](int block) {
            const auto& at = places.afterMove.at(static_cast<std::size_t>(shown->cutMoveOf(block)));
            return std::vector<Point3>{{at[0].z, 0.0, at[0].r}, {at[1].z, 0.0, -at[1].r}};
        };
        const int second = cut.paths[1].blocks.at(0).number, fourth = cut.paths[1].blocks.at(1).number;

        clickCut(second);
        QCOMPARE(scene().selectedStep(), static_cast<int>(balanced->step));
        std::vector<Point3> atSecond = scene().turretToolPositions();
        QCOMPARE(atSecond.size(), std::size_t(2));
        for (std::size_t p = 0; p < 2; ++p)
            QVERIFY2(near(atSecond[p], expected(second)[p]),
                     qPrintable(QString("path %1 at %2 %3").arg(p + 1).arg(atSecond[p].x).arg(atSecond[p].z)));
        QVERIFY(atSecond[0].z > 0 && atSecond[1].z < 0);  // on either side of the axis
        QVERIFY(scene().toolPosition() && near(*scene().toolPosition(), atSecond[0]));

        // The picture: path 2's colour below the axis only, path 1's above.
        QImage img = frame();
        const double axis = axisRow(img, atSecond[1]);
        const Split two = pixelsOf(img, viz::palette::kTool2, axis), one = pixelsOf(img, viz::palette::kTool, axis);
        QVERIFY2(two.below > 30 && two.above == 0, qPrintable(QString("path 2's colour: %1 above, %2 below").arg(two.above).arg(two.below)));
        QVERIFY2(one.above > 30 && one.below == 0, qPrintable(QString("path 1's colour: %1 above, %2 below").arg(one.above).arg(one.below)));

        // Another block: both tools moved, to core's places again.
        clickCut(fourth);
        const std::vector<Point3> atFourth = scene().turretToolPositions();
        QCOMPARE(atFourth.size(), std::size_t(2));
        for (std::size_t p = 0; p < 2; ++p) {
            QVERIFY(near(atFourth[p], expected(fourth)[p]));
            QVERIFY2(!near(atFourth[p], atSecond[p]), qPrintable(QString("path %1's tool did not move").arg(p + 1)));
        }

        // A step path 1 runs alone: its tool, none of path 2's.
        int alone = -1;
        for (std::size_t k = 0; k < plan.steps.size() && alone < 0; ++k)
            if (k != balanced->step && plan.steps[k].tool && turnOf(plan.steps[k])) alone = static_cast<int>(k);
        QVERIFY(alone >= 0);
        w_->stepPanel()->selectStep(alone);
        preview()->highlightMove(alone, -1);  // the step's tool at its start
        QCOMPARE(scene().selectedStep(), alone);
        QVERIFY(scene().turretToolPositions().empty());
        img = frame();
        QCOMPARE(pixelsOf(img, viz::palette::kTool2, axis).below + pixelsOf(img, viz::palette::kTool2, axis).above, 0);
        QVERIFY(pixelsOf(img, viz::palette::kTool, axis).above > 30);
    }

    // The control: a one-path lathe job's roughing shows its one tool, none in path 2's colour.
    void onePathJobShowsOneTool()
    {
        QVERIFY(test::showSettled(*w_, "resources/samples/lathe-turned-shaft.taiwa"));
        preview()->setView(viz::ViewPreset::Front);
        const Plan& plan = *w_->planRunner()->fullPlan();
        int rough = -1;
        for (std::size_t k = 0; k < plan.steps.size() && rough < 0; ++k)
            if (plan.steps[k].machiningType == MachiningType::TurnRoughing) rough = static_cast<int>(k);
        QVERIFY(rough >= 0);
        w_->stepPanel()->selectStep(rough);
        preview()->highlightMove(rough, 3);
        QVERIFY(scene().turretToolPositions().empty());
        QVERIFY(scene().toolPosition());
        const QImage img = frame();
        const double axis = axisRow(img, *scene().toolPosition());
        const Split two = pixelsOf(img, viz::palette::kTool2, axis), one = pixelsOf(img, viz::palette::kTool, axis);
        QCOMPARE(two.above + two.below, 0);
        QVERIFY2(one.above > 30 && one.below == 0, qPrintable(QString("%1 above, %2 below").arg(one.above).arg(one.below)));
    }
};

QTEST_MAIN(TestRenderTwoPath)
#include "test_render_two_path.moc"
