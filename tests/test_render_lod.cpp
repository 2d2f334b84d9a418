// The preview's level of detail while the camera moves (viz/path_lod.h,
// viz::Scene::setMoving, PreviewWidget's interaction events): decimated
// lines stay within their bound of every point they drop, keep each run's
// ends and runs apart; in the widget a large plan is drawn from far fewer
// segments while the left button is down, covering the same region of the
// picture, and exactly as before once it is released; the tool, the axes'
// labels and the scale note left out while moving; a small plan keeps
// all its segments. Needs an X display (xvfb-run -a).
#include "support/images.h"
#include "ui/preview_widget.h"
#include "viz/path_lod.h"
#include "viz/render.h"
#include "viz/scene.h"

#include <QApplication>
#include <QtTest>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPoints.h>
#include <vtkRenderWindow.h>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::test;
using namespace taiwa::viz;
using taiwa::ui::PreviewWidget;

namespace {

constexpr int kW = 800, kH = 600;

// Lines as the scene makes them: one two-point cell per piece, consecutive
// pieces sharing their point; a new run wherever `breaks` says.
vtkSmartPointer<vtkPolyData> pieces(const std::vector<std::array<double, 3>>& pts, const std::vector<std::size_t>& breaks = {})
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    for (const auto& p : pts) points->InsertNextPoint(p.data());
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        if (std::find(breaks.begin(), breaks.end(), i + 1) != breaks.end()) continue;  // no piece into a break
        const vtkIdType ids[2] = {static_cast<vtkIdType>(i), static_cast<vtkIdType>(i + 1)};
        lines->InsertNextCell(2, ids);
    }
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetLines(lines);
    return pd;
}

double segmentDistance(const double p[3], const double a[3], const double b[3])
{
    double ab[3], ap[3];
    for (int i = 0; i < 3; ++i) {
        ab[i] = b[i] - a[i];
        ap[i] = p[i] - a[i];
    }
    const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const double t = len2 > 0 ? std::clamp((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]);
}

// The farthest any point of `full` lies from the decimated lines.
double worstDeviation(vtkPolyData* full, vtkPolyData* lod)
{
    double worst = 0;
    for (vtkIdType i = 0; i < full->GetNumberOfPoints(); ++i) {
        double p[3];
        full->GetPoint(i, p);
        double best = 1e300;
        auto it = vtk::TakeSmartPointer(lod->GetLines()->NewIterator());
        for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
            vtkIdType n = 0;
            const vtkIdType* ids = nullptr;
            it->GetCurrentCell(n, ids);
            for (vtkIdType k = 0; k + 1 < n; ++k) {
                double a[3], b[3];  // copies: GetPoint(id) alone returns one buffer for every call
                lod->GetPoint(ids[k], a);
                lod->GetPoint(ids[k + 1], b);
                best = std::min(best, segmentDistance(p, a, b));
            }
        }
        worst = std::max(worst, best);
    }
    return worst;
}

// One step whose path hatches the 200 x 150 stock in `rows` rows, each a
// wiggle 0.08 mm high sampled every 0.05 mm (3,800 pieces a row).
std::shared_ptr<const Plan> hatchPlan(int rows)
{
    auto plan = std::make_shared<Plan>();
    plan->mmJob.stock = {0, 0, 200, 150, 30};
    Tool mill;
    mill.id = 1;
    mill.diameter = 10;
    plan->tools = {mill};
    Step s;
    s.tool = ToolChoice{1, ""};
    ToolPath p{{5, 5, 5}, {{MoveKind::Feed, {5, 5, -5}}}};
    for (int r = 0; r < rows; ++r) {
        const double y = 5 + 140.0 * r / std::max(rows - 1, 1);
        for (int i = 0; i <= 3800; ++i) {
            const double x = r % 2 == 0 ? 5 + 0.05 * i : 195 - 0.05 * i;
            p.moves.push_back({MoveKind::Feed, {x, y + 0.04 * std::sin(x * 4 * std::numbers::pi), -5}});
        }
    }
    s.path = p;
    plan->steps = {s};
    return plan;
}

// The box around the pixels of the feed colour (with a margin for lines
// blended into the backdrop), as left, top, right, bottom.
std::array<int, 4> feedBox(const QImage& img)
{
    std::array<int, 4> box{img.width(), img.height(), -1, -1};
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            if (colourDistance(img.pixel(x, y), palette::kFeed) < 60) {
                box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
            }
    return box;
}

}  // namespace

class TestRenderLod : public QObject {
    Q_OBJECT

private slots:
    // A wiggle below the tolerance becomes a straight line; one above it
    // keeps its turns; an out-and-back run is not cut short to its ends;
    // every dropped point lies within 3 x the tolerance.
    void decimationKeepsItsBound()
    {
        const double tol = 0.1;
        std::vector<std::array<double, 3>> pts;
        for (int i = 0; i <= 2000; ++i) pts.push_back({0.01 * i, 0.05 * std::sin(0.01 * i * 20), 0});    // small wiggle: 20 mm
        for (int i = 1; i <= 2000; ++i) pts.push_back({20 - 0.01 * i, 2 + 1.5 * std::sin(0.01 * i), 0});  // large arc back
        for (int i = 1; i <= 1000; ++i) pts.push_back({0.01 * i, 4, 0});                                  // out 10 mm
        for (int i = 1; i <= 900; ++i) pts.push_back({10 - 0.01 * i, 4.001, 0});                          // and back 9 mm
        const std::size_t second = pts.size();
        for (int i = 0; i <= 500; ++i) pts.push_back({50 + 0.01 * i, 50, 0});  // a run of its own
        const auto full = pieces(pts, {second});
        const auto lod = decimateLines(full, tol);
        QCOMPARE(lod->GetLines()->GetNumberOfCells(), vtkIdType(2));  // the two runs stay apart
        QVERIFY2(lineSegmentCount(lod) < lineSegmentCount(full) / 20, qPrintable(QString::number(lineSegmentCount(lod))));
        const double worst = worstDeviation(full, lod);
        QVERIFY2(worst <= 3 * tol, qPrintable(QString::number(worst)));
        // Each run's ends are kept as they are.
        for (const vtkIdType i : {vtkIdType(0), vtkIdType(second - 1), vtkIdType(second), vtkIdType(pts.size() - 1)}) {
            double p[3];
            full->GetPoint(i, p);
            bool found = false;
            for (vtkIdType k = 0; k < lod->GetNumberOfPoints() && !found; ++k) {
                const double* q = lod->GetPoint(k);
                found = q[0] == p[0] && q[1] == p[1] && q[2] == p[2];
            }
            QVERIFY2(found, qPrintable(QString("point %1").arg(i)));
        }
        // No tolerance: every point.
        QCOMPARE(lineSegmentCount(decimateLines(full, 0)), lineSegmentCount(full));
        // A budget: the tolerance grows until the lines fit in it.
        QVERIFY(lineSegmentCount(decimateLinesWithin(full, 0.01, 50)) <= 50);
    }

    // A 300,000-segment plan in the widget: while the left button is down
    // (the interactor's rotation started) the path is drawn from its
    // decimated twin, no more than the budget, over the same region of the
    // picture; released, the picture is the one before, pixel for pixel.
    void widgetDrawsTheLevelOfDetailWhileDragging()
    {
        PreviewWidget w;
        w.resize(kW, kH);
        w.setPlan(hatchPlan(80));
        w.setView(ViewPreset::Top);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const std::size_t full = w.scene().drawnPathSegments();
        QVERIFY2(full > Scene::kLodAbove, qPrintable(QString::number(full)));
        const QImage still = w.grabImage().convertToFormat(QImage::Format_RGB32);

        const QPointF at(400, 300);
        QMouseEvent press(QEvent::MouseButtonPress, at, w.mapToGlobal(at), Qt::LeftButton, Qt::LeftButton, {});
        QApplication::sendEvent(&w, &press);
        QVERIFY(w.scene().moving());
        const std::size_t drawn = w.scene().drawnPathSegments();
        QVERIFY2(drawn <= Scene::kLodBudget && drawn < full / 20, qPrintable(QString::number(drawn)));
        const QImage moving = w.grabImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY(differingPixels(moving, still) > 0);  // it is another drawing
        const auto a = feedBox(still), b = feedBox(moving);
        QVERIFY2(a[2] > a[0] + 400 && a[3] > a[1] + 300, "the still picture shows the hatch");
        for (int i = 0; i < 4; ++i)
            QVERIFY2(std::abs(a[i] - b[i]) <= 3, qPrintable(QString("box side %1: %2 still, %3 moving").arg(i).arg(a[i]).arg(b[i])));

        QMouseEvent release(QEvent::MouseButtonRelease, at, w.mapToGlobal(at), Qt::LeftButton, Qt::NoButton, {});
        QApplication::sendEvent(&w, &release);
        QVERIFY(!w.scene().moving());
        QCOMPARE(w.scene().drawnPathSegments(), full);
        const QImage after = w.grabImage().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(differingPixels(after, still), 0);
    }

    // A large plan (blocks of units, over 400 steps): every
    // block decimated within its share of the budget while moving, full
    // detail again when it stops; after an edit of one step the same.
    void mergedPlanDecimatesEachBlock()
    {
        auto plan = std::make_shared<Plan>(*hatchPlan(1));
        const ToolPath row = *plan->steps.front().path;
        plan->steps.clear();
        for (int k = 0; k < 480; ++k) {  // 120 units of 4 steps, each a row of 650 pieces
            Step s;
            s.unit = k / 4;
            s.tool = ToolChoice{1, ""};
            ToolPath p{{5, 5, 5}, {}};
            const double dy = 140.0 * k / 480;
            for (std::size_t i = 0; i < 650; ++i) p.moves.push_back({MoveKind::Feed, {row.moves[i].end.x, row.moves[i].end.y + dy, -5}});
            s.path = p;
            plan->steps.push_back(s);
        }
        Scene scene;
        scene.setPlan(plan);
        QVERIFY(scene.pathBlockActors().size() > 1);
        const std::size_t full = scene.drawnPathSegments();
        QVERIFY2(full > Scene::kLodAbove, qPrintable(QString::number(full)));
        for (int edit = 0; edit < 2; ++edit) {
            scene.setMoving(true);
            const std::size_t drawn = scene.drawnPathSegments();
            QVERIFY2(drawn <= Scene::kLodBudget && drawn < full / 5, qPrintable(QString::number(drawn)));
            scene.setMoving(false);
            QCOMPARE(scene.drawnPathSegments(), full);
            auto next = std::make_shared<Plan>(*plan);
            next->steps.front().path->moves.front().end.z = -4 - edit;
            scene.setPlan(next);
            QVERIFY(scene.lastPlanUpdate().inPlace && scene.lastPlanUpdate().blocksMade == 1);
        }
    }

    // While moving, the tool, the axes' labels and the scale note are left
    // out (scene_lod.cpp); once still, the picture is a scene's that never
    // moved, pixel for pixel.
    void movingLeavesOutToolAndTexts()
    {
        const auto plan = hatchPlan(2);
        const auto draw = [](Scene& scene) {
            OffscreenWindow window(kW, kH);
            if (window.problem()) return QImage();
            window.window()->AddRenderer(scene.renderer());
            scene.setView(ViewPreset::Iso, static_cast<double>(kW) / kH);
            window.window()->Render();
            const std::string png = pngOf(window.window());
            window.window()->RemoveRenderer(scene.renderer());
            return QImage::fromData(reinterpret_cast<const uchar*>(png.data()), static_cast<int>(png.size()), "PNG")
                .convertToFormat(QImage::Format_RGB32);
        };
        const auto gold = [](const QImage& img) {
            int n = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x) n += goldish(img.pixel(x, y)) ? 1 : 0;
            return n;
        };
        Scene never, moved;
        never.setPlan(plan);
        moved.setPlan(plan);
        const QImage still = draw(never);
        QVERIFY2(!still.isNull(), "no display");
        QVERIFY2(gold(still) > 50, qPrintable(QString::number(gold(still))));  // the tool
        moved.setMoving(true);
        const QImage moving = draw(moved);
        QCOMPARE(gold(moving), 0);
        QVERIFY(moved.scaleNote().size() > 0);
        moved.setMoving(false);
        QCOMPARE(differingPixels(draw(moved), still), 0);
    }

    // A small plan keeps every segment while moving (only its lines thin).
    void smallPlanKeepsItsSegments()
    {
        Scene scene;
        scene.setPlan(hatchPlan(2));
        const std::size_t full = scene.drawnPathSegments();
        QVERIFY(full > 7000 && full < Scene::kLodAbove);
        scene.setMoving(true);
        QCOMPARE(scene.drawnPathSegments(), full);
        scene.setMoving(false);
        QCOMPARE(scene.drawnPathSegments(), full);
    }
};

QTEST_MAIN(TestRenderLod)
#include "test_render_lod.moc"
