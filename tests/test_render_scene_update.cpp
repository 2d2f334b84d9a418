// The preview scene updated in place for an edited job (viz/scene_update.cpp)
// draws the picture a new scene draws of the edited plan, pixel for pixel:
// the sample plate.taiwa with unit 1's depth changed (or its stock wider),
// with the simulated stock and the translucent block, all steps or one
// selected, and a job of 150 pockets. Paths are drawn merged in blocks of
// units: the update keeps the blocks without unit 1 (their actors) and makes
// unit 1's, and the edit shows (the picture before it differs), so a path
// or stock left stale would fail the comparison. Needs an X display (xvfb-run -a).
#include "job/job_file.h"
#include "modules/m4/m4.h"
#include "pipeline/pipeline.h"
#include "support/images.h"
#include "support/scene_picture.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "viz/render.h"
#include "viz/scene.h"

#include <QImage>
#include <QtTest>

#include <set>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <memory>
#include <string>

using namespace taiwa;
using namespace taiwa::viz;

namespace {

constexpr int kWidth = 640, kHeight = 400;

std::shared_ptr<const Plan> planOf(const Job& job)
{
    return std::make_shared<const Plan>(planJob(job, TechnologyTable::builtIn(), defaultToolLibrary()));
}

// The sample plate.
Job plate()
{
    const auto read = readJobFile(taiwa::test::sourcePath(QStringLiteral("resources/samples/plate.taiwa")).toStdString());
    return read.job ? *read.job : Job{};
}

// `units` rectangular pockets on a 30 mm grid, 12 to a row (150 of them
// make 50 blocks of 3 units).
Job grid(int units)
{
    Job job;
    const int columns = 12, rows = (units + columns - 1) / columns;
    job.stock = {0, 0, columns * 30.0, rows * 30.0, 30};
    for (int i = 0; i < units; ++i) {
        const double x = (i % columns) * 30.0 + 5, y = (i / columns) * 30.0 + 5;
        M4Pocket m;
        m.corners = {Point2{x, y}, Point2{x + 20, y}, Point2{x + 20, y + 18}, Point2{x, y + 18}};
        m.cornerRadius = 4;
        m.depth = 6;
        m.toolUse = 1;
        m.wallFinish = 2;
        m.pilotHole = 0;
        job.units.push_back({"", m});
    }
    return job;
}

Job deeper(Job job)
{
    job.units[0].module.as<M4Pocket>().depth += 0.5;
    return job;
}

// The scene's picture through the camera it is given.
QImage picture(Scene& scene, vtkCamera* camera) { return test::scenePicture(scene, camera, kWidth, kHeight); }

struct Settings {
    bool stock = false;
    int step = -1;
};

void apply(Scene& s, const Settings& o)
{
    s.setShowStock(o.stock);
    s.setSelectedStep(o.step);
}

}  // namespace

class TestRenderSceneUpdate : public QObject {
    Q_OBJECT

    // The scene of `before` updated to `after` against a new scene of
    // `after`, through one camera (the one fitted to `before`).
    // What the update kept and made.
    Scene::PlanUpdate compare(const Job& before, const Job& after, const Settings& o)
    {
        Scene::PlanUpdate u;
        compareInto(before, after, o, u);
        return u;
    }
    // A merged scene's block actors before and after the update.
    using BlockActors = std::vector<std::array<const vtkActor*, 2>>;
    void compareInto(const Job& before, const Job& after, const Settings& o, Scene::PlanUpdate& u,
                     BlockActors* blocksBefore = nullptr, BlockActors* blocksAfter = nullptr)
    {
        const auto p0 = planOf(before), p1 = planOf(after);
        QVERIFY2(!p0->steps.empty() && p0->steps.size() == p1->steps.size(), qPrintable(QString("%1 and %2 steps, %3").arg(p0->steps.size()).arg(p1->steps.size()).arg(p0->diagnostics.empty() ? QString() : QString::fromStdString(p0->diagnostics.front().message))));
        Scene updated;
        updated.setPlan(p0);
        apply(updated, o);
        updated.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        auto camera = vtkSmartPointer<vtkCamera>::New();
        camera->DeepCopy(updated.renderer()->GetActiveCamera());
        const QImage old = picture(updated, camera);
        QVERIFY2(!old.isNull(), "no display");

        if (blocksBefore) *blocksBefore = updated.pathBlockActors();
        updated.setPlan(p1);
        u = updated.lastPlanUpdate();
        if (blocksAfter) *blocksAfter = updated.pathBlockActors();
        QVERIFY(u.inPlace);
        const QImage edited = picture(updated, camera);

        Scene fresh;
        fresh.setPlan(p1);
        apply(fresh, o);
        QVERIFY(!fresh.lastPlanUpdate().inPlace);
        const QImage want = picture(fresh, camera);

        QCOMPARE(edited.size(), want.size());
        // The edit shows: a stale picture would not pass the comparison.
        QVERIFY2(test::differingPixels(old, want) > 20, qPrintable(QString::number(test::differingPixels(old, want))));
        const int differing = test::differingPixels(edited, want);
        if (differing != 0 && !qEnvironmentVariableIsEmpty("TAIWA_SCREENSHOTS")) {
            const QString dir = qEnvironmentVariable("TAIWA_SCREENSHOTS");
            edited.save(dir + "/scene-updated.png");
            want.save(dir + "/scene-fresh.png");
        }
        QVERIFY2(differing == 0, qPrintable(QString("%1 pixels differ from a new scene's").arg(differing)));
    }

    // Unit 1's block is made anew, the other units' kept (plate.taiwa has
    // fewer units than blocks: a block each).
    static void keptOthers(const Scene::PlanUpdate& u)
    {
        const auto p = planOf(plate());
        std::set<int> units;
        for (const Step& s : p->steps)
            if (s.path) units.insert(s.unit);
        QVERIFY(units.size() > 1);
        QCOMPARE(u.blocksMade, 1);
        QCOMPARE(u.blocksKept, static_cast<int>(units.size()) - 1);
    }

private slots:
    void pathsAndBlockAsANewScene()
    {
        const auto u = compare(plate(), deeper(plate()), {});
        keptOthers(u);
    }

    void simulatedStockAsANewScene()
    {
        const auto u = compare(plate(), deeper(plate()), {true, -1});
        keptOthers(u);
    }

    void selectedStepAsANewScene()
    {
        // The first step of unit 1 (its path changed with the depth), over the stock after it.
        const auto p = planOf(plate());
        int first = -1;
        for (std::size_t k = 0; k < p->steps.size() && first < 0; ++k)
            if (p->steps[k].unit == 0 && p->steps[k].path) first = static_cast<int>(k);
        QVERIFY(first >= 0);
        compare(plate(), deeper(plate()), {true, first});
        // A step of another unit selected: its own actors kept too.
        int other = -1;
        for (std::size_t k = 0; k < p->steps.size() && other < 0; ++k)
            if (p->steps[k].unit == 1 && p->steps[k].path) other = static_cast<int>(k);
        QVERIFY(other >= 0);
        const auto u = compare(plate(), deeper(plate()), {true, other});
        QCOMPARE(u.pathsKept, 1);
    }

    void mergedAsANewScene() { compare(grid(150), deeper(grid(150)), {false, 3}); }

    // Merged, the paths are in blocks of units (viz/scene_blocks.cpp): an
    // edit of unit 1 makes its block anew and keeps every other block's
    // actors (the same objects, their GPU buffers with them); the picture,
    // all steps alike or one step selected over the dimmed rest, is a new
    // scene's.
    void mergedEditKeepsTheOtherBlocks()
    {
        for (const Settings& o : {Settings{false, -1}, Settings{false, 3}, Settings{true, -1}}) {
            Scene::PlanUpdate u;
            BlockActors was, now;
            compareInto(grid(150), deeper(grid(150)), o, u, &was, &now);
            if (QTest::currentTestFailed()) return;
            QVERIFY2(was.size() >= 8, qPrintable(QString::number(was.size())));
            QCOMPARE(now.size(), was.size());
            QCOMPARE(u.blocksMade, 1);
            QCOMPARE(u.blocksKept, static_cast<int>(was.size()) - 1);
            // Unit 1's steps are in the first block: made anew; the rest the same actors.
            QVERIFY(now[0][0] != was[0][0] && now[0][1] != was[0][1]);
            for (std::size_t b = 1; b < was.size(); ++b) QVERIFY2(now[b] == was[b], qPrintable(QString("block %1").arg(b)));
        }
    }

    // Blocks of units: every step with a path in exactly one block, a
    // unit's steps all in one, at most 64 blocks.
    void mergedBlocksFollowUnits()
    {
        const auto p = planOf(grid(150));
        Scene s;
        s.setPlan(p);
        const auto blocks = s.pathBlockSteps();
        QVERIFY(blocks.size() > 1 && blocks.size() <= 64);
        std::vector<int> blockOfStep(p->steps.size(), -1), blockOfUnit(150, -1);
        for (std::size_t b = 0; b < blocks.size(); ++b)
            for (int k : blocks[b]) {
                QCOMPARE(blockOfStep[static_cast<std::size_t>(k)], -1);
                blockOfStep[static_cast<std::size_t>(k)] = static_cast<int>(b);
                int& unit = blockOfUnit[static_cast<std::size_t>(p->steps[static_cast<std::size_t>(k)].unit)];
                QVERIFY(unit == -1 || unit == static_cast<int>(b));
                unit = static_cast<int>(b);
            }
        for (std::size_t k = 0; k < p->steps.size(); ++k) QCOMPARE(blockOfStep[k] >= 0, p->steps[k].path.has_value());
    }

    // A wider stock: its edges, block and axes new, the paths kept.
    void widerStockAsANewScene()
    {
        Job other = plate();
        other.stock.width += 20;
        const auto u = compare(plate(), other, {true, -1});
        QCOMPARE(u.blocksMade, 0);
        QVERIFY(u.blocksKept > 0);
    }
};

QTEST_MAIN(TestRenderSceneUpdate)
#include "test_render_scene_update.moc"
