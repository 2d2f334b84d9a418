// Tool choice on the default library: the largest end mill that fits the
// corner, the pilot drill chosen after the roughing tool, taper walls, pins,
// no-fit messages; the job-wide order honours every dependency and saves
// tool changes; tool-life notes.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "job/job_check.h"
#include "pipeline/pipeline.h"
#include "modules/pocket_tools.h"
#include "modules/registry.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <numeric>
#include <random>

using namespace taiwa;

namespace {

const std::vector<Tool>& lib()
{
    static const auto tools = defaultToolLibrary();
    return tools;
}
const Tool& tool(int id) { return *std::find_if(lib().begin(), lib().end(), [id](const Tool& t) { return t.id == id; }); }

M4Pocket pocket(double r1, double taper = 0, int h = 0)
{
    M4Pocket p;
    p.corners = {{{0, 0}, {100, 0}, {100, 60}, {0, 60}}};
    p.cornerRadius = r1;
    p.depth = 12;
    p.taper = taper;
    p.pilotHole = h;
    return p;
}

TechnologyData tech()
{
    TechnologyData t;
    t.alpha2 = 0.3;
    t.alpha3 = 0.1;
    t.beta2 = 0.2;
    return t;
}

// Number of tool changes along an order.
int changes(const std::vector<Step>& steps, const std::vector<int>& order)
{
    int n = 0, current = -1;
    for (const int i : order) {
        const int t = steps[static_cast<std::size_t>(i)].tool->toolId;
        n += t != current;
        current = t;
    }
    return n;
}

}  // namespace

class TestToolChoice : public QObject {
    Q_OBJECT
private slots:
    void aToolThatFitsExactlyIsChosen()
    {
        // 4.6 x 4.6, r1 1.3, α2 0.3: the roughing outline is 4.0 wide and its
        // corners 1.0, so a 2 mm end mill fits exactly by the documented rule
        // (radius <= r1 - α2, diameter <= the inscribed radius). The arithmetic
        // gives 1.9999999999999998: the check passed it and tool choice refused it.
        Job j;
        j.stock = {0, 0, 50, 50, 20};
        M4Pocket p;
        p.corners = {Point2{10, 10}, Point2{14.6, 10}, Point2{14.6, 14.6}, Point2{10, 14.6}};
        p.cornerRadius = 1.3;
        p.depth = 5;
        p.pilotHole = 9;
        j.units.push_back({"exact", p});
        QVERIFY(!hasErrors(checkJob(j, TechnologyTable::builtIn(), lib())));
        PlanOptions stepsOnly;
        stepsOnly.withToolPaths = false;
        const Plan plan = planJob(j, TechnologyTable::builtIn(), lib(), stepsOnly);
        QVERIFY2(plan.ok(), plan.diagnostics.empty() ? "" : plan.diagnostics.front().message.c_str());
        for (const auto& s : plan.steps)
            if (s.kind == StepKind::Roughing) QCOMPARE(tool(s.tool->toolId).diameter, 2.0);
    }

    void roughingTakesTheLargestEndMillThatFitsAndThePilotFollowsIt()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);  // roughing corner radius 5.7
        QVERIFY(chooseTools(steps, {}, lib(), "aluminium-6061").empty());
        const Tool& rough = tool(steps[1].tool->toolId);
        QCOMPARE(steps[1].kind, StepKind::Roughing);
        QCOMPARE(rough.type, ToolType::FlatEndMill);
        QCOMPARE(rough.diameter, 10.0);  // 12 mm would need radius 6 > 5.7
        QCOMPARE(steps[1].tool->reason.str(), std::string("largest flat end mill (10 mm) whose radius 5 mm fits the corner "
                                                    "radius 5.7 mm; enters the 10 mm pilot hole"));
        const Tool& drill = tool(steps[0].tool->toolId);
        QCOMPARE(drill.type, ToolType::Drill);
        QCOMPARE(drill.diameter, 10.0);  // the smallest drill not smaller than 10 mm
        const Tool& wall = tool(steps.back().tool->toolId);
        QCOMPARE(steps.back().kind, StepKind::WallFinishing);
        QCOMPARE(wall.diameter, 12.0);  // radius 6 fits the finished corner radius 6
        QCOMPARE(tool(steps[2].tool->toolId).diameter, 10.0);  // the floor follows the roughing outline (5.7)
    }

    void aPilotHoleAskedWiderGetsAWiderDrill()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);
        editMilling(steps[0]).holeDiameter = 11;
        QVERIFY(chooseTools(steps, {}, lib(), "aluminium-6061").empty());
        // The smallest library drill not smaller than asked: the 11.8 mm
        // pre-drill of the reamers (the hole tools of schema 6).
        QCOMPARE(tool(steps[0].tool->toolId).diameter, 11.8);
        QCOMPARE(millingOf(steps[0]).holeDiameter, 11.8);
    }

    void deepRoughingFallsBackToShortFlutesThatReach()
    {
        M4Pocket p = pocket(3);
        p.depth = 25;  // radius 2.7: the 5 mm end mill's 12.5 mm flutes are too short, its 30 mm stick-out reaches
        auto steps = decomposeM4(p, tech(), 0);
        chooseTools(steps, {}, lib(), "aluminium-6061");
        QCOMPARE(tool(steps[1].tool->toolId).diameter, 5.0);
        QVERIFY2(QString::fromStdString(steps[1].tool->reason.str()).contains("its flutes (12.5 mm) are shorter than the depth 24.8 mm"),
                 steps[1].tool->reason.str().c_str());
        p.depth = 31;  // deeper than every stick-out that fits
        auto deeper = decomposeM4(p, tech(), 0);
        const auto problems = chooseTools(deeper, {}, lib(), "aluminium-6061");
        QVERIFY(!problems.empty());
        QVERIFY2(QString::fromStdString(problems[0]).startsWith("Roughing I: no flat end mill"), problems[0].c_str());
    }

    void m2dRoughingAndInclinedFaces()
    {
        M2DPocket p;
        p.lengthX = 80;
        p.lengthY = 50;
        p.depth = 15;
        p.theta1 = 10;
        p.cornerRadius = 6;
        const ToolPick rough = chooseM2DRoughingTool(p, tech(), lib(), "steel-s45c");
        QVERIFY2(rough.choice, rough.problem.c_str());
        QCOMPARE(tool(rough.choice->toolId).diameter, 10.0);
        QVERIFY(rough.choice->reason.str().find("corner radius 5.7 mm") != std::string::npos);
        auto steps = decomposeM2D(p, tech(), 10.0, 0);
        QVERIFY(chooseTools(steps, {}, lib(), "steel-s45c").empty());
        int faces = 0;
        for (const auto& s : steps)
            if (s.kind == StepKind::InclinedFaceFinishing) {
                ++faces;
                QCOMPARE(tool(s.tool->toolId).type, ToolType::BallEndMill);
                QCOMPARE(tool(s.tool->toolId).diameter, 12.0);  // radius 6 mm at most
            }
        QCOMPARE(faces, 2);
        // Steep walls: the deepest layer is 12.3 mm wide, so every layer takes the 6 mm end mill
        // the decomposition was made for, though the upper layers would take a 10 mm one.
        M2DPocket steep = p;
        steep.lengthX = 30;
        steep.theta1 = 30;
        const ToolPick six = chooseM2DRoughingTool(steep, tech(), lib(), "steel-s45c");
        QVERIFY2(six.choice, six.problem.c_str());
        QCOMPARE(tool(six.choice->toolId).diameter, 6.0);
        auto layers = decomposeM2D(steep, tech(), 6.0, 0);
        chooseTools(layers, {}, lib(), "steel-s45c");
        int roughing = 0;
        for (const auto& s : layers)
            if (s.kind == StepKind::Roughing) {
                ++roughing;
                QCOMPARE(s.tool->toolId, six.choice->toolId);
            }
        QVERIFY(roughing >= 3);
        // A narrow face: the ball's radius at most half its 7 mm length.
        p.lengthY = 7;
        p.cornerRadius = 2;
        p.depth = 8;
        auto narrow = decomposeM2D(p, tech(), 3.0, 0);
        const auto problems = chooseTools(narrow, {}, lib(), "steel-s45c");
        QVERIFY2(problems.empty(), problems.empty() ? "" : problems[0].c_str());
        QCOMPARE(tool(narrow.back().tool->toolId).diameter, 6.0);
        QVERIFY2(narrow.back().tool->reason.str().find("half the inclined face's length 7 mm") != std::string::npos,
                 narrow.back().tool->reason.str().c_str());
        // Pins apply to every step of their kind.
        auto pinned = decomposeM2D(p, tech(), 3.0, 0);
        QVERIFY(chooseTools(pinned, {{"inclined", 43}}, lib(), "steel-s45c").empty());
        for (const auto& s : pinned)
            if (s.kind == StepKind::InclinedFaceFinishing) QCOMPARE(s.tool->toolId, 43);
    }

    void withoutPilotHoleTheEndMillRampsIn()
    {
        auto steps = decomposeM4(pocket(6, 0, 9), tech(), 0);
        QVERIFY(chooseTools(steps, {}, lib(), "steel-s45c").empty());
        QVERIFY(QString::fromStdString(steps[0].tool->reason.str()).contains("ramps in"));
    }

    void rampingWithoutPilotHoleNeedsACentreCuttingEndMill()
    {
        auto library = lib();
        for (auto& t : library)
            if (t.id == 27) t.centreCutting = false;  // the 10 mm end mill cannot ramp in
        auto ramped = decomposeM4(pocket(6, 0, 9), tech(), 0);
        QVERIFY(chooseTools(ramped, {}, library, "steel-s45c").empty());
        QCOMPARE(ramped[0].kind, StepKind::Roughing);
        QCOMPARE(tool(ramped[0].tool->toolId).diameter, 8.0);
        QCOMPARE(ramped[0].tool->reason.str(), std::string("largest flat end mill (8 mm) whose radius 4 mm fits the corner radius "
                                                     "5.7 mm; it cuts at its centre and ramps in (no pilot hole)"));
        QCOMPARE(tool(ramped[1].tool->toolId).diameter, 8.0);  // floor finishing ramps into the beta2 left
        auto drilled = decomposeM4(pocket(6), tech(), 0);
        QVERIFY(chooseTools(drilled, {}, library, "steel-s45c").empty());
        QCOMPARE(drilled[1].tool->toolId, 27);  // it plunges into the pilot hole
        const auto pinned = [&] {
            auto s = decomposeM4(pocket(6, 0, 9), tech(), 0);
            return chooseTools(s, {{"roughing", 27}}, library, "steel-s45c");
        }();
        QCOMPARE(pinned.size(), std::size_t(1));
        QVERIFY2(QString::fromStdString(pinned[0]).contains("it does not cut at its centre"), pinned[0].c_str());
    }

    void thePilotDrillStaysWellBelowThePocketWidth()
    {
        M4Pocket slot = pocket(2);
        slot.corners = {{{0, 0}, {40, 0}, {40, 5}, {0, 5}}};  // roughed width 4.4 mm: a 2 mm end mill, no drill below 2.5 mm (the M3 tap drill)
        slot.depth = 5;
        auto steps = decomposeM4(slot, tech(), 0);
        const auto problems = chooseTools(steps, {}, lib(), "aluminium-6061");
        QCOMPARE(tool(steps[1].tool->toolId).diameter, 2.0);
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY2(QString::fromStdString(problems[0]).startsWith("Pilot hole: no drill in the tool library fits the pilot hole") &&
                     QString::fromStdString(problems[0]).contains("its diameter 2.5 mm is too large for the pocket"),
                 problems[0].c_str());
        slot.pilotHole = 9;  // the operator's way out: ramp in
        auto ramped = decomposeM4(slot, tech(), 0);
        QVERIFY(chooseTools(ramped, {}, lib(), "aluminium-6061").empty());
    }

    void taperedWallsTakeTheTaperEndMillOfTheirAngle()
    {
        auto steps = decomposeM4(pocket(6, 5), tech(), 0);
        QVERIFY(chooseTools(steps, {}, lib(), "aluminium-6061").empty());
        const Tool& t = tool(steps.back().tool->toolId);
        QCOMPARE(t.type, ToolType::TaperEndMill);
        QCOMPARE(t.taperAngle, 5.0);
        auto four = decomposeM4(pocket(6, 4), tech(), 0);
        const auto problems = chooseTools(four, {}, lib(), "aluminium-6061");
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY2(QString::fromStdString(problems[0]).contains("no taper end mill of 4 deg per side"), problems[0].c_str());
        // The tip must fit the corner at the floor: r1 4 - 12 x tan 10 deg = 1.88 mm < the 10 deg mill's 3 mm tip radius.
        auto steep = decomposeM4(pocket(4, 10), tech(), 0);
        const auto tight = chooseTools(steep, {}, lib(), "aluminium-6061");
        QCOMPARE(tight.size(), std::size_t(1));
        QVERIFY2(QString::fromStdString(tight[0]).contains("radius 3 mm is larger than the corner radius 1.884"), tight[0].c_str());
    }

    void pinsOverrideButAreChecked()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);
        QVERIFY(chooseTools(steps, {{"roughing", 26}}, lib(), "aluminium-6061").empty());
        QCOMPARE(steps[1].tool->toolId, 26);
        QCOMPARE(steps[1].tool->reason.str(), std::string("pinned by the operator"));
        auto again = decomposeM4(pocket(6), tech(), 0);
        const auto problems = chooseTools(again, {{"roughing", 28}}, lib(), "aluminium-6061");  // 12 mm
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY2(QString::fromStdString(problems[0]).contains("radius 6 mm is larger than the corner radius 5.7 mm"), problems[0].c_str());
    }

    void nothingFitsATinyCorner()
    {
        auto steps = decomposeM4(pocket(1.1), tech(), 0);  // roughing radius 0.8 < the 2 mm end mill's 1 mm
        const auto problems = chooseTools(steps, {}, lib(), "aluminium-6061");
        QVERIFY(!problems.empty());
        QVERIFY2(QString::fromStdString(problems[0]).startsWith("Roughing I: no flat end mill in the tool library fits"), problems[0].c_str());
    }

    void orderHonoursDependenciesAndSavesToolChanges()
    {
        std::mt19937 rng(7);
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<Step> steps;
            const int units = 1 + static_cast<int>(rng() % 5);
            for (int u = 0; u < units; ++u) {
                std::vector<Step> s;
                if (rng() % 3 == 0) {
                    M2DPocket p;
                    p.lengthX = 80;
                    p.lengthY = 50;
                    p.depth = 10 + static_cast<double>(rng() % 10);
                    p.theta1 = 10;
                    p.cornerRadius = 4 + static_cast<double>(rng() % 4);
                    p.toolUse = rng() % 2 ? 1 : 9;
                    p.pilotHole = rng() % 2 ? 0 : 9;
                    s = decomposeM2D(p, tech(), 6.0, u);
                } else {
                    const int codes[] = {1, 6, 7, 8, 9};
                    M4Pocket p = pocket(3 + static_cast<double>(rng() % 8), rng() % 4 ? 0 : 3);
                    p.toolUse = codes[rng() % 5];
                    p.wallFinish = 1 + static_cast<int>(rng() % 3);
                    p.pilotHole = rng() % 2 ? 0 : 9;
                    s = decomposeM4(p, tech(), u);
                }
                QVERIFY(chooseTools(s, {}, lib(), "aluminium-6061").empty());
                steps.insert(steps.end(), s.begin(), s.end());
            }
            const auto order = orderSteps(steps);
            QCOMPARE(order.size(), steps.size());
            std::vector<int> naive(steps.size());
            std::iota(naive.begin(), naive.end(), 0);
            QVERIFY(changes(steps, order) <= changes(steps, naive));
            // Every dependency: pilot before roughing before finishing, layers and passes in number order.
            std::vector<std::size_t> at(steps.size());
            for (std::size_t k = 0; k < order.size(); ++k) at[static_cast<std::size_t>(order[k])] = k;
            for (std::size_t a = 0; a < steps.size(); ++a)
                for (std::size_t b = 0; b < steps.size(); ++b) {
                    if (steps[a].unit != steps[b].unit) continue;
                    const auto rank = [](const Step& s) { return s.kind == StepKind::PilotHole ? 0 : s.kind == StepKind::Roughing ? 1 : 2; };
                    if (rank(steps[a]) < rank(steps[b])) QVERIFY(at[a] < at[b]);
                    if (steps[a].kind == steps[b].kind && steps[a].number < steps[b].number &&
                        (steps[a].kind == StepKind::WallFinishing || steps[a].kind == StepKind::Roughing))
                        QVERIFY(at[a] < at[b]);
                }
        }
        // Three identical units: 3 x (drill, rough, finish) in unit order is 9 changes, grouped 3.
        std::vector<Step> three;
        for (int u = 0; u < 3; ++u) {
            M4Pocket p = pocket(6);
            p.toolUse = 6;
            auto s = decomposeM4(p, tech(), u);
            chooseTools(s, {}, lib(), "aluminium-6061");
            three.insert(three.end(), s.begin(), s.end());
        }
        std::vector<int> naive(three.size());
        std::iota(naive.begin(), naive.end(), 0);
        QCOMPARE(changes(three, naive), 6);  // drill, 10 mm (rough + floor) per unit
        QCOMPARE(changes(three, orderSteps(three)), 2);
    }

    void toolLifeNotesPlanTheChange()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);
        chooseTools(steps, {}, lib(), "aluminium-6061");
        for (auto& s : steps) s.minutes = 70.0;  // the 10 mm end mill has 120 min of life
        const auto notes = planToolLife(steps, lib());
        QCOMPARE(notes.size(), std::size_t(1));
        QCOMPARE(notes[0].stepIndex, 2);  // roughing 70 + floor 70 > 120
        QCOMPARE(notes[0].toolId, 27);
        QCOMPARE(notes[0].message, std::string("T27 (10 mm flat end mill) reaches its life during step 3 (unit 1 Floor "
                                               "finishing I): 50.0 min left, the step needs 70.0 min; change it for a "
                                               "fresh one before that step"));
        // A worn tool: 100 of its 120 min used, so the roughing step already exceeds it.
        auto worn = lib();
        for (auto& t : worn)
            if (t.id == 27) t.usedMinutes = 100;
        const auto early = planToolLife(steps, worn);
        QCOMPARE(early.size(), std::size_t(2));  // changed before step 2, and again before step 3 (70 + 70 > 120)
        QCOMPARE(early[0].stepIndex, 1);
        QCOMPARE(early[1].stepIndex, 2);
        for (auto& s : steps) s.minutes = 10.0;
        QVERIFY(planToolLife(steps, lib()).empty());
    }
};

QTEST_APPLESS_MAIN(TestToolChoice)
#include "test_tool_choice.moc"
