// Tool choice on the default library: the largest end mill that fits the
// corner, the pilot drill chosen after the roughing tool, taper walls, pins,
// no-fit messages; the job-wide order honours every dependency and saves
// tool changes; tool-life notes.
#include "decompose/decompose.h"
#include "tools/tool_choice.h"
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
    void roughingTakesTheLargestEndMillThatFitsAndThePilotFollowsIt()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);  // roughing corner radius 5.7
        QVERIFY(chooseTools(steps, {}, lib(), "aluminium-6061").empty());
        const Tool& rough = tool(steps[1].tool->toolId);
        QCOMPARE(steps[1].kind, StepKind::Roughing);
        QCOMPARE(rough.type, ToolType::FlatEndMill);
        QCOMPARE(rough.diameter, 10.0);  // 12 mm would need radius 6 > 5.7
        QVERIFY(QString::fromStdString(steps[1].tool->reason).contains("fits the corner radius 5.7 mm"));
        QVERIFY(QString::fromStdString(steps[1].tool->reason).contains("pilot hole"));
        const Tool& drill = tool(steps[0].tool->toolId);
        QCOMPARE(drill.type, ToolType::Drill);
        QCOMPARE(drill.diameter, 10.0);  // the smallest drill not smaller than 10 mm
        const Tool& wall = tool(steps.back().tool->toolId);
        QCOMPARE(steps.back().kind, StepKind::WallFinishing);
        QCOMPARE(wall.diameter, 12.0);  // radius 6 fits the finished corner radius 6
    }

    void withoutPilotHoleTheEndMillRampsIn()
    {
        auto steps = decomposeM4(pocket(6, 0, 9), tech(), 0);
        QVERIFY(chooseTools(steps, {}, lib(), "steel-s45c").empty());
        QVERIFY(QString::fromStdString(steps[0].tool->reason).contains("ramps in"));
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
    }

    void pinsOverrideButAreChecked()
    {
        auto steps = decomposeM4(pocket(6), tech(), 0);
        QVERIFY(chooseTools(steps, {{"roughing", 26}}, lib(), "aluminium-6061").empty());
        QCOMPARE(steps[1].tool->toolId, 26);
        QCOMPARE(steps[1].tool->reason, std::string("pinned by the operator"));
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
                const int codes[] = {1, 6, 7, 8, 9};
                M4Pocket p = pocket(3 + static_cast<double>(rng() % 8));
                p.toolUse = codes[rng() % 5];
                p.wallFinish = 1 + static_cast<int>(rng() % 3);
                p.pilotHole = rng() % 2 ? 0 : 9;
                auto s = decomposeM4(p, tech(), u);
                QVERIFY(chooseTools(s, {}, lib(), "aluminium-6061").empty());
                steps.insert(steps.end(), s.begin(), s.end());
            }
            const auto order = orderSteps(steps);
            QCOMPARE(order.size(), steps.size());
            std::vector<int> naive(steps.size());
            std::iota(naive.begin(), naive.end(), 0);
            QVERIFY(changes(steps, order) <= changes(steps, naive));
            // Every dependency: pilot before roughing before finishing, passes in number order.
            std::vector<std::size_t> at(steps.size());
            for (std::size_t k = 0; k < order.size(); ++k) at[static_cast<std::size_t>(order[k])] = k;
            for (std::size_t a = 0; a < steps.size(); ++a)
                for (std::size_t b = 0; b < steps.size(); ++b) {
                    if (steps[a].unit != steps[b].unit) continue;
                    const auto rank = [](const Step& s) { return s.kind == StepKind::PilotHole ? 0 : s.kind == StepKind::Roughing ? 1 : 2; };
                    if (rank(steps[a]) < rank(steps[b])) QVERIFY(at[a] < at[b]);
                    if (steps[a].kind == StepKind::WallFinishing && steps[b].kind == StepKind::WallFinishing &&
                        steps[a].number < steps[b].number)
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
        QVERIFY2(QString::fromStdString(notes[0].message).contains("change it for a fresh one before that step"), notes[0].message.c_str());
    }
};

QTEST_APPLESS_MAIN(TestToolChoice)
#include "test_tool_choice.moc"
