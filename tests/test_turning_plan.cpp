// Turning steps (core/modules/turn/turn_plan.h) and the lathe tape: which steps a
// turned profile gets and in what order, the tools chosen and why, roughing
// as the control's G71 cycle or explicit passes, grooving's plunges and its
// withdrawal along the surface normal, the FANUC G71 P/Q numbers pointing at
// the contour's first and last block, threading (its passes, speed and
// feed, the G76 words), pins and steps turned off kept in the job file, and
// every refusal with its message. The paths themselves are
// judged by LinuxCNC and an oracle in test_rs274_turning.
#include "job/job_file.h"
#include "modules/registry.h"
#include "model/turned_geometry.h"
#include "model/turn_path.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "sim/turned_stock.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "turning/allowance.h"
#include "modules/turn/turn_plan.h"

#include <nlohmann/json.hpp>

#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>

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
        QVERIFY(turnOf(rough)->path.cycle.has_value());
        QCOMPARE(turnOf(rough)->path.cycle->depthOfCut, 2.0);  // steel's depth of cut
        QCOMPARE(turnOf(rough)->allowanceX, 0.2);
        const Step& finish = *find(p, StepKind::TurnFinishing);
        QCOMPARE(finish.tool->toolId, 102);  // reaches everything, smallest nose radius, lowest number
        QVERIFY2(finish.tool->reason.str().find("reaches every element") != std::string::npos, finish.tool->reason.str().c_str());
        QCOMPARE(turnOf(finish)->path.comp, NoseCompensation::Right);  // G42 outside
        QCOMPARE(turnOf(finish)->orientation, 2);
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
        const auto& moves = turnOf(*find(p, StepKind::TurnRoughing))->path.moves;
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
        QVERIFY(!turnOf(*find(p, StepKind::TurnRoughing))->path.cycle);  // not monotone: explicit passes
        const Step& g = *find(p, StepKind::Grooving);
        QCOMPARE(g.tool->toolId, 105);
        // Plunges (blade 3 mm, groove 4 mm): two, less than a blade width apart, to the bottom Ø24.
        std::vector<ZR> bottoms;
        for (const auto& m : turnOf(g)->path.moves)
            if (m.kind == TurnMove::Feed && m.feed == FeedKind::Plunge) bottoms.push_back(m.end);
        QCOMPARE(bottoms.size(), std::size_t(2));
        QVERIFY(std::abs(bottoms[0].z - bottoms[1].z) < 3.0);
        for (const ZR b : bottoms) QVERIFY(std::abs(b.r - 12.0) < 1e-3);
        QVERIFY(std::abs(bottoms.front().z + 20.0) < 1e-3 && std::abs(bottoms.back().z + 21.0) < 1e-3);  // both walls
        // Seed 002: the move after the last plunge is the normal (+X) times da.
        const auto& moves = turnOf(g)->path.moves;
        std::size_t last = moves.size();
        while (last > 0 && moves[last - 1].kind != TurnMove::Feed) --last;
        QVERIFY(last >= 2);
        const TurnMove& away = moves[last - 1];
        QCOMPARE(away.feed, FeedKind::Cut);
        QCOMPARE(turnOf(g)->withdrawal, 0.3);
        QVERIFY(std::abs(away.end.r - (bottoms.back().r + 0.3)) < 1e-9 && std::abs(away.end.z - bottoms.back().z) < 1e-9);
        QCOMPARE(moves[last - 2].end, bottoms.back());
        // The finishing contour runs across the groove's mouth: nothing below Ø30 between its walls.
        for (const auto& m : turnOf(*find(p, StepKind::TurnFinishing))->path.moves)
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
        QVERIFY2(d.diameter >= 16.0 && d.diameter <= 20.0 - 0.4 - 1.0, drill.tool->reason.str().c_str());  // the boring bar enters; the bore keeps stock
        QVERIFY(!turnOf(drill)->cutting.constantSurfaceSpeed && turnOf(drill)->cutting.rpm > 0);
        const Step& bore = *find(p, StepKind::TurnFinishing, 1);
        QCOMPARE(bore.tool->toolId, 104);
        QCOMPARE(turnOf(bore)->path.comp, NoseCompensation::Left);  // G41 inside
        QCOMPARE(turnOf(bore)->orientation, 3);
        QVERIFY(turnOf(*find(p, StepKind::TurnRoughing, 1))->path.cycle->inner);
        // The boring bar leaves the bore along the axis before the turret moves.
        const ZR out = turnOf(bore)->path.moves.back().end;
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
        QCOMPARE(find(p, StepKind::TurnFinishing)->tool->reason.str(), std::string("pinned"));
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

    void threadIsCutAfterFinishingInDecreasingPasses()
    {
        const Job j = sample("lathe-threaded-shaft");
        const Plan p = plan(j);
        QVERIFY2(p.ok(), firstError(p).c_str());
        QCOMPARE(kinds(p), (std::vector<StepKind>{StepKind::Facing, StepKind::TurnRoughing, StepKind::TurnFinishing, StepKind::Grooving,
                                                  StepKind::Threading, StepKind::Parting}));
        const Step& s = *find(p, StepKind::Threading);
        QCOMPARE(s.tool->toolId, 107);
        QCOMPARE(s.label(), std::string("Threading I"));
        const TurnStep& ts = *turnOf(s);
        QVERIFY(ts.thread);
        const TurnThread& th = *ts.thread;
        // M20×2.5: ISO depth 0.6134 P on the radius, fixed rpm from the
        // insert's surface speed at Ø20, the pitch as the feed.
        QCOMPARE(th.pitch, 2.5);
        QVERIFY(std::abs(th.depth - 0.6134 * 2.5) < 1e-9);
        QCOMPARE(th.crestR, 10.0);
        QVERIFY(!ts.cutting.constantSurfaceSpeed);
        QCOMPARE(ts.cutting.feedPerRev, 2.5);
        const Tool& tool = *findTool(defaultToolLibrary(), 107);
        const double vc = tool.cuttingFor(j.material)->surfaceSpeed;
        // The lathe's feed limit (5000 mm/min) holds it below the 3979 rpm
        // the insert's surface speed asks for at Ø20.
        QVERIFY(1000.0 * vc / (std::numbers::pi * 20.0) > 2000.0);
        QCOMPARE(ts.cutting.rpm, 2000.0);
        // Constant chip area: depth_k = first × √k, increments decreasing,
        // then the full depth and a spring pass; the increments sum to the depth.
        const auto& d = th.passDepths;
        QVERIFY(d.size() >= 5);
        QCOMPARE(d.front(), th.firstDepth);
        QCOMPARE(d.back(), th.depth);
        QCOMPARE(d[d.size() - 2], th.depth);
        double sum = 0.0, previous = 1e9;
        for (std::size_t k = 0; k + 1 < d.size(); ++k) {
            const double step = d[k] - (k ? d[k - 1] : 0.0);
            QVERIFY2(step > 0 && step <= previous + 1e-12, qPrintable(QString("pass %1 cuts %2 after %3").arg(k + 1).arg(step).arg(previous)));
            if (k + 2 < d.size()) QVERIFY(std::abs(d[k] - th.firstDepth * std::sqrt(static_cast<double>(k + 1))) < 1e-12);
            previous = step;
            sum += step;
        }
        QVERIFY(std::abs(sum - th.depth) < 1e-12);
        // The path: one synchronised feed along Z per pass at its depth,
        // from the run-in in front of the thread to its end in the relief.
        std::vector<TurnMove> feeds;
        for (const auto& m : ts.path.moves)
            if (m.kind != TurnMove::Rapid) feeds.push_back(m);
        QCOMPARE(feeds.size(), d.size());
        for (std::size_t k = 0; k < d.size(); ++k) QVERIFY(std::abs(feeds[k].end.r - (10.0 - d[k])) < 1e-12);
        QCOMPARE(feeds.back().end.z, th.zEnd);
        QVERIFY(th.zEnd < -25.0 && th.zEnd > -31.0 + 2.5);  // into the relief, a pitch clear of its far wall
        QVERIFY(ts.path.start.z > 0.0 && ts.path.start.r > 10.0);
        // The tapes' cycles (docs/turning.md "Threading").
        const auto nc = [&](const char* dialect) {
            return QString::fromStdString(postProcess(p.steps, p.tools, postOptions(p, dialect, LengthUnit::Millimetre, 1000, "T")).nc);
        };
        QVERIFY2(nc("linuxcnc").contains("G76 P2.5 Z-26.25 I-4 J0.97 R2 K3.067 Q29.5 H1"), qPrintable(nc("linuxcnc")));
        QVERIFY2(nc("fanuc").contains(QRegularExpression(R"(N\d+ G76 P020060 Q50 R0\.\nN\d+ G76 X16\.933 Z-26\.25 P153[34] Q485 F2\.5\n)")),
                 qPrintable(nc("fanuc")));
        QVERIFY2(nc("haas").contains(QRegularExpression(R"(G76 X16\.933 Z-26\.25 K1\.53[34] D0\.485 F2\.5 A60 P1)")), qPrintable(nc("haas")));
        QVERIFY2(nc("sinumerik").contains(QRegularExpression(R"(G33 X16\.933 Z-26\.25 K2\.5)")), qPrintable(nc("sinumerik")));
        // The job file keeps the attribute.
        const std::string text = writeJob(j);
        QVERIFY(text.find("\"thread\": {\n") != std::string::npos);
        QCOMPARE(*readJob(text).job, j);
    }

    void threadRefusals_data()
    {
        QTest::addColumn<int>("row");       // 0-based row of the sample to change
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("words");
        QTest::newRow("arc") << 5 << "arc" << "rows[6].thread" << "E6 is an arc";
        QTest::newRow("face") << 2 << "face" << "rows[3].thread" << "E3 is not a cylinder";
        QTest::newRow("pitch") << 1 << "pitch 10" << "rows[2].thread.pitch" << "a pitch of 10 mm is out of range";
        QTest::newRow("depth") << 1 << "depth 3" << "rows[2].thread.depth" << "a thread 3 mm deep does not fit Ø20 mm";
        QTest::newRow("no tool") << 1 << "pitch 4" << "rows[2].thread.pitch" << "no external threading insert";
        QTest::newRow("shoulder") << 2 << "shoulder" << "rows" << "the thread on E2 ends at a shoulder";
    }
    void threadRefusals()
    {
        QFETCH(int, row);
        QFETCH(QString, change);
        QFETCH(QString, field);
        QFETCH(QString, words);
        Job j = sample("lathe-threaded-shaft");
        auto& t = j.units[0];
        turning::TurnedProfile p = *moduleKind(t.module).turnedProfile(t.module);
        auto& r = p.rows[static_cast<std::size_t>(row)];
        auto& thread = p.rows[1].attributes.thread;  // the sample's M20×2.5
        if (change == "arc" || change == "face") {  // the thread moved to another row
            r.attributes.thread = thread;
            thread.reset();
        }
        if (change == "arc") {
            r.kind = turning::ElementKind::ArcCCW;
            r.radius = 40.0;
        }
        if (change == "pitch 10") thread->pitch = 10;
        if (change == "pitch 4") thread->pitch = 4;
        if (change == "depth 3") thread->depth = 3;
        if (change == "shoulder") {  // a collar right behind the thread: no relief
            p.rows.resize(4);
            p.rows[2].x = p.rows[3].x = 30.0;
            p.rows[3].z = -55.0;
        }
        moduleKind(t.module).setTurnedProfile(t.module, p);
        const Plan pl = plan(j);
        QVERIFY(!pl.ok());
        const std::string e = firstError(pl);
        QVERIFY2(e.starts_with(field.toStdString() + ": ") && e.find(words.toStdString()) != std::string::npos, e.c_str());
    }

    void innerThreadIsRefused()
    {
        // The bushing's bore, its first row along the axis asked for a thread.
        Job j = sample("lathe-bushing");
        for (auto& t : j.units) {
            turning::TurnedProfile p = *moduleKind(t.module).turnedProfile(t.module);
            if (p.side != turning::ProfileSide::Inner) continue;
            double x = p.startX;
            for (std::size_t i = 0; i < p.rows.size(); ++i) {
                if (p.rows[i].kind == turning::ElementKind::Line && p.rows[i].x == x) {
                    p.rows[i].attributes.thread = turning::ThreadSpec{1.5, std::nullopt};
                    moduleKind(t.module).setTurnedProfile(t.module, p);
                    const Plan pl = plan(j);
                    QVERIFY(!pl.ok());
                    const std::string e = firstError(pl);
                    QVERIFY2(e.starts_with("rows[" + std::to_string(i + 1) + "].thread: ") && e.find("internal threads are not cut yet") != std::string::npos,
                             e.c_str());
                    return;
                }
                x = p.rows[i].x;
            }
        }
        QFAIL("the bushing has no straight bore row");
    }

    void noThreadingToolIsRefused()
    {
        std::vector<Tool> library = defaultToolLibrary();
        std::erase_if(library, [](const Tool& t) { return t.type == ToolType::Threading; });
        const Plan p = plan(sample("lathe-threaded-shaft"), library);
        QVERIFY(!p.ok());
        QVERIFY2(firstError(p).find("rows[2].thread.pitch: no external threading insert of the tool library cuts a pitch of 2.5 mm") !=
                     std::string::npos,
                 firstError(p).c_str());
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
