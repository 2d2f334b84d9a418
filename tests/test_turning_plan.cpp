// Turning steps (core/turning/turn_plan.h) and the lathe tape: which steps a
// turned profile gets and in what order, the tools chosen and why, roughing
// as the control's G71 cycle or explicit passes, grooving's plunges and its
// withdrawal along the surface normal, the FANUC G71 P/Q numbers pointing at
// the contour's first and last block, pins and steps turned off kept in the
// job file, and every refusal with its message. The paths themselves are
// judged by LinuxCNC and an oracle in test_rs274_turning.
#include "job/job_file.h"
#include "modules/registry.h"
#include "model/turned_geometry.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "sim/turned_stock.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "turning/allowance.h"
#include "turning/turn_plan.h"

#include <nlohmann/json.hpp>

#include <QRegularExpression>
#include <QtTest>

#include <algorithm>

using namespace taiwa;
using turning::ZR;

namespace {

Job sample(const char* name)
{
    auto r = readJobFile(test::sourcePath(QString("resources/samples/%1.taiwa").arg(name)).toStdString());
    if (!r.job) qFatal("cannot read sample %s", name);
    return *r.job;
}

Plan plan(const Job& job, const std::vector<Tool>& library = defaultToolLibrary())
{
    return planJob(job, TechnologyTable::builtIn(), library);
}

std::vector<StepKind> kinds(const Plan& p)
{
    std::vector<StepKind> k;
    for (const auto& s : p.steps) k.push_back(s.kind);
    return k;
}

const Step* find(const Plan& p, StepKind k, int unit = -1)
{
    for (const auto& s : p.steps)
        if (s.kind == k && (unit < 0 || s.unit == unit)) return &s;
    return nullptr;
}

std::string firstError(const Plan& p)
{
    for (const auto& d : p.diagnostics)
        if (d.severity == Severity::Error) return d.field + ": " + d.message;
    return {};
}

// A job of one outer profile on a Ø40 bar from the rows' (diameter, Z) end points.
Job shaft(std::vector<std::pair<double, double>> ends)
{
    Job j = sample("lathe-grooved-shaft");
    auto& t = j.units[0];
    turning::TurnedProfile p = *moduleKind(t.module).turnedProfile(t.module);
    p.rows.clear();
    int id = 1;
    for (auto [x, z] : ends) {
        turning::ProfileRow r;
        r.id = id++;
        r.x = x;
        r.z = z;
        p.rows.push_back(r);
    }
    moduleKind(t.module).setTurnedProfile(t.module, p);
    return j;
}

}  // namespace

class TestTurningPlan : public QObject {
    Q_OBJECT

private slots:
    void monotoneShaftRoughsInTheControlsCycle()
    {
        const Plan p = plan(sample("lathe-turned-shaft"));
        QVERIFY2(p.ok(), firstError(p).c_str());
        QCOMPARE(kinds(p), (std::vector<StepKind>{StepKind::Facing, StepKind::TurnRoughing, StepKind::TurnFinishing, StepKind::Parting}));
        const Step& rough = *find(p, StepKind::TurnRoughing);
        QCOMPARE(rough.tool->toolId, 101);  // the strongest nose
        QVERIFY(rough.turn->path.cycle.has_value());
        QCOMPARE(rough.turn->path.cycle->depthOfCut, 2.0);  // steel's depth of cut
        QCOMPARE(rough.turn->allowanceX, 0.2);
        const Step& finish = *find(p, StepKind::TurnFinishing);
        QCOMPARE(finish.tool->toolId, 102);  // reaches everything, smallest nose radius, lowest number
        QVERIFY2(finish.tool->reason.find("reaches every element") != std::string::npos, finish.tool->reason.c_str());
        QCOMPARE(finish.turn->path.comp, NoseCompensation::Right);  // G42 outside
        QCOMPARE(finish.turn->orientation, 2);
        QCOMPARE(find(p, StepKind::Parting)->tool->toolId, 106);
        for (const auto& s : p.steps) QVERIFY(s.minutes && *s.minutes > 0);
    }

    void fanucG71PointsAtTheContour()
    {
        const Plan p = plan(sample("lathe-turned-shaft"));
        PostOptions o = postOptions(p, "fanuc", std::nullopt, 1000, "shaft");
        const std::string nc = postProcess(p.steps, defaultToolLibrary(), o).nc;
        const QStringList lines = QString::fromStdString(nc).split('\n');
        const auto m = QRegularExpression(R"(G71 P(\d+) Q(\d+) U0\.4 W0\.1 F0\.3)").match(QString::fromStdString(nc));
        QVERIFY2(m.hasMatch(), nc.c_str());
        int at = -1, pLine = -1, qLine = -1;
        for (int i = 0; i < lines.size(); ++i) {
            if (lines[i].contains("G71 P")) at = i;
            if (lines[i].startsWith("N" + m.captured(1) + " ")) pLine = i;
            if (lines[i].startsWith("N" + m.captured(2) + " ")) qLine = i;
        }
        QCOMPARE(pLine, at + 1);                               // the contour follows the cycle
        QCOMPARE(lines[pLine].mid(lines[pLine].indexOf(' ') + 1), QString("G0 X18."));  // type I: X alone, the chamfer's start
        QVERIFY2(lines[qLine].endsWith("G1 X54."), qPrintable(lines[qLine]));             // out over the bar at the end
        QVERIFY2(lines[qLine + 1].contains("G0 X54. Z2."), qPrintable(lines[qLine + 1]));  // after the cycle, not in it
        QVERIFY(nc.find("G50 S4500") != std::string::npos && nc.find("G96 S200 M3") != std::string::npos);
        QVERIFY(nc.find("T0101") != std::string::npos && nc.find("G99") != std::string::npos);
    }

    void explicitPassesWhenTheJobSaysSo()
    {
        Job j = sample("lathe-turned-shaft");
        j.latheRoughingCycles = false;
        const Plan p = plan(j);
        PostOptions o = postOptions(p, "linuxcnc", std::nullopt, 1000, "shaft");
        QVERIFY(!o.turningCycles);
        const std::string nc = postProcess(p.steps, defaultToolLibrary(), o).nc;
        QVERIFY(nc.find("G71") == std::string::npos && nc.find(" sub") == std::string::npos);
        const auto& moves = find(p, StepKind::TurnRoughing)->turn->path.moves;
        QVERIFY(std::count_if(moves.begin(), moves.end(), [](const TurnMove& m) { return m.kind == TurnMove::Feed; }) >= 8);
        // The job file keeps it, and only then says it.
        const std::string text = writeJob(j);
        QVERIFY(text.find("\"latheRoughing\": \"passes\"") != std::string::npos);
        QCOMPARE(*readJob(text).job, j);
        QVERIFY(writeJob(sample("lathe-turned-shaft")).find("latheRoughing") == std::string::npos);
    }

    void grooveIsPlungedAndWithdrawnAlongTheNormal()
    {
        const Plan p = plan(sample("lathe-grooved-shaft"));
        QVERIFY2(p.ok(), firstError(p).c_str());
        QCOMPARE(kinds(p), (std::vector<StepKind>{StepKind::Facing, StepKind::TurnRoughing, StepKind::TurnFinishing,
                                                  StepKind::Grooving, StepKind::Parting}));
        QVERIFY(!find(p, StepKind::TurnRoughing)->turn->path.cycle);  // not monotone: explicit passes
        const Step& g = *find(p, StepKind::Grooving);
        QCOMPARE(g.tool->toolId, 105);
        // Plunges (blade 3 mm, groove 4 mm): two, less than a blade width apart, to the bottom Ø24.
        std::vector<ZR> bottoms;
        for (const auto& m : g.turn->path.moves)
            if (m.kind == TurnMove::Feed && m.feed == FeedKind::Plunge) bottoms.push_back(m.end);
        QCOMPARE(bottoms.size(), std::size_t(2));
        QVERIFY(std::abs(bottoms[0].z - bottoms[1].z) < 3.0);
        for (const ZR b : bottoms) QVERIFY(std::abs(b.r - 12.0) < 1e-3);
        QVERIFY(std::abs(bottoms.front().z + 20.0) < 1e-3 && std::abs(bottoms.back().z + 21.0) < 1e-3);  // both walls
        // Seed 002: the move after the last plunge is the normal (+X) times da.
        const auto& moves = g.turn->path.moves;
        std::size_t last = moves.size();
        while (last > 0 && moves[last - 1].kind != TurnMove::Feed) --last;
        QVERIFY(last >= 2);
        const TurnMove& away = moves[last - 1];
        QCOMPARE(away.feed, FeedKind::Cut);
        QCOMPARE(g.turn->withdrawal, 0.3);
        QVERIFY(std::abs(away.end.r - (bottoms.back().r + 0.3)) < 1e-9 && std::abs(away.end.z - bottoms.back().z) < 1e-9);
        QCOMPARE(moves[last - 2].end, bottoms.back());
        // The finishing contour runs across the groove's mouth: nothing below Ø30 between its walls.
        for (const auto& m : find(p, StepKind::TurnFinishing)->turn->path.moves)
            if (m.end.z < -20.0 + 1e-9 && m.end.z > -24.0 - 1e-9) QVERIFY(m.end.r >= 15.0 - 1e-9);
    }

    void boreIsDrilledThenBoredInsideOut()
    {
        const Plan p = plan(sample("lathe-bushing"));
        QVERIFY2(p.ok(), firstError(p).c_str());
        QCOMPARE(kinds(p), (std::vector<StepKind>{StepKind::Facing, StepKind::CentreDrilling, StepKind::Drilling, StepKind::TurnRoughing,
                                                  StepKind::TurnRoughing, StepKind::TurnFinishing, StepKind::TurnFinishing,
                                                  StepKind::Parting}));
        const Step& drill = *find(p, StepKind::Drilling);
        const Tool& d = *findTool(defaultToolLibrary(), drill.tool->toolId);
        QCOMPARE(d.type, ToolType::Drill);
        QVERIFY2(d.diameter >= 16.0 && d.diameter <= 20.0 - 0.4 - 1.0, drill.tool->reason.c_str());  // the boring bar enters; the bore keeps stock
        QVERIFY(!drill.turn->cutting.constantSurfaceSpeed && drill.turn->cutting.rpm > 0);
        const Step& bore = *find(p, StepKind::TurnFinishing, 1);
        QCOMPARE(bore.tool->toolId, 104);
        QCOMPARE(bore.turn->path.comp, NoseCompensation::Left);  // G41 inside
        QCOMPARE(bore.turn->orientation, 3);
        QVERIFY(find(p, StepKind::TurnRoughing, 1)->turn->path.cycle->inner);
        // The boring bar leaves the bore along the axis before the turret moves.
        const ZR out = bore.turn->path.moves.back().end;
        QVERIFY(out.z > 0 && out.r < 10.0);
    }

    void pinsAndStepsTurnedOffAreKept()
    {
        nlohmann::ordered_json doc = nlohmann::ordered_json::parse(writeJob(sample("lathe-turned-shaft")));
        doc["units"][0]["tools"] = {{"turn-finish", 103}};
        doc["units"][0]["skip"] = {"part", "facing"};
        const auto read = readJob(doc.dump());
        QVERIFY(read.job);
        const Plan p = plan(*read.job);
        QVERIFY2(p.ok(), firstError(p).c_str());
        QCOMPARE(kinds(p), (std::vector<StepKind>{StepKind::TurnRoughing, StepKind::TurnFinishing}));
        QCOMPARE(find(p, StepKind::TurnFinishing)->tool->toolId, 103);
        QCOMPARE(find(p, StepKind::TurnFinishing)->tool->reason, std::string("pinned"));
        QCOMPARE(*readJob(writeJob(*read.job)).job, *read.job);  // round trip
        // An unknown step and a tool not in the library are refused on their fields.
        doc["units"][0]["skip"] = {"polish"};
        doc["units"][0]["tools"] = {{"turn-finish", 999}};
        const Plan bad = plan(*readJob(doc.dump()).job);
        QVERIFY(!bad.ok());
        bool skip = false, tool = false;
        for (const auto& d : bad.diagnostics) {
            skip = skip || (d.field == "skip[1]" && d.message.find("\"polish\" is not a turning step") != std::string::npos);
            tool = tool || (d.field == "tools.turn-finish" && d.message.find("T999 is not in the tool library") != std::string::npos);
        }
        QVERIFY(skip && tool);
    }

    void shoulderFacingTheChuckIsRefused()
    {
        // Ø30 then down to Ø20 toward the chuck: no right-hand insert finishes Ø20 behind the shoulder.
        const Plan p = plan(shaft({{30, 0}, {30, -20}, {20, -20}, {20, -40}}));
        QVERIFY(!p.ok());
        const std::string e = firstError(p);
        QVERIFY2(e.find("rows: E3 cannot be turned: it falls 90.0° behind the insert") != std::string::npos, e.c_str());
        QVERIFY2(e.find("shoulder facing the chuck") != std::string::npos, e.c_str());
    }

    void grooveNarrowerThanEveryBladeIsRefused()
    {
        const Plan p = plan(shaft({{30, 0}, {30, -20}, {26, -20}, {26, -22}, {30, -22}, {30, -40}}));
        QVERIFY(!p.ok());
        const std::string e = firstError(p);
        QVERIFY2(e.find("E3…E5 cannot be turned") != std::string::npos && e.find("as a groove it is 2 mm wide and 2 mm deep") != std::string::npos &&
                     e.find("T105") != std::string::npos,
                 e.c_str());
    }

    void noBladeForAGrooveIsRefused()
    {
        std::vector<Tool> library = defaultToolLibrary();
        std::erase_if(library, [](const Tool& t) { return t.type == ToolType::Grooving; });
        const Plan p = plan(sample("lathe-grooved-shaft"), library);
        QVERIFY(!p.ok());
        QVERIFY2(firstError(p).find("the tool library has no outside grooving blade") != std::string::npos, firstError(p).c_str());
    }

    void stockAfterEachStepShrinksToThePart()
    {
        const Plan p = plan(sample("lathe-turned-shaft"));
        const BarStock& bar = *p.mmJob.bar;
        const double R = bar.diameter / 2.0, barArea = R * bar.length;
        QVERIFY(std::abs(sim::loopsArea(sim::turnedStockAfter(p, -1)) - barArea) < 1e-3);
        // The part's half-section (its profile closed along the axis) and the bar left behind it.
        std::vector<turning::Segment> loop;
        for (const auto& e : p.turned.front().deformed.edges) loop.push_back(e.geometry);
        const ZR a = loop.front().a, b = loop.back().b;
        loop.push_back(turning::lineSegment(b, {b.z, 0.0}));
        loop.push_back(turning::lineSegment({b.z, 0.0}, a));
        const double part = std::abs(turning::signedArea(loop)) + R * (b.z - (bar.face - bar.length));
        double before = barArea;
        for (int k = 0; k < static_cast<int>(p.steps.size()) - 1; ++k) {  // up to finishing
            const double now = sim::loopsArea(sim::turnedStockAfter(p, k));
            QVERIFY2(now < before, qPrintable(QString("step %1 took nothing").arg(k + 1)));
            QVERIFY2(now > part - 0.5, qPrintable(QString("step %1 cut into the part: %2 < %3").arg(k + 1).arg(now).arg(part)));
            before = now;
        }
        // Finished: the part and the bar behind it, less what the nose's fillets keep.
        QVERIFY2(before - part < 0.5, qPrintable(QString("%1 left over %2").arg(before).arg(part)));
        // Parted off: the part and the bar's remnant apart, a blade's width less.
        const auto parted = sim::turnedStockAfter(p, static_cast<int>(p.steps.size()) - 1);
        QCOMPARE(parted.size(), std::size_t(2));
        QVERIFY(std::abs(sim::loopsArea(parted) - (before - 3.0 * R)) < 0.5);
    }

    void spindleLimitTooLowIsRefused()
    {
        // The planner on its own, with a lathe whose spindle stops at 100 rpm:
        // Ø18 turns at 6 m/min where the inserts need 200 and 250.
        const Job j = sample("lathe-turned-shaft");
        const auto& t = j.units[0];
        const turning::ResolvedProfile rp = turning::resolveProfile(*moduleKind(t.module).turnedProfile(t.module)).profile;
        const turning::DeformedProfile d = turning::applyAllowances(rp, {}).profile;
        const std::vector<Tool> library = defaultToolLibrary();
        turning::TurnPlanRequest q;
        q.deformed = &d;
        q.bar = *j.bar;
        q.library = &library;
        q.material = j.material;
        q.maxRpm = 100;
        const auto r = turning::planTurnedUnit(q);
        QVERIFY(!r.problems.empty());
        QCOMPARE(r.problems.front().field, std::string("tools.turn-rough"));
        QVERIFY2(r.problems.front().message.find("the spindle limit of 100 rpm turns Ø18 mm at only 6 m/min") != std::string::npos,
                 r.problems.front().message.c_str());
    }
};

QTEST_GUILESS_MAIN(TestTurningPlan)
#include "test_turning_plan.moc"
