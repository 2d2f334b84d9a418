// The two-path lathe and the gang-tool lathe (docs/two-path-lathe.md): their
// machine files read and refused (machine/lathe_kinds.h); balanced roughing
// on a cylinder and a taper (turning/balanced_roughing.h): the blocks
// alternate between the paths, path 2's coordinates are path 1's converted,
// the infeed is doubled after the first block, waits stand exactly where the
// previous meeting's cycles differ in length (none on the cylinder unless
// asked), every follower's dwell is at least the set revolutions at the
// spindle speed there (constant surface speed and G97), both paths' cuts
// together are the single path's, no more no less; the refusals; and the
// timeline (verify/two_path_timeline.h): no deadlock, the follower never
// closer than the set revolutions, the pair faster than one path, with
// negative controls (a wait removed deadlocks, dwells removed bring the
// follower too close; both are findings of taiwa verify, verify/two_path_check.h),
// on every two-path sample too; FANUC's pair of
// programs of the whole job (post/two_path_post.h) against golden files
// read by hand; and the gang-tool change (machine/gang_change.h): no X
// motion while any tool on the slide is inside the part's envelope plus
// the clearance, for every pair of the slide's tools.
#include "job/job_file.h"
#include "machine/gang_change.h"
#include "machine/machine.h"
#include "turning/balanced_roughing.h"
#include "pipeline/pipeline.h"
#include "post/two_path_post.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "verify/two_path_timeline.h"
#include "verify/two_path_check.h"

#include <nlohmann/json.hpp>

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QtTest>

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>

using namespace taiwa;
using turning::ZR;

namespace {

// The roughing step of a two-path sample (tests/data/two-path/STEM.taiwa).
std::map<std::string, Plan>& plansCache()
{
    static std::map<std::string, Plan> plans;
    return plans;
}
const Step& roughingStep(const std::string& stem)
{
    auto& plans = plansCache();
    auto it = plans.find(stem);
    if (it == plans.end()) {
        auto r = readJobFile(test::dataPath(QString::fromStdString("two-path/" + stem + ".taiwa")).toStdString());
        if (!r.job) qFatal("cannot read %s", stem.c_str());
        it = plans.emplace(stem, planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary())).first;
    }
    for (const auto& s : it->second.steps)
        if (s.kind == StepKind::TurnRoughing) return s;
    std::string why;
    for (const auto& d : it->second.diagnostics) why += d.field + ": " + d.message + "; ";
    qFatal("no roughing step in %s: %s", stem.c_str(), why.c_str());
}
const TurnStep& roughing(const std::string& stem) { return *roughingStep(stem).turn; }
const Plan& planOf(const std::string& stem)
{
    roughingStep(stem);
    return plansCache().at(stem);
}

const std::string kCylinder = "lathe-two-path-cylinder";  // Ø40 bar to Ø20
const std::string kTaper = "lathe-two-path-taper";        // Ø40 bar to a Ø16–Ø36 taper

const Machine& twoPath()
{
    const Machine* m = findMachine("lathe-two-path");
    if (!m) qFatal("no two-path lathe");
    return *m;
}

BalancedCut balanced(const TurnStep& s, const turning::BalanceSettings& settings = {}, const Machine& m = twoPath())
{
    auto r = turning::balanceRoughing(s.path, s.cutting, m, settings);
    if (!r) qFatal("%s", r.error().c_str());
    return *r;
}

// Every block of the cut, by CB number.
std::vector<const BalancedBlock*> byNumber(const BalancedCut& c)
{
    std::vector<const BalancedBlock*> all(static_cast<std::size_t>(c.blockCount), nullptr);
    for (const auto& p : c.paths)
        for (const auto& b : p.blocks) all.at(static_cast<std::size_t>(b.number - 1)) = &b;
    return all;
}

// The feed moves of a path (start, end) in path 1's coordinates.
using Feed = std::pair<ZR, ZR>;
std::vector<Feed> feedsOf(const TurnPath& p)
{
    std::vector<Feed> f;
    ZR at = p.start;
    for (const auto& m : p.moves) {
        if (m.kind != TurnMove::Rapid) f.emplace_back(at, m.end);
        at = m.end;
    }
    return f;
}

bool near(ZR a, ZR b) { return std::abs(a.z - b.z) < 1e-9 && std::abs(a.r - b.r) < 1e-9; }

std::string refusal(const std::function<void(nlohmann::json&)>& change, const char* file = "lathe-two-path.json")
{
    nlohmann::json j = nlohmann::json::parse(test::readFile(test::sourcePath(QString("resources/machines/") + file)));
    change(j);
    auto m = readMachine(j.dump(2), "mine.json");
    return m ? std::string() : m.error();
}

// The spindle speed at a radius, as the test reckons it (not the code's).
double rpmAt(const TurnCutting& c, double limit, double r)
{
    if (!c.constantSurfaceSpeed) return c.rpm;
    return std::min(limit, 1000.0 * c.surfaceSpeed / (std::numbers::pi * 2 * std::abs(r)));
}

}  // namespace

class TestTwoPath : public QObject {
    Q_OBJECT

private slots:
    void shippedMachinesRead()
    {
        const Machine& m = twoPath();
        QVERIFY(m.layout.multiPath);
        QCOMPARE(m.layout.pathCount(), std::size_t{2});
        QCOMPARE(m.layout.multiPath->paths[1].xDirection, -1);
        QCOMPARE(m.layout.multiPath->waitCodes.first, 101);
        const Machine* g = findMachine("lathe-gang");
        QVERIFY(g && g->layout.gang && !g->layout.multiPath);
        QVERIFY(g->layout.gang->place(102));
        QCOMPARE(g->layout.gang->place(102)->offset.r, 60.0);  // x 120 on the diameter
        QVERIFY(!findMachine("lathe")->layout.multiPath && !findMachine("lathe")->layout.gang);
        // Path 2's program is path 1's converted, and back.
        MultiPath mp = *m.layout.multiPath;
        mp.paths[1].origin = {5.0, 100.0};
        const ZR p{-30.0, 12.0};
        const ZR q = mp.fromPath1(p, 1);
        QCOMPARE(q.z, -35.0);
        QCOMPARE(q.r, 88.0);  // machine r 12, path 2's zero at 100, X mirrored
        QVERIFY(near(mp.toPath1(q, 1), p));
    }

    void machineFilesRefused_data()
    {
        QTest::addColumn<int>("which");
        QTest::addColumn<QString>("expected");
        QTest::newRow("one path") << 0 << "paths: must be a list of 2 or 3 paths";
        QTest::newRow("direction") << 1 << "paths[1].direction.x: must be 1 or -1";
        QTest::newRow("same side") << 2 << "paths[1].direction.x: path 2 must face path 1";
        QTest::newRow("no waits") << 3 << "waitCodes: missing";
        QTest::newRow("wait range") << 4 << "waitCodes.last: must be a whole M number from waitCodes.first";
        QTest::newRow("unknown key") << 5 << "paths[0].turrets: unknown key";
        QTest::newRow("gang without offset") << 6 << "gangSlide.tools[1].offset: missing";
        QTest::newRow("gang tool twice") << 7 << "gangSlide.tools[1].tool: tool 101 is on the slide twice";
        QTest::newRow("gang no clearance") << 8 << "gangSlide.clearance: must be a number above zero";
    }
    void machineFilesRefused()
    {
        QFETCH(int, which);
        QFETCH(QString, expected);
        using J = nlohmann::json;
        const std::vector<std::pair<std::function<void(J&)>, const char*>> changes{
            {[](J& j) { j["paths"].erase(1); }, "lathe-two-path.json"},
            {[](J& j) { j["paths"][1]["direction"]["x"] = 2; }, "lathe-two-path.json"},
            {[](J& j) { j["paths"][1]["direction"]["x"] = 1; }, "lathe-two-path.json"},
            {[](J& j) { j.erase("waitCodes"); }, "lathe-two-path.json"},
            {[](J& j) { j["waitCodes"]["last"] = 100; }, "lathe-two-path.json"},
            {[](J& j) { j["paths"][0]["turrets"] = 2; }, "lathe-two-path.json"},
            {[](J& j) { j["gangSlide"]["tools"][1].erase("offset"); }, "lathe-gang.json"},
            {[](J& j) { j["gangSlide"]["tools"][1]["tool"] = 101; }, "lathe-gang.json"},
            {[](J& j) { j["gangSlide"]["clearance"] = 0; }, "lathe-gang.json"},
        };
        const auto& [change, file] = changes.at(static_cast<std::size_t>(which));
        const std::string e = refusal(change, file);
        QVERIFY2(QString::fromStdString(e).contains(expected), e.c_str());
        QVERIFY2(e.rfind("mine.json:", 0) == 0, e.c_str());
        // The unchanged file reads (the negative control).
        QVERIFY(refusal([](J&) {}, file).empty());
    }

    void blocksAlternateConvertedAndDoubled_data()
    {
        QTest::addColumn<bool>("taper");
        QTest::newRow("cylinder") << false;
        QTest::newRow("taper") << true;
    }
    void blocksAlternateConvertedAndDoubled()
    {
        QFETCH(bool, taper);
        const TurnStep& s = roughing(taper ? kTaper : kCylinder);
        const auto single = turning::analyseRoughing(s.path);
        QVERIFY(single.blocks.size() >= 5);
        const BalancedCut c = balanced(s);
        QCOMPARE(c.paths.size(), std::size_t{2});
        QCOMPARE(c.blockCount, static_cast<int>(single.blocks.size()));
        const auto all = byNumber(c);
        const MultiPath& mp = *twoPath().layout.multiPath;
        const double depth = std::abs(single.blocks[1].level - single.blocks[0].level);
        QVERIFY(depth > 0.5);
        for (std::size_t k = 0; k < all.size(); ++k) {
            QVERIFY(all[k]);
            QCOMPARE(all[k]->path, k % 2);  // CB1 path 1, CB2 path 2, CB3 path 1 …
            // Path 2's moves are path 1's converted: X mirrored, Z kept.
            QCOMPARE(all[k]->moves.size(), single.blocks[k].moves.size());
            for (std::size_t i = 0; i < all[k]->moves.size(); ++i) {
                const ZR want = all[k]->path == 0 ? single.blocks[k].moves[i].end : mp.fromPath1(single.blocks[k].moves[i].end, 1);
                QVERIFY(near(all[k]->moves[i].end, want));
                if (all[k]->path == 1 && std::abs(want.r) > 1e-9) QVERIFY(all[k]->moves[i].end.r * single.blocks[k].moves[i].end.r < 0);
            }
            // The first block's infeed is one depth of cut, every other's two.
            QCOMPARE_LE(std::abs(all[k]->infeed - (k == 0 ? 1.0 : 2.0) * depth), 1e-6);
        }
    }

    void waitsWhereCyclesDiffer_data()
    {
        QTest::addColumn<bool>("taper");
        QTest::addColumn<bool>("everywhere");
        QTest::newRow("cylinder") << false << false;
        QTest::newRow("cylinder, waits asked") << false << true;
        QTest::newRow("taper") << true << false;
    }
    void waitsWhereCyclesDiffer()
    {
        QFETCH(bool, taper);
        QFETCH(bool, everywhere);
        turning::BalanceSettings set;
        set.waitsEverywhere = everywhere;
        const BalancedCut c = balanced(roughing(taper ? kTaper : kCylinder), set);
        const auto all = byNumber(c);
        int waits = 0, expectedCode = 101;
        for (std::size_t m = 0; 2 * m < all.size(); ++m) {
            const BalancedBlock* a = all[2 * m];
            const BalancedBlock* b = 2 * m + 1 < all.size() ? all[2 * m + 1] : nullptr;
            bool differs = false;
            if (m > 0) differs = std::abs(all[2 * m - 2]->cutLength - all[2 * m - 1]->cutLength) > 1e-3;
            const bool want = everywhere || differs;
            QCOMPARE(a->wait.has_value(), want);
            if (b) QCOMPARE(b->wait, a->wait);  // the same number on both paths
            else QCOMPARE(c.paths[1].tailWait, a->wait);  // path 2 meets path 1's last block before going home
            if (want) {
                QCOMPARE(*a->wait, expectedCode++);
                ++waits;
            }
        }
        if (taper) QCOMPARE(waits, static_cast<int>((all.size() + 1) / 2) - 1);  // every meeting after the first
        else if (!everywhere) QCOMPARE(waits, 0);
        else QCOMPARE(waits, static_cast<int>((all.size() + 1) / 2));
    }

    void followerDwellsAtLeastTheSetRevolutions_data()
    {
        QTest::addColumn<bool>("taper");
        QTest::addColumn<bool>("css");
        QTest::addColumn<double>("revolutions");
        QTest::newRow("cylinder, G96, one") << false << true << 1.0;
        QTest::newRow("taper, G96, half") << true << true << 0.5;
        QTest::newRow("taper, G97, two") << true << false << 2.0;
    }
    void followerDwellsAtLeastTheSetRevolutions()
    {
        QFETCH(bool, taper);
        QFETCH(bool, css);
        QFETCH(double, revolutions);
        TurnStep s = roughing(taper ? kTaper : kCylinder);
        if (!css) {
            s.cutting.constantSurfaceSpeed = false;
            s.cutting.rpm = 700;
        }
        QVERIFY(!css || s.cutting.surfaceSpeed > 0);
        turning::BalanceSettings set;
        set.dwellRevolutions = revolutions;
        const BalancedCut c = balanced(s, set);
        const auto all = byNumber(c);
        const double limit = std::min(s.cutting.maxRpm > 0 ? s.cutting.maxRpm : 1e9, twoPath().maxSpindleSpeed);
        std::set<double> dwells;
        for (std::size_t k = 0; k < all.size(); ++k) {
            if (k % 2 == 0) {
                QCOMPARE(all[k]->dwellSeconds, 0.0);  // the leader does not wait
                continue;
            }
            const double rpm = std::min(rpmAt(s.cutting, limit, all[k - 1]->level), rpmAt(s.cutting, limit, all[k]->level));
            const double revs = all[k]->dwellSeconds * rpm / 60.0;
            QVERIFY2(revs >= revolutions - 1e-9 && revs < revolutions + rpm / 60.0 * 0.001 + 1e-9,
                     qPrintable(QString("CB%1: %2 s is %3 revolutions at %4 rpm").arg(k + 1).arg(all[k]->dwellSeconds).arg(revs).arg(rpm)));
            dwells.insert(all[k]->dwellSeconds);
        }
        // Under constant surface speed a deeper cut turns faster: the dwell
        // shortens (below the spindle limit); under G97 it stays.
        if (!css) QCOMPARE(dwells.size(), std::size_t{1});
        else QVERIFY(dwells.size() > 1 || limit <= rpmAt(s.cutting, 1e9, all[1]->level));
    }

    void bothPathsCutWhatOnePathCuts_data()
    {
        QTest::addColumn<bool>("taper");
        QTest::newRow("cylinder") << false;
        QTest::newRow("taper") << true;
    }
    void bothPathsCutWhatOnePathCuts()
    {
        QFETCH(bool, taper);
        const TurnStep& s = roughing(taper ? kTaper : kCylinder);
        const BalancedCut c = balanced(s);
        const MultiPath& mp = *twoPath().layout.multiPath;
        std::vector<Feed> both;
        for (std::size_t p = 0; p < c.paths.size(); ++p) {
            ZR at = mp.toPath1(c.paths[p].start, p);
            for (const auto& b : c.paths[p].blocks)
                for (const auto& m : b.moves) {
                    const ZR end = mp.toPath1(m.end, p);
                    if (m.kind != TurnMove::Rapid) both.emplace_back(at, end);
                    at = end;
                }
        }
        const std::vector<Feed> one = feedsOf(s.path);
        QVERIFY(one.size() >= 10);
        auto key = [](const Feed& f) { return std::make_tuple(f.first.z, f.first.r, f.second.z, f.second.r); };
        auto sorted = [&](std::vector<Feed> v) {
            std::sort(v.begin(), v.end(), [&](const Feed& a, const Feed& b) { return key(a) < key(b); });
            return v;
        };
        const auto a = sorted(both), b = sorted(one);
        QCOMPARE(a.size(), b.size());  // no pass lost or doubled
        for (std::size_t i = 0; i < a.size(); ++i) QVERIFY(near(a[i].first, b[i].first) && near(a[i].second, b[i].second));
        // Negative control: one pass dropped is seen.
        auto fewer = both;
        fewer.pop_back();
        QVERIFY(sorted(fewer).size() != b.size());
    }

    void refusals()
    {
        const TurnStep& s = roughing(kTaper);
        auto r = turning::balanceRoughing(s.path, s.cutting, *findMachine("lathe"));
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()), QString("machine: lathe has one path; a balanced cut needs a two-path lathe"));
        turning::BalanceSettings half;
        half.dwellRevolutions = 0.4;
        r = turning::balanceRoughing(s.path, s.cutting, twoPath(), half);
        QVERIFY(!r);
        QVERIFY2(r.error().rfind("dwellRevolutions: 0.4 is below half a spindle revolution", 0) == 0, r.error().c_str());
        turning::BalanceSettings low;
        low.firstWait = 99;
        r = turning::balanceRoughing(s.path, s.cutting, twoPath(), low);
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()), QString("waitCodes: M99 is outside the machine's wait codes M101 to M199"));
        // One code fewer than the taper needs.
        int waits = 0;
        for (const auto& b : balanced(s).paths[0].blocks) waits += b.wait ? 1 : 0;
        QVERIFY(waits >= 2);
        Machine narrow = twoPath();
        narrow.layout.multiPath->waitCodes = {101, 99 + waits};
        r = turning::balanceRoughing(s.path, s.cutting, narrow);
        QVERIFY(!r);
        QCOMPARE(QString::fromStdString(r.error()),
                 QString("waitCodes: the balanced cut needs wait code M%1, beyond the machine's last M%2").arg(100 + waits).arg(99 + waits));
        // Within the range it is taken (the control: the same job, more codes).
        narrow.layout.multiPath->waitCodes = {101, 110};
        QVERIFY(turning::balanceRoughing(s.path, s.cutting, narrow));
    }

    void timelineProvesTheBalancedCut_data()
    {
        QTest::addColumn<bool>("taper");
        QTest::addColumn<double>("revolutions");
        QTest::newRow("cylinder") << false << 1.0;
        QTest::newRow("taper") << true << 1.0;
        QTest::newRow("taper, two revolutions") << true << 2.0;
    }
    void timelineProvesTheBalancedCut()
    {
        QFETCH(bool, taper);
        QFETCH(double, revolutions);
        const TurnStep& s = roughing(taper ? kTaper : kCylinder);
        turning::BalanceSettings set;
        set.dwellRevolutions = revolutions;
        const BalancedCut c = balanced(s, set);
        const Timeline t = runTimeline(c, twoPath());
        QVERIFY(t.deadlocks.empty());
        QCOMPARE(t.blocks.size(), static_cast<std::size_t>(c.blockCount));
        QCOMPARE(t.lags.size(), static_cast<std::size_t>(c.blockCount - 1));
        QVERIFY2(t.leastLag() >= revolutions - 1e-6, qPrintable(QString::number(t.leastLag())));
        for (const auto& b : t.blocks) QVERIFY(b.start <= b.cutStart && b.cutStart < b.cutEnd && b.cutEnd <= b.end);
        const double one = singlePathSeconds(s.path, s.cutting, twoPath());
        const double ratio = t.seconds() / one;
        qInfo("%s: one path %.2f s, two paths %.2f s, ratio %.3f, least lag %.2f revolutions", taper ? "taper" : "cylinder", one,
              t.seconds(), ratio, t.leastLag());
        QVERIFY(ratio < 1.0);
        if (!taper) QVERIFY(ratio < 0.6);  // a cylinder comes close to half
        // Meeting before the first cut and after the last, as the job's programs do.
        set.meetAtEnds = true;
        const BalancedCut ends = balanced(s, set);
        QVERIFY(ends.paths[0].blocks.front().wait && ends.paths[0].endWait && ends.paths[0].endWait == ends.paths[1].endWait);
        const Timeline te = runTimeline(ends, twoPath());
        QVERIFY(te.deadlocks.empty());
        QVERIFY(te.leastLag() >= revolutions - 1e-6);
        QCOMPARE_LE(std::abs(te.pathEnd[0] - te.pathEnd[1]), 1e-9);  // they leave the roughing together
    }

    void timelineCatchesDeadlockAndCloseFollower()
    {
        const TurnStep& s = roughing(kTaper);
        BalancedCut c = balanced(s);
        // A wait path 2 never reaches: deadlock, named.
        BalancedCut broken = c;
        for (auto& b : broken.paths[1].blocks)
            if (b.wait) {
                b.wait = 150;
                break;
            }
        const Timeline t = runTimeline(broken, twoPath());
        QVERIFY(!t.deadlocks.empty());
        QCOMPARE(t.deadlocks[0].path, std::size_t{0});
        QVERIFY2(t.deadlocks[0].why.find("path 2") == 0, t.deadlocks[0].why.c_str());
        // No dwell: the follower starts with the leader, 0 revolutions behind.
        BalancedCut close = c;
        for (auto& b : close.paths[1].blocks) b.dwellSeconds = 0;
        QVERIFY(runTimeline(close, twoPath()).leastLag() < 0.5);
        // What taiwa verify reports of them (verify/two_path_check.h): each a finding; the cut as balanced, none.
        const auto deadlocked = verify::checkTimeline(t, 1.0);
        QVERIFY(!deadlocked.findings.empty());
        QVERIFY2(deadlocked.findings[0].find("deadlock on path 1") != std::string::npos, deadlocked.findings[0].c_str());
        const auto tooClose = verify::checkTimeline(runTimeline(close, twoPath()), 1.0);
        QVERIFY(!tooClose.findings.empty());
        QVERIFY2(tooClose.findings[0].find("fewer than the set 1") != std::string::npos, tooClose.findings[0].c_str());
        QVERIFY(verify::checkTimeline(runTimeline(c, twoPath()), 1.0).findings.empty());
    }
    void gangToolChangeNeverSweepsThroughThePart()
    {
        const GangSlide& g = *findMachine("lathe-gang")->layout.gang;
        const PartEnvelope part{1.0, -75.0, 20.0};
        auto tip = [](ZR s, const GangPlace& p) { return ZR{s.z + p.offset.z, s.r + p.offset.r}; };
        auto insideOthers = [&](ZR s, int chosen) {
            for (const auto& p : g.places) {
                const ZR t = tip(s, p);
                if (p.tool != chosen && t.z < part.zFront + g.clearance && t.z > part.zBack - g.clearance &&
                    std::abs(t.r) < part.radius + g.clearance)
                    return true;
            }
            return false;
        };
        int pairs = 0;
        for (const auto& a : g.places)
            for (const auto& b : g.places) {
                if (a.tool == b.tool) continue;
                const ZR at{part.zFront - 30.0, part.radius - 3.0};  // the last tool still in the cut
                const ZR start{part.zFront + 1.0, part.radius + 1.0};
                const auto c = gangToolChange(g, a.tool, at, b.tool, start, part);
                QVERIFY2(c, c ? "" : c.error().c_str());
                QCOMPARE(c->slide.size(), std::size_t{4});
                QVERIFY(near(tip(c->slide.front(), a), at));
                QVERIFY(near(tip(c->slide.back(), b), start));  // the chosen tool at its start
                for (std::size_t i = 1; i < c->slide.size(); ++i) {
                    const ZR s = c->slide[i - 1], e = c->slide[i];
                    const bool movesX = std::abs(e.r - s.r) > 1e-9;
                    // Z clear, then X, then the approach along Z: one axis at a time.
                    QVERIFY(!(movesX && std::abs(e.z - s.z) > 1e-9));
                    for (int k = 0; k <= 200; ++k) {
                        const double f = k / 200.0;
                        const ZR p{s.z + f * (e.z - s.z), s.r + f * (e.r - s.r)};
                        if (movesX) QVERIFY2(!anyToolInside(g, p, part), qPrintable(QString("T%1 to T%2").arg(a.tool).arg(b.tool)));
                        else if (i == 3) QVERIFY(!insideOthers(p, b.tool));  // the approach: only the chosen tool comes near
                    }
                }
                ++pairs;
            }
        QCOMPARE(pairs, static_cast<int>(g.places.size() * (g.places.size() - 1)));
        // Negative control: X first from where the last tool cut is caught.
        const auto c = *gangToolChange(g, 101, {-29.0, 17.0}, 102, {2.0, 21.0}, part);
        QVERIFY(anyToolInside(g, {c.slide[0].z, c.slide[2].r}, part) || anyToolInside(g, c.slide[0], part));
        // A tool with no mounting offset is refused.
        const auto none = gangToolChange(g, 101, {-29.0, 17.0}, 104, {2.0, 21.0}, part);
        QVERIFY(!none);
        QCOMPARE(QString::fromStdString(none.error()), QString("tools.T104: tool 104 has no mounting offset on the gang slide (gangSlide.tools)"));
    }
    // FANUC's pair: golden files, read by hand (tests/golden/two-path/).
    void fanucProgramsMatchTheGoldens_data()
    {
        QTest::addColumn<QString>("stem");
        QTest::newRow("cylinder") << QString::fromStdString(kCylinder);
        QTest::newRow("taper") << QString::fromStdString(kTaper);
    }
    void fanucProgramsMatchTheGoldens()
    {
        QFETCH(QString, stem);
        const std::string st = stem.toStdString();
        // The whole job: path 1 faces, roughs its blocks, finishes and
        // parts off; path 2 roughs its blocks; they meet before and after.
        const Plan& plan = planOf(st);
        std::size_t index = 0;
        while (plan.steps.at(index).kind != StepKind::TurnRoughing) ++index;
        QVERIFY(index > 0 && index + 1 < plan.steps.size());
        turning::BalanceSettings set;
        set.meetAtEnds = true;
        const BalancedCut c = balanced(*plan.steps[index].turn, set);
        const PostOptions o = postOptions(plan, "fanuc", std::nullopt, 1000, st);
        const auto programs = postBalancedCut(c, plan.steps, index, *twoPath().layout.multiPath, defaultToolLibrary(), o);
        QCOMPARE(programs.size(), std::size_t{2});
        bool rewrote = false;
        for (std::size_t p = 0; p < programs.size(); ++p) {
            const std::string& nc = programs[p].nc;
            // Each a whole program of its own: its O-number, its end.
            QVERIFY2(nc.find(fmt::format("\nO{:04d} (", 1000 + p)) != std::string::npos, nc.substr(0, 200).c_str());
            QVERIFY(nc.find("M30") != std::string::npos);
            int waits = 0, dwells = 0;
            for (const auto& b : c.paths[p].blocks) {
                waits += b.wait ? 1 : 0;
                dwells += b.dwellSeconds > 0 ? 1 : 0;
                if (b.wait) QVERIFY(nc.find(fmt::format("\nM{}\n", *b.wait)) != std::string::npos);
            }
            // The dwells in order, each the block's in seconds.
            std::vector<double> written;
            auto it = QRegularExpression(R"(^G04 X([0-9.]+)$)", QRegularExpression::MultilineOption).globalMatch(QString::fromStdString(nc));
            while (it.hasNext()) written.push_back(it.next().captured(1).toDouble());
            QCOMPARE(static_cast<int>(written.size()), dwells);
            std::size_t k = 0;
            for (const auto& b : c.paths[p].blocks)
                if (b.dwellSeconds > 0) QCOMPARE_LE(std::abs(written.at(k++) - b.dwellSeconds), 1e-9);
            if (c.paths[p].tailWait) ++waits;
            QVERIFY(c.paths[p].endWait);
            ++waits;
            // Path 1 holds every step of the job, path 2 the roughing alone.
            for (std::size_t i = 0; i < plan.steps.size(); ++i)
                QCOMPARE(nc.find(fmt::format("(STEP {}:", i + 1)) != std::string::npos, p == 0 || i == 0);
            QCOMPARE(static_cast<int>(QString::fromStdString(nc).count(QRegularExpression(R"(^M1\d\d$)", QRegularExpression::MultilineOption))), waits);
            const QString golden = test::sourcePath(QString("tests/golden/two-path/%1.p%2.fanuc.nc").arg(stem).arg(p + 1));
            if (test::rewroteGolden(golden, nc)) {
                rewrote = true;
                continue;
            }
            QVERIFY2(QFileInfo::exists(golden), qPrintable("no golden file " + golden + " (TAIWA_UPDATE_GOLDEN=1 writes it)"));
            if (nc != test::readFile(golden)) {
                test::writeFile(golden + ".actual", nc);
                QFAIL(qPrintable("differs from " + golden + "; see " + golden + ".actual"));
            }
        }
        if (rewrote) return;
    }
    // Every two-path sample (tests/data/two-path/*.taiwa): no deadlock, no
    // follower closer than one revolution, the pair faster than one path,
    // alone and meeting before and after (the job's programs).
    void everyTwoPathSampleIsProven()
    {
        const auto files = QDir(test::dataPath("two-path")).entryInfoList({"*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(files.size() >= 2);
        for (const QFileInfo& f : files) {
            const std::string stem = f.completeBaseName().toStdString();
            const TurnStep& s = roughing(stem);
            for (const bool ends : {false, true}) {
                turning::BalanceSettings set;
                set.meetAtEnds = ends;
                const Timeline t = runTimeline(balanced(s, set), twoPath());
                QVERIFY2(t.deadlocks.empty(), stem.c_str());
                QVERIFY2(t.leastLag() >= 1.0 - 1e-6, stem.c_str());
                const double ratio = t.seconds() / singlePathSeconds(s.path, s.cutting, twoPath());
                qInfo("%s%s: ratio %.3f, least lag %.2f revolutions", stem.c_str(), ends ? " (meeting at the ends)" : "", ratio,
                      t.leastLag());
                QVERIFY2(ratio < 1.0, stem.c_str());
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestTwoPath)
#include "test_two_path.moc"
