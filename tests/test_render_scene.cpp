// The 3-D preview scene, rendered offscreen (`taiwa render`'s code): a
// hand-built plan (support/hand_plan.h) and the sample m4-standard.taiwa.
// Pixels at known world positions show the path, rapid, tool and stock
// colours, pixels off the stock the background; views and step selection
// change the image; the simulated stock is cut after its step and not
// before; the stock surface is closed and merged; picking finds the move
// under a pixel; no display is an error message. The same scene inside the
// Qt widget: test_render_preview_widget. A section plane shows the face it
// cuts; the verification's colour map shows gouges and what is at size.
// The wheel zooms about the pointer, "Zoom to step" frames the selected
// step, the paths switch hides every path. Needs an X display (xvfb-run -a).
#include "job/job_file.h"
#include "sim/stock_simulation.h"
#include "support/hand_plan.h"
#include "support/images.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "verify/deviation.h"
#include "ui/preview_widget.h"
#include "viz/palette.h"
#include "viz/render.h"
#include "viz/scene.h"
#include "viz/solids.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>

#include <cstdlib>

using namespace taiwa;
using namespace taiwa::test;
using namespace taiwa::viz;
using taiwa::ui::PreviewWidget;

namespace {

// Where world points land in the offscreen image made with these options.
std::array<double, 2> pixelOf(const Plan& plan, ViewPreset view, Point3 p)
{
    Scene s;
    s.setPlan(std::make_shared<const Plan>(plan));
    s.setView(view, static_cast<double>(kW) / kH);
    return s.toPixel(p, kW, kH);
}

// The midpoint of a straight feed at the step's cut depth, at least 5 mm
// long and a tool diameter away from the path start (where the tool stands).
std::optional<Point3> feedPointOf(const Plan& plan, const Step& step)
{
    const Tool* tool = plan.tool(step.tool->toolId);
    Point3 from = step.path->start;
    for (const Move& m : step.path->moves) {
        const Point3 to = m.end;
        const Point3 mid{(from.x + to.x) / 2, (from.y + to.y) / 2, to.z};
        if (m.kind == MoveKind::Feed && std::abs(from.z - to.z) < 1e-6 && std::abs(to.z + millingOf(step).cutDepth) < 1e-6 &&
            std::hypot(to.x - from.x, to.y - from.y) > 5 &&
            std::hypot(mid.x - step.path->start.x, mid.y - step.path->start.y) > tool->diameter)
            return mid;
        from = to;
    }
    return std::nullopt;
}

}  // namespace

class TestRenderScene : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    Plan plan_ = handPlan();

    QImage render(RenderOptions o, const QString& name)
    {
        const QString path = dir_.filePath(name);
        const auto drawn = renderToPng(plan_, o, path.toStdString());
        if (!drawn) qWarning("%s", drawn.error().c_str());
        if (const QByteArray shots = qgetenv("TAIWA_SCREENSHOTS"); drawn && !shots.isEmpty()) {
            QFile::remove(shots + "/" + name);
            QFile::copy(path, shots + "/" + name);
        }
        return drawn ? QImage(path).convertToFormat(QImage::Format_RGB32) : QImage();
    }

private slots:
    void topViewShowsPathsToolAndBackground()
    {
        RenderOptions o;
        o.view = ViewPreset::Top;
        const QImage img = render(o, "top.png");
        QCOMPARE(img.size(), QSize(kW, kH));
        // Off the stock: exactly the background.
        QVERIFY(near(img.pixel(3, 3), palette::kBackground, 0));
        QVERIFY(near(img.pixel(qRound(pixelOf(plan_, o.view, {-3, 40, 0})[0]), kH / 2), palette::kBackground, 0));
        // The pocket centre (50, 40) lies on the slot: the feed colour.
        QVERIFY(colourNear(img, pixelOf(plan_, o.view, {50, 40, -5}), palette::kFeed));
        // The rapid away at safe height.
        QVERIFY(colourNear(img, pixelOf(plan_, o.view, {82.5, 55, 5}), palette::kRapid));
        // The translucent stock block tints the background inside the stock.
        const auto inStock = pixelOf(plan_, o.view, {8, 8, 0});
        QVERIFY(!near(img.pixel(int(inStock[0]), int(inStock[1])), palette::kBackground, 2));
        // The tool (the drill of the first step) stands over the path start.
        const auto start = pixelOf(plan_, o.view, {40, 40, 5});
        QVERIFY2(goldish(img.pixel(int(start[0]), int(start[1]))), qPrintable(QString::number(img.pixel(int(start[0]), int(start[1])), 16)));
    }

    void viewsAndSelectionChangeTheImage()
    {
        RenderOptions o;
        o.view = ViewPreset::Top;
        const QImage top = render(o, "top.png");
        o.view = ViewPreset::Iso;
        const QImage iso = render(o, "iso.png");
        o.view = ViewPreset::Front;
        const QImage front = render(o, "front.png");
        QVERIFY(differingPixels(top, iso) > kW * kH / 20);
        QVERIFY(differingPixels(iso, front) > kW * kH / 20);

        // Step 0 selected: the roughing path is dimmed, the drill shown.
        o.view = ViewPreset::Top;
        o.step = 0;
        const QImage drillOnly = render(o, "step0.png");
        QVERIFY(colourNear(drillOnly, pixelOf(plan_, o.view, {50, 40, -5}), palette::kDimmed));
        QVERIFY(!colourNear(drillOnly, pixelOf(plan_, o.view, {50, 40, -5}), palette::kFeed));
        QVERIFY(!colourNear(drillOnly, pixelOf(plan_, o.view, {82.5, 55, 5}), palette::kRapid));
        o.step = kRoughing;
        const QImage rough = render(o, "step1.png");
        QVERIFY(colourNear(rough, pixelOf(plan_, o.view, {50, 40, -5}), palette::kFeed));
        QVERIFY(differingPixels(drillOnly, rough) > 1000);
    }

    // A plan of many steps is drawn in blocks (two actors per block of units and the selected
    // step's own): the same colours where the same paths are.
    void largePlansAreDrawnMerged()
    {
        Plan big = plan_;
        big.steps.clear();
        for (int i = 0; i < 250; ++i) big.steps.insert(big.steps.end(), plan_.steps.begin(), plan_.steps.begin() + 2);
        QVERIFY(big.steps.size() > 400);
        const auto draw = [&](int step, const QString& name) {
            RenderOptions o;
            o.view = ViewPreset::Top;
            o.step = step;
            const QString path = dir_.filePath(name);
            const auto drawn = renderToPng(big, o, path.toStdString());
            if (!drawn) qWarning("%s", drawn.error().c_str());
            return drawn ? QImage(path).convertToFormat(QImage::Format_RGB32) : QImage();
        };
        const QImage all = draw(-1, "big-all.png");
        QVERIFY(colourNear(all, pixelOf(big, ViewPreset::Top, {50, 40, -5}), palette::kFeed));
        QVERIFY(colourNear(all, pixelOf(big, ViewPreset::Top, {82.5, 55, 5}), palette::kRapid));
        const QImage drill = draw(0, "big-step0.png");
        QVERIFY(colourNear(drill, pixelOf(big, ViewPreset::Top, {50, 40, -5}), palette::kDimmed));
        QVERIFY(!colourNear(drill, pixelOf(big, ViewPreset::Top, {82.5, 55, 5}), palette::kRapid));
        const QImage rough = draw(kRoughing, "big-step1.png");
        QVERIFY(colourNear(rough, pixelOf(big, ViewPreset::Top, {50, 40, -5}), palette::kFeed));
    }

    void simulatedStockAfterTheStep()
    {
        RenderOptions o;
        o.view = ViewPreset::Top;
        o.showStock = true;
        const QImage img = render(o, "stock.png");
        // Uncut top: the stock colour (lit head-on); the pocket floor off the path: machined.
        const auto uncut = pixelOf(plan_, o.view, {8, 8, 0});
        QVERIFY(near(img.pixel(int(uncut[0]), int(uncut[1])), palette::kStock, 20));
        const auto floor = pixelOf(plan_, o.view, {27.5, 40, -5});
        QVERIFY(near(img.pixel(int(floor[0]), int(floor[1])), palette::kMachined, 20));
        // Before the pocket (after the pilot hole only) the same spot is uncut.
        o.step = 0;
        const QImage before = render(o, "stock0.png");
        QVERIFY(near(before.pixel(int(floor[0]), int(floor[1])), palette::kStock, 20));
    }

    // The selected step's own cut in its colour (floor and wall finishing
    // no longer look alike); played block by block, only the blocks played.
    void selectedStepCutInItsColourAndPlayedByBlock()
    {
        RenderOptions o;
        o.view = ViewPreset::Top;
        o.showStock = true;
        o.step = kRoughing;
        const QImage whole = render(o, "step-removed.png");
        const auto floor = pixelOf(plan_, o.view, {27.5, 40, -5});
        const auto slot = pixelOf(plan_, o.view, {50, 44, -5});
        QVERIFY2(near(whole.pixel(int(floor[0]), int(floor[1])), palette::kRemoved, 30), qPrintable(QColor(whole.pixel(int(floor[0]), int(floor[1]))).name()));
        QVERIFY(near(whole.pixel(int(slot[0]), int(slot[1])), palette::kRemoved, 30));
        // After the slot (40,40) -> (60,40) only: the slot cut, the rest uncut.
        o.move = kSlotMove;
        const QImage played = render(o, "step-played.png");
        QVERIFY(near(played.pixel(int(slot[0]), int(slot[1])), palette::kRemoved, 30));
        QVERIFY(near(played.pixel(int(floor[0]), int(floor[1])), palette::kStock, 20));
        // The scene puts the tool at that block's end and simulates the stock under it.
        Scene s;
        auto plan = std::make_shared<Plan>(plan_);
        auto sim = std::make_shared<sim::StockSimulation>(*plan);
        s.setPlan(plan, sim);
        s.setShowStock(true);
        s.setPlayhead(kRoughing, kSlotMove);
        QCOMPARE(s.playhead(), (MoveRef{kRoughing, kSlotMove}));
        QCOMPARE(s.selectedStep(), kRoughing);
        QVERIFY(s.toolPosition() && *s.toolPosition() == (Point3{60, 40, -5}));
        const auto under = sim->afterMove(kRoughing, kSlotMove);
        QCOMPARE(under->atPoint(60, 40), -5.0);
        QCOMPARE(under->atPoint(27.5, 40), 0.0);
        // Playing on cuts the rest; the last block equals the whole step, cell for cell.
        QVERIFY(*sim->afterMove(kRoughing, 1000) == *sim->after(kRoughing));
        QCOMPARE(sim->afterMove(kRoughing, kSlotMove + 3)->atPoint(70, 48), -5.0);
        // And back: before the slot the stock there is the pilot hole's only.
        QCOMPARE(sim->afterMove(kRoughing, 0)->atPoint(50, 40), 0.0);
        s.setPlayhead(-1, -1);
        QCOMPARE(s.playhead(), MoveRef{});
    }

    // The simulated stock's surface is closed (its vector area sums to
    // zero), its upward faces cover the stock exactly once, and flat regions
    // are merged: far fewer quads than cells (a block is six).
    void stockSurfaceIsClosedAndMerged()
    {
        const Stock stock{0, 0, 200, 150, 30};
        sim::HeightField field(stock, 0.25);
        const auto measure = [](vtkPolyData* pd) {
            std::array<double, 3> total{0, 0, 0};
            double up = 0;
            vtkIdType n = 0;
            const vtkIdType* ids = nullptr;
            auto polys = pd->GetPolys();
            polys->InitTraversal();
            while (polys->GetNextCell(n, ids)) {
                std::array<double, 3> area{0, 0, 0};  // Newell's vector area
                for (vtkIdType k = 0; k < n; ++k) {
                    double a[3], b[3];
                    pd->GetPoint(ids[k], a);
                    pd->GetPoint(ids[(k + 1) % n], b);
                    area[0] += 0.5 * (a[1] * b[2] - a[2] * b[1]);
                    area[1] += 0.5 * (a[2] * b[0] - a[0] * b[2]);
                    area[2] += 0.5 * (a[0] * b[1] - a[1] * b[0]);
                }
                for (int i = 0; i < 3; ++i) total[i] += area[i];
                if (area[2] > 0) up += area[2];
            }
            return std::tuple{total, up, pd->GetNumberOfPolys()};
        };
        const auto [fresh, freshUp, freshCount] = measure(heightFieldSurface(field));
        QVERIFY(std::abs(fresh[0]) + std::abs(fresh[1]) + std::abs(fresh[2]) < 1e-6);
        QVERIFY(std::abs(freshUp - 200.0 * 150.0) < 1e-6);
        const long cells = static_cast<long>(field.columns()) * field.rows();
        QVERIFY2(freshCount < 2 * (field.columns() + field.rows()) + 20, qPrintable(QString::number(freshCount)));

        // A pocket 5 mm deep with a sloped wall along one side.
        for (int j = 0; j < field.rows(); ++j)
            for (int i = 0; i < field.columns(); ++i) {
                const Point2 c = field.centre(i, j);
                if (c.x > 40 && c.x < 120 && c.y > 30 && c.y < 90) field.lower(i, j, c.x < 50 ? -(c.x - 40) / 2 : -5);
            }
        const auto [cut, cutUp, cutCount] = measure(heightFieldSurface(field));
        QVERIFY(std::abs(cut[0]) + std::abs(cut[1]) + std::abs(cut[2]) < 1e-6);
        QVERIFY(std::abs(cutUp - 200.0 * 150.0) < 1e-6);
        QVERIFY2(cutCount < cells / 20, qPrintable(QString("%1 quads for %2 cells").arg(cutCount).arg(cells)));
        // Merged along rows and columns (viz/stock_surface.cpp): the uncut
        // block is its five faces and its top, a quad per band of rows; the
        // pocket's floor rows, its walls and the sloped wall's columns (level
        // along y) are a quad each, not one per cell (the sloped wall alone
        // is 40 x 240 cells).
        QVERIFY(field.rows() - 1 >= kSurfaceBands * kSurfaceBandRows);
        QCOMPARE(freshCount, 5 + kSurfaceBands);
        QVERIFY2(cutCount < 300, qPrintable(QString("%1 quads").arg(cutCount)));
    }

    void pickingAndHighlight()
    {
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan_));
        s.setView(ViewPreset::Top, static_cast<double>(kW) / kH);
        const auto at = s.toPixel({55, 40, -5}, kW, kH);
        QCOMPARE(s.pickMove(at[0], at[1] + 3, kW, kH), (MoveRef{kRoughing, kSlotMove}));
        const auto rapid = s.toPixel({82.5, 55, 5}, kW, kH);
        QCOMPARE(s.pickMove(rapid[0], rapid[1], kW, kH), (MoveRef{kRoughing, kRapidMove}));
        QVERIFY(!s.pickMove(5, 5, kW, kH));
    }

    // The wheel zooms about the pointer (issue 34, item 7): the point under
    // it stays under it, every other point moves away from it by the
    // factor (parallel projection: exactly), and zooming about another
    // pixel gives another view.
    void zoomAboutThePointer()
    {
        for (const ViewPreset view : {ViewPreset::Top, ViewPreset::Iso, ViewPreset::Front}) {
            Scene s;
            s.setPlan(std::make_shared<const Plan>(plan_));
            s.setView(view, static_cast<double>(kW) / kH);
            const Point3 corner{0, 0, 0}, other{60, 45, -5};
            const auto at = s.toPixel(corner, kW, kH), q = s.toPixel(other, kW, kH);
            s.zoomAt(at[0], at[1], kW, kH, 1.5);
            const auto atAfter = s.toPixel(corner, kW, kH), qAfter = s.toPixel(other, kW, kH);
            QVERIFY2(std::hypot(atAfter[0] - at[0], atAfter[1] - at[1]) < 1e-6,
                     qPrintable(QString("(%1, %2) moved to (%3, %4)").arg(at[0]).arg(at[1]).arg(atAfter[0]).arg(atAfter[1])));
            const double before = std::hypot(q[0] - at[0], q[1] - at[1]), after = std::hypot(qAfter[0] - atAfter[0], qAfter[1] - atAfter[1]);
            QVERIFY(before > 20);
            QVERIFY2(std::abs(after / before - 1.5) < 1e-9, qPrintable(QString::number(after / before, 'g', 12)));
            // Back out by the inverse: where it was.
            s.zoomAt(at[0], at[1], kW, kH, 1 / 1.5);
            const auto qBack = s.toPixel(other, kW, kH);
            QVERIFY(std::hypot(qBack[0] - q[0], qBack[1] - q[1]) < 1e-6);
            // About the middle instead: the corner moves (the old wheel's zoom).
            s.zoomAt(kW / 2.0, kH / 2.0, kW, kH, 1.5);
            const auto moved = s.toPixel(corner, kW, kH);
            QVERIFY(std::hypot(moved[0] - at[0], moved[1] - at[1]) > 5);
        }
    }

    // "Zoom to step": the camera frames the selected step's path, the view
    // turned as it was; with no step selected, the whole scene.
    void framingTheSelectedStep()
    {
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan_));
        s.setView(ViewPreset::Top, static_cast<double>(kW) / kH);
        // The drill's path: a hole at (40, 40), small in the whole view.
        const auto spanOf = [&](double r) {
            const auto a = s.toPixel({40 - r, 40 - r, 0}, kW, kH), b = s.toPixel({40 + r, 40 + r, 0}, kW, kH);
            return std::max(std::abs(b[0] - a[0]), std::abs(b[1] - a[1]));
        };
        const double wholeView = spanOf(5);
        s.setSelectedStep(0);
        s.frameSelectedStep(static_cast<double>(kW) / kH);
        const auto centre = s.toPixel({40, 40, 0}, kW, kH);
        QVERIFY2(std::abs(centre[0] - kW / 2.0) < kW / 10.0 && std::abs(centre[1] - kH / 2.0) < kH / 10.0,
                 qPrintable(QString("(%1, %2)").arg(centre[0]).arg(centre[1])));
        QVERIFY2(spanOf(5) > 3 * wholeView, qPrintable(QString("%1 px, %2 px before").arg(spanOf(5)).arg(wholeView)));
        // Looking down still.
        const auto east = s.toPixel({50, 40, 0}, kW, kH);
        QVERIFY(east[0] > centre[0] && std::abs(east[1] - centre[1]) < 1e-6);
        // Nothing selected: the stock whole in view again.
        s.setSelectedStep(-1);
        s.frameSelectedStep(static_cast<double>(kW) / kH);
        const Stock& stock = plan_.mmJob.stock;
        for (const Point3 c : {Point3{stock.x, stock.y, 0}, Point3{stock.x + stock.width, stock.y + stock.length, 0}}) {
            const auto px = s.toPixel(c, kW, kH);
            QVERIFY(px[0] >= 0 && px[0] <= kW && px[1] >= 0 && px[1] <= kH);
        }
    }

    // The paths switched off: no path segment drawn, with or without a
    // step selected; on again, as before.
    void pathsSwitchedOff()
    {
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan_));
        const std::size_t all = s.drawnPathSegments();
        QVERIFY(all > 0);
        s.setPathsShown(false);
        QCOMPARE(s.drawnPathSegments(), std::size_t{0});
        s.setSelectedStep(kRoughing);
        s.highlightMove(kRoughing, kSlotMove);
        QCOMPARE(s.drawnPathSegments(), std::size_t{0});
        s.setPathsShown(true);
        QVERIFY(s.drawnPathSegments() > 0);
        s.setSelectedStep(-1);
        QCOMPARE(s.drawnPathSegments(), all);
    }

    // Issue 34, item 7: the 3-D view shows the probing touches and the
    // fitted centre, in work coordinates (the centre is X Y 0, the top face
    // Z 0). Every point of the actor is on the centre's line or cross, or
    // on a stylus ball whose centre lies on the fitted circle of the ball's
    // centres (the boss's measured radius and the ball's, touched from
    // outside; off it by the touch's residual) at the touch depth; a job
    // without probing has none.
    void probingTouchesAndCentre()
    {
        const Plan plan = samplePlan("probe-flange.taiwa");
        QVERIFY2(plan.ok(), plan.diagnostics.empty() ? "" : plan.diagnostics.front().message.c_str());
        QCOMPARE(plan.setups.size(), std::size_t{1});
        QVERIFY(plan.setups[0].measured);
        const WorkSetup& w = plan.setups[0];
        QVERIFY(w.round && !w.inside && w.ballRadius > 0);
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan));
        vtkActor* actor = s.probeActor();
        QVERIFY(actor);
        vtkPolyData* pd = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
        QVERIFY(pd && pd->GetNumberOfPoints() > 0);
        const double ring = w.measured->radius + w.ballRadius, z = -w.touchDepth, r = w.ballRadius;
        // The ball centres lie off the fitted circle by their residuals.
        double worst = 0;
        for (const double res : w.measured->residuals) worst = std::max(worst, std::abs(res));
        QVERIFY(worst < 0.05);
        int onBalls = 0;
        double low = 0, high = -1e9;
        for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i) {
            double p[3];
            pd->GetPoint(i, p);
            const bool onCentre = std::hypot(p[0], p[1]) < 1e-9 || (std::abs(p[2]) < 1e-9 && (std::abs(p[0]) < 1e-9 || std::abs(p[1]) < 1e-9));
            if (onCentre) continue;
            // Distance from the circle of the balls' centres.
            const double off = std::hypot(std::hypot(p[0], p[1]) - ring, p[2] - z);
            QVERIFY2(off <= r + worst + 1e-6, qPrintable(QString("(%1, %2, %3) is %4 mm off the touches' circle").arg(p[0]).arg(p[1]).arg(p[2]).arg(off)));
            ++onBalls;
            low = std::min(low, p[2]);
            high = std::max(high, p[2]);
        }
        // The balls' poles: the touch depth less and more the ball's radius.
        QVERIFY(onBalls > 100);
        QVERIFY2(std::abs(low - (z - r)) < 1e-6 && std::abs(high - (z + r)) < 1e-6,
                 qPrintable(QString("balls from Z %1 to %2").arg(low).arg(high)));
        // The centre's line reaches the touches' depth.
        double b[6];
        pd->GetBounds(b);
        QVERIFY(b[4] <= z - r);
        QVERIFY(!Scene().probeActor());
        Scene milled;
        milled.setPlan(std::make_shared<const Plan>(plan_));
        QVERIFY(!milled.probeActor());
    }

    // Merged, the steps have no geometry of their own until one is selected
    // or highlighted: picking goes through the merged points and finds the
    // same move, on the last copy of the step when nothing is selected and
    // on the selected copy otherwise.
    void pickingAMergedPlan()
    {
        Plan big = plan_;
        big.steps.clear();
        for (int i = 0; i < 250; ++i) big.steps.insert(big.steps.end(), plan_.steps.begin(), plan_.steps.begin() + 2);
        Scene s;
        s.setPlan(std::make_shared<const Plan>(big));
        s.setView(ViewPreset::Top, static_cast<double>(kW) / kH);
        const auto at = s.toPixel({55, 40, -5}, kW, kH);
        const int last = kRoughing + 2 * 249;
        QCOMPARE(s.pickMove(at[0], at[1] + 3, kW, kH), (MoveRef{last, kSlotMove}));
        s.setSelectedStep(kRoughing + 2);
        QCOMPARE(s.pickMove(at[0], at[1] + 3, kW, kH), (MoveRef{kRoughing + 2, kSlotMove}));
        const auto rapid = s.toPixel({82.5, 55, 5}, kW, kH);
        QCOMPARE(s.pickMove(rapid[0], rapid[1], kW, kH), (MoveRef{kRoughing + 2, kRapidMove}));
        s.highlightMove(kRoughing + 4, kSlotMove);  // a step not selected: its geometry made for the highlight
        QCOMPARE(s.highlightedMove(), (MoveRef{kRoughing + 4, kSlotMove}));
        const auto b = s.bounds();
        QVERIFY(b[4] < -5 && b[5] >= 5);  // the paths' depth and clearance height, from the merged points
    }

    // A section across Y at Y40, the material in front of it taken away,
    // seen from the front: the face the plane cuts in the section colour,
    // with the pocket's hollow (Z 0 to -5 from X20 to X80) open in it; no
    // section: the stock's front face there. Flipped, the plane keeps the
    // front half: its face at Y0 hides the section.
    void sectionShowsTheFaceItCuts()
    {
        RenderOptions o;
        o.view = ViewPreset::Front;
        o.showStock = true;
        const QImage whole = render(o, "front-stock.png");
        o.section = SectionPlane{{50, 40, -15}, {0, -1, 0}};
        const QImage cut = render(o, "front-section.png");
        const auto solid = pixelOf(plan_, o.view, {10, 40, -15}), below = pixelOf(plan_, o.view, {50, 40, -15});
        const auto hollow = pixelOf(plan_, o.view, {50, 40, -2.5});
        const auto colourAt = [](const QImage& img, std::array<double, 2> p) { return img.pixel(int(p[0]), int(p[1])); };
        QVERIFY2(near(colourAt(cut, solid), palette::kSection, 4), qPrintable(QColor(colourAt(cut, solid)).name()));
        QVERIFY(near(colourAt(cut, below), palette::kSection, 4));
        QVERIFY2(!near(colourAt(cut, hollow), palette::kSection, 40), qPrintable(QColor(colourAt(cut, hollow)).name()));
        QVERIFY(!near(colourAt(whole, solid), palette::kSection, 40));
        o.section->normal = {0, 1, 0};
        const QImage back = render(o, "front-section-flipped.png");
        QVERIFY(!near(colourAt(back, solid), palette::kSection, 40));
        QVERIFY(differingPixels(back, whole) < kW * kH / 200);
        // A level section at Z-2.5: seen from above, the face at that height
        // over the stock, the pocket a hole in it.
        o.view = ViewPreset::Top;
        o.section = SectionPlane{{50, 40, -2.5}, {0, 0, 1}};
        const QImage level = render(o, "top-section.png");
        QVERIFY(near(colourAt(level, pixelOf(plan_, o.view, {8, 8, -2.5})), palette::kSection, 4));
        QVERIFY(!near(colourAt(level, pixelOf(plan_, o.view, {27.5, 40, -5})), palette::kSection, 40));
        // The face itself: a quad a run of samples, covering the stock's section.
        sim::HeightField field(plan_.mmJob.stock, 0.5);
        const auto cap = sectionCap(field, SectionPlane{{50, 40, 0}, {0, 0, 1}});
        double bounds[6];
        cap->GetBounds(bounds);
        QVERIFY(std::abs(bounds[0]) < 1e-9 && std::abs(bounds[1] - 100) < 1e-9 && std::abs(bounds[3] - 80) < 1e-9);
        QCOMPARE(cap->GetNumberOfPolys(), vtkIdType(160));  // one run per row of 0.5 mm
    }

    // The verification's colour map: the hand plan has no unit, so every
    // cut is into the part (red) and the uncut top is the stock's colour;
    // m4-standard.taiwa's pocket is at size (green) and gouged nowhere.
    void colourMapOfTheFinishedPart()
    {
        RenderOptions o;
        o.view = ViewPreset::Top;
        o.deviation = true;
        const QImage img = render(o, "deviation-hand.png");
        const auto floor = pixelOf(plan_, o.view, {27.5, 40, -5}), top = pixelOf(plan_, o.view, {8, 8, 0});
        QVERIFY2(near(img.pixel(int(floor[0]), int(floor[1])), palette::kGouge, 30), qPrintable(QColor(img.pixel(int(floor[0]), int(floor[1]))).name()));
        QVERIFY(near(img.pixel(int(top[0]), int(top[1])), palette::kStock, 20));

        const Plan plan = samplePlan("m4-standard.taiwa");
        const QString path = dir_.filePath("deviation-m4.png");
        QVERIFY(renderToPng(plan, o, path.toStdString()));
        const QImage m4 = QImage(path).convertToFormat(QImage::Format_RGB32);
        int green = 0, red = 0;
        for (int y = 0; y < m4.height(); ++y)
            for (int x = 0; x < m4.width(); ++x) {
                green += near(m4.pixel(x, y), palette::kAtSize, 30) ? 1 : 0;
                red += near(m4.pixel(x, y), palette::kGouge, 30) ? 1 : 0;
            }
        QVERIFY2(green > kW * kH / 50, qPrintable(QString::number(green)));
        QCOMPARE(red, 0);
        // The scene drops a map with its plan.
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan));
        const verify::Report r = verify::verifyPlan(plan, {0.25, 0});
        s.setDeviationMap(std::make_shared<const verify::DeviationMap>(verify::deviationMap(plan, r)));
        QVERIFY(s.showsDeviation());
        s.setPlan(std::make_shared<const Plan>(plan));
        QVERIFY(!s.showsDeviation());
    }

    void missingDisplayIsAnError()
    {
        const QByteArray display = qgetenv("DISPLAY");
        qunsetenv("DISPLAY");
        const auto err = renderToPng(plan_, {}, dir_.filePath("none.png").toStdString());
        qputenv("DISPLAY", display);
        QVERIFY(!err);
        QCOMPARE(QString::fromStdString(err.error()), QString("rendering needs an X display (run under xvfb-run)"));
        QVERIFY(!QFile::exists(dir_.filePath("none.png")));
    }

    void samplePlanTopView()
    {
        const Plan plan = samplePlan("m4-standard.taiwa");
        QVERIFY(plan.ok() && plan.steps.size() >= 3);
        constexpr int w = 400, h = 300;
        RenderOptions o;
        o.view = ViewPreset::Top;
        o.width = w;
        o.height = h;
        const auto png = [&](const RenderOptions& opt, const char* name) {
            const QString path = dir_.filePath(name);
            const auto err = renderToPng(plan, opt, path.toStdString());
            if (!err) qWarning("%s", err.error().c_str());
            return err ? QImage(path).convertToFormat(QImage::Format_RGB32) : QImage();
        };
        const QImage top = png(o, "m4-top.png");
        QCOMPARE(top.size(), QSize(w, h));
        Scene s;
        s.setPlan(std::make_shared<const Plan>(plan));
        s.setView(ViewPreset::Top, static_cast<double>(w) / h);
        const Stock& st = plan.mmJob.stock;
        // Top view fitted to the stock: its centre is the image centre.
        const auto centre = s.toPixel({st.x + st.width / 2, st.y + st.length / 2, 0}, w, h);
        QVERIFY(std::abs(centre[0] - w / 2.0) < 2 && std::abs(centre[1] - h / 2.0) < 2);
        // Off the stock (left of its left edge): the background.
        const auto off = s.toPixel({st.x - 0.03 * st.width, st.y + st.length / 2, 0}, w, h);
        QVERIFY(off[0] > 0);
        QVERIFY(near(top.pixel(int(off[0]), int(off[1])), palette::kBackground, 0));
        // The roughing path of the pocket: the feed colour; the pocket centre is drawn on.
        const auto rough = std::find_if(plan.steps.begin(), plan.steps.end(), [](const Step& st2) { return st2.kind == StepKind::Roughing && st2.path; });
        QVERIFY(rough != plan.steps.end());
        const auto feed = feedPointOf(plan, *rough);
        QVERIFY(feed);
        QVERIFY(colourNear(top, s.toPixel(*feed, w, h), palette::kFeed));
        const auto pc = s.toPixel({millingOf(*rough).position.x, millingOf(*rough).position.y, 0}, w, h);
        QVERIFY(!near(top.pixel(int(pc[0]), int(pc[1])), palette::kBackground, 8));
        // The finished pocket's outline (middle of its first side): the outline colour.
        const auto& q = millingOf(*rough).outline->corners;
        QVERIFY(colourNear(top, s.toPixel({(q[0].x + q[1].x) / 2, (q[0].y + q[1].y) / 2, 0}, w, h), palette::kPartEdges));

        o.view = ViewPreset::Iso;
        QVERIFY(differingPixels(top, png(o, "m4-iso.png")) > w * h / 20);
        o.view = ViewPreset::Top;
        o.step = 1;  // step 2 only
        QVERIFY(differingPixels(top, png(o, "m4-step2.png")) > 200);

        // Figure, not asserted: plate.taiwa (29 steps) at 800 x 600.
        const Plan plate = samplePlan("plate.taiwa");
        QElapsedTimer t;
        t.start();
        const auto err = renderToPng(plate, {}, dir_.filePath("plate.png").toStdString());
        qDebug("plate.taiwa iso 800x600: renderToPng %lld ms (%s)", static_cast<long long>(t.elapsed()),
               err ? "ok" : err.error().c_str());
    }
};

QTEST_MAIN(TestRenderScene)
#include "test_render_scene.moc"
