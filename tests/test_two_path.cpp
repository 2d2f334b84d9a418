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
// the clearance, for every pair of the slide's tools, and on the posted
// tape of a gang-tool job (post/gang_post.h) too. The job's two-path
// settings (Job::twoPath): read, written and refused by the job check
// naming the field, and taken by the export and verify. The sheet's part
// (export/two_path_sheet.h): each step's path, the timeline as a
// Gantt-style table with the waits side by side.
#include "export/two_path_export.h"
#include "export/two_path_sheet.h"
#include "job/job_file.h"
#include "machine/gang_change.h"
#include "machine/machine.h"
#include "turning/balanced_roughing.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/gang_post.h"
#include "post/lathe_post.h"
#include "post/two_path_post.h"
#include "sheet/sheet.h"
#include "support/hand_plan.h"
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
#include <optional>
#include <set>

using namespace taiwa;
using turning::ZR;

namespace {

// The roughing step of a two-path sample (resources/samples/STEM.taiwa).
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
        auto r = readJobFile(test::sourcePath(QString::fromStdString("resources/samples/" + stem + ".taiwa")).toStdString());
        if (!r.job) qFatal("cannot read %s", stem.c_str());
        it = plans.emplace(stem, planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary())).first;
    }
    for (const auto& s : it->second.steps)
        if (s.kind == StepKind::TurnRoughing) return s;
    std::string why;
    for (const auto& d : it->second.diagnostics) why += d.field + ": " + d.message + "; ";
    qFatal("no roughing step in %s: %s", stem.c_str(), why.c_str());
}
const TurnStep& roughing(const std::string& stem) { return *turnOf(roughingStep(stem)); }
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

// What the slide does during a tape's tool changes, by the test's own
// reading of the tape: the physical slide (reference point) through every
// motion the post wrote outside the steps' paths (BlockSource move -1: the
// changes, the approach to a step's start, the end), and each X motion
// sampled against the envelope grown by the clearance. `offsetAtT`: the
// control applies a new tool's offset at the T word itself (the slide
// moves by the offsets' difference there), else with the next motion.
struct SlideRun {
    int changes = 0;
    int xMoves = 0;          // X motions checked
    QStringList sweeps;      // "line 31: T101 inside at Z.. X.."
};
SlideRun runSlide(const PostedProgram& p, const GangSlide& g, const PartEnvelope& part, bool offsetAtT)
{
    SlideRun run;
    const QStringList lines = QString::fromStdString(p.nc).split('\n');
    std::map<int, int> toolAt;
    for (const QString& l : lines) {
        const auto m = QRegularExpression(R"(T(\d+) = LIBRARY T(\d+))", QRegularExpression::CaseInsensitiveOption).match(l);
        if (m.hasMatch()) toolAt[m.captured(1).toInt()] = m.captured(2).toInt();
    }
    ZR offset{0.0, 0.0};
    std::optional<ZR> tip, slidePos;
    const auto known = [](const std::optional<ZR>& at) { return at && !std::isnan(at->z) && !std::isnan(at->r); };
    const auto segment = [&](int line, ZR from, ZR to) {
        if (std::isnan(from.z + from.r + to.z + to.r) || std::abs(to.r - from.r) < 1e-9) return;
        ++run.xMoves;
        for (int k = 0; k <= 400; ++k) {
            const double f = k / 400.0;
            const ZR at{from.z + f * (to.z - from.z), from.r + f * (to.r - from.r)};
            if (anyToolInside(g, at, part)) {
                run.sweeps << QString("line %1: slide at Z%2 X%3").arg(line + 1).arg(at.z).arg(2 * at.r);
                return;
            }
        }
    };
    const QRegularExpression words(R"((?:^|\s)([XZ])(-?[0-9]*\.?[0-9]+))");
    // A G71's contour blocks (P to Q) say the profile, they move nothing themselves.
    int contourFrom = -1, contourTo = -1;
    for (int i = 0; i < lines.size(); ++i) {
        QString body = lines[i];
        const auto number = QRegularExpression(R"(^N(\d+) )").match(body);
        if (number.hasMatch() && number.captured(1).toInt() >= contourFrom && number.captured(1).toInt() <= contourTo) continue;
        if (const auto pq = QRegularExpression(R"(G71 P(\d+) Q(\d+))").match(body); pq.hasMatch()) {
            contourFrom = pq.captured(1).toInt();
            contourTo = pq.captured(2).toInt();
        }
        body.remove(QRegularExpression(R"(^N\d+ )"));
        body.remove(QRegularExpression(R"(\(.*\)|;.*$)"));
        const bool inChange = static_cast<std::size_t>(i) < p.lines.size() && p.lines[static_cast<std::size_t>(i)].move < 0;
        if (QRegularExpression(R"(^T(\d\d)\d\d$|^T(\d+)\b)").match(body).hasMatch()) {
            const auto m = QRegularExpression(R"(^T(\d\d)\d\d$|^T(\d+)\b)").match(body);
            const int station = (m.captured(1).isEmpty() ? m.captured(2) : m.captured(1)).toInt();
            const GangPlace* place = g.place(toolAt.at(station));
            if (!place) qFatal("no place for station %d", station);
            ++run.changes;
            if (offsetAtT && known(tip) && known(slidePos)) {
                const ZR to{tip->z - place->offset.z, tip->r - place->offset.r};
                segment(i, *slidePos, to);
                slidePos = to;
            }
            offset = place->offset;
            continue;
        }
        if (body.startsWith(' ') || body.startsWith('o') || body.contains(QRegularExpression(R"(G0?4\b|G7[0-6]|G50|CYCLE)"))) continue;
        ZR next = tip.value_or(ZR{std::nan(""), std::nan("")});
        bool moved = false;
        auto it = words.globalMatch(body);
        while (it.hasNext()) {
            const auto w = it.next();
            (w.captured(1) == "X" ? next.r : next.z) = w.captured(2).toDouble() / (w.captured(1) == "X" ? 2.0 : 1.0);
            moved = true;
        }
        if (!moved) continue;
        const ZR to{next.z - offset.z, next.r - offset.r};
        if (inChange && slidePos) segment(i, *slidePos, to);
        tip = next;
        slidePos = to;
    }
    return run;
}

// What breaks the block tape's rules in a tape of a dialect that numbers
// its blocks, by the test's own reading: every line but '%', the O-number
// line and a comment is a block with its N word, each the one before plus
// the increment; no line longer than the dialect's limit; every G71 P and
// Q names a block of the tape.
QStringList blockFaults(const std::string& nc, const post::Dialect& d)
{
    QStringList faults;
    const QStringList lines = QString::fromStdString(nc).split('\n', Qt::SkipEmptyParts);
    std::set<int> numbers;
    std::optional<int> last;
    for (int i = 0; i < lines.size(); ++i) {
        const QString& l = lines[i];
        if (static_cast<std::size_t>(l.size()) > d.maxLineLength)
            faults << QString("line %1: %2 characters, more than %3").arg(i + 1).arg(l.size()).arg(d.maxLineLength);
        if (l == "%" || l.startsWith('O') || l.startsWith('(')) continue;
        const auto m = QRegularExpression(R"(^N(\d+) \S)").match(l);
        if (!m.hasMatch()) {
            faults << QString("line %1: no N word: %2").arg(i + 1).arg(l);
            continue;
        }
        const int n = m.captured(1).toInt();
        if (last && n != *last + d.sequenceIncrement) faults << QString("line %1: N%2 after N%3").arg(i + 1).arg(n).arg(*last);
        last = n;
        numbers.insert(n);
    }
    auto it = QRegularExpression(R"(G71 P(\d+) Q(\d+))").globalMatch(QString::fromStdString(nc));
    while (it.hasNext()) {
        const auto m = it.next();
        for (int k : {1, 2})
            if (!numbers.count(m.captured(k).toInt())) faults << QString("G71 names N%1, not on the tape").arg(m.captured(k));
    }
    return faults;
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

    // The job's settings (docs/job-format.md "twoPath"): in the job file
    // only when not the defaults (version 6), read back the same; refused
    // by the job check at their field; taken by the export's programs and
    // by verify's timeline.
    void jobSettingsReadCheckedAndUsed()
    {
        const std::string text = test::readFile(test::sourcePath(QString::fromStdString("resources/samples/" + kCylinder + ".taiwa")));
        const Job sample = *readJob(text).job;
        QCOMPARE(sample.twoPath, TwoPathSettings{});
        QCOMPARE(writeJob(sample), text);  // the defaults: no "twoPath", the version the sample has
        Job job = sample;
        job.twoPath = {2.0, true, 120};
        const std::string written = writeJob(job);
        QVERIFY2(written.find("\"version\": 6,") != std::string::npos, written.c_str());
        QVERIFY2(written.find("\"twoPath\": {\n    \"dwellRevolutions\": 2,\n    \"waitsEverywhere\": true,\n    \"firstWait\": 120\n  },")
                     != std::string::npos,
                 written.c_str());
        const auto back = readJob(written);
        QVERIFY(back.job);
        QCOMPARE(back.job->twoPath, job.twoPath);
        // Read errors name the key.
        const auto fieldsOf = [](const Diagnostics& ds) {
            QStringList out;
            for (const auto& d : ds) out << QString::fromStdString(d.field + ": " + d.message);
            return out.join("\n");
        };
        std::string bad = written;
        bad.replace(bad.find("\"waitsEverywhere\": true"), 23, "\"waitsEverywhere\": 1");
        auto refused = readJob(bad);
        QVERIFY(!refused.job);
        QVERIFY2(fieldsOf(refused.diagnostics).startsWith("twoPath.waitsEverywhere: "), qPrintable(fieldsOf(refused.diagnostics)));

        // The job check, one field at a time.
        const auto check = [&](const Job& j) { return fieldsOf(planJob(j, TechnologyTable::builtIn(), defaultToolLibrary()).diagnostics); };
        QCOMPARE(check(job), QString());
        Job slow = sample;
        slow.twoPath.dwellRevolutions = 0.4;
        QCOMPARE(check(slow), QString("twoPath.dwellRevolutions: the follower's dwell is 0.4 spindle revolutions; it must be at "
                                      "least 0.5, or the follower cuts where the leader has not"));
        slow.twoPath.dwellRevolutions = 0.5;  // half a revolution is taken
        QCOMPARE(check(slow), QString());
        Job onePath = job;
        onePath.machine = "lathe";
        QCOMPARE(check(onePath), QString("twoPath: machine lathe has one path; the two-path settings are for a two-path lathe "
                                         "(lathe-two-path)"));
        onePath.twoPath = {};  // the defaults: an ordinary lathe job
        QCOMPARE(check(onePath), QString());
        Job siemens = sample;  // a dialect without the waits
        siemens.dialect = "sinumerik";
        QCOMPARE(check(siemens), QString("dialect: the sinumerik dialect writes no two-path programs; machine lathe-two-path needs one "
                                         "of the ISO dialects"));
        siemens.dialect = "haas";
        QCOMPARE(check(siemens), QString());
        for (const int code : {99, 200}) {
            Job outside = sample;
            outside.twoPath.firstWait = code;
            QCOMPARE(check(outside), QString("twoPath.firstWait: M%1 is not a wait code of machine lathe-two-path: it waits "
                                             "with M101 to M199").arg(code));
        }

        // The export and verify take them: waits at every meeting, two
        // revolutions behind, the codes from M120 (the defaults: fewer
        // waits, one revolution, from M101).
        const auto fanucPair = [](const Job& j) {
            const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
            auto files = twoPathTapes(plan, "fanuc", std::nullopt, 1000, "t");
            if (!files || !*files) qFatal("no two-path tapes");
            return std::make_pair(plan, **files);
        };
        const auto waitsOf = [](const std::string& nc) {
            QStringList codes;
            auto it = QRegularExpression(R"(^M(1\d\d)$)", QRegularExpression::MultilineOption).globalMatch(QString::fromStdString(nc));
            while (it.hasNext()) codes << it.next().captured(1);
            return codes;
        };
        const auto [plainPlan, plain] = fanucPair(sample);
        const auto [setPlan, set] = fanucPair(job);
        QCOMPARE(set.at(0).first, std::string(".p1.nc"));
        const BalancedCut everywhere = balanced(roughing(kCylinder), turning::balanceSettings(job.twoPath, true));
        const QStringList p1 = waitsOf(set.at(0).second), p2 = waitsOf(set.at(1).second);
        QCOMPARE(p1, p2);  // the same codes on both paths
        QCOMPARE(p1.front(), QString("120"));
        // Every meeting waits: one per meeting (blocks in pairs, rounded up), before the first and after the last.
        QCOMPARE(static_cast<int>(p1.size()), (everywhere.blockCount + 1) / 2 + 1);
        QVERIFY(waitsOf(plain.at(0).second).size() < p1.size());
        QCOMPARE(waitsOf(plain.at(0).second).front(), QString("101"));
        const auto check2 = verify::checkTwoPath(setPlan);
        const auto check1 = verify::checkTwoPath(plainPlan);
        QVERIFY(check2 && check1 && check2->findings.empty() && check1->findings.empty());
        qInfo("least lag: %.2f revolutions set to 2, %.2f by default", check2->leastLag, check1->leastLag);
        QVERIFY(check2->leastLag >= 2.0 - 1e-6);
        QVERIFY(check1->leastLag < 2.0);
        // Wait codes the range cannot hold from the first set: the export refuses, writing nothing.
        Job last = sample;
        last.twoPath.firstWait = 199;
        auto none = twoPathTapes(planJob(last, TechnologyTable::builtIn(), defaultToolLibrary()), "fanuc", std::nullopt, 1000, "t");
        QVERIFY(none && !*none);
        QVERIFY2(none->error().rfind("waitCodes: the balanced cut needs wait code M200, beyond the machine's last M199", 0) == 0,
                 none->error().c_str());
    }

    // The sheet covers both paths: each step's path, and the roughing's
    // blocks in time, one column per path, every cut and every wait in its
    // path's column, the paths leaving each wait together.
    void sheetCoversBothPaths()
    {
        QVERIFY(twoPathSheet(test::samplePlan("lathe-bushing.taiwa")).empty());  // one path: nothing
        const Plan& plan = planOf(kTaper);
        const auto sections = twoPathSheet(plan);
        QCOMPARE(sections.size(), std::size_t{2});
        const sheet::Table& paths = sections[0].table;
        QCOMPARE(paths.rows.size(), plan.steps.size());
        std::size_t rough = 0;
        while (plan.steps[rough].kind != StepKind::TurnRoughing) ++rough;
        const BalancedCut c = balanced(roughing(kTaper), turning::balanceSettings(plan.mmJob.twoPath, true));
        for (std::size_t k = 0; k < plan.steps.size(); ++k) {
            const std::string& where = paths.rows[k][2];
            if (k != rough) {
                QCOMPARE(QString::fromStdString(where), QString("1 (upper turret)"));
                continue;
            }
            // Each path's blocks, by number, in its part of the cell.
            const auto second = where.find("; 2 (");
            QVERIFY2(where.rfind("1 (", 0) == 0 && second != std::string::npos, where.c_str());
            for (std::size_t p = 0; p < 2; ++p)
                for (const auto& b : c.paths[p].blocks) {
                    const auto m = QRegularExpression(QString("\\bCB%1\\b").arg(b.number)).match(QString::fromStdString(where));
                    QVERIFY2(m.hasMatch() && (p == 0) == (static_cast<std::size_t>(m.capturedStart()) < second), where.c_str());
                }
        }
        const sheet::Table& gantt = sections[1].table;
        const Timeline t = runTimeline(c, twoPath());
        QCOMPARE(gantt.headers.size(), std::size_t{4});
        QVERIFY2(gantt.headers[2] == "Path 1 upper turret" && gantt.headers[3].rfind("Path 2 ", 0) == 0, gantt.headers[3].c_str());
        // Rows run on without a gap, from 0 to the end of the roughing.
        QCOMPARE(QString::fromStdString(gantt.rows.front()[0]), QString("0.00"));
        QCOMPARE(QString::fromStdString(gantt.rows.back()[1]), QString::number(t.seconds(), 'f', 2));
        for (std::size_t r = 1; r < gantt.rows.size(); ++r)
            QCOMPARE(QString::fromStdString(gantt.rows[r][0]), QString::fromStdString(gantt.rows[r - 1][1]));
        const auto rowsWith = [&](std::size_t p, const std::string& text) {
            std::vector<std::size_t> rows;
            for (std::size_t r = 0; r < gantt.rows.size(); ++r)
                if (gantt.rows[r][2 + p] == text || gantt.rows[r][2 + p].rfind(text + ",", 0) == 0) rows.push_back(r);
            return rows;
        };
        int waits = 0;
        for (std::size_t p = 0; p < 2; ++p)
            for (const auto& b : c.paths[p].blocks) {
                QVERIFY2(rowsWith(p, fmt::format("CB{} cut", b.number)).size() >= 1, qPrintable(QString::number(b.number)));
                QVERIFY(rowsWith(1 - p, fmt::format("CB{} cut", b.number)).empty());
                // A wait both paths meet at in a block (the last meeting's partner without a block waits in its tail).
                const auto& other = c.paths[1 - p].blocks;
                if (!b.wait || std::none_of(other.begin(), other.end(), [&](const BalancedBlock& o) { return o.wait == b.wait; })) continue;
                ++waits;
                // The wait in both paths' columns; both leave it at the same row's end.
                std::vector<std::size_t> here = rowsWith(p, fmt::format("M{} wait", *b.wait)), there = rowsWith(1 - p, fmt::format("M{} wait", *b.wait));
                const auto met = [&](std::size_t q) { return rowsWith(q, fmt::format("M{} met", *b.wait)); };
                for (const auto r : met(p)) here.push_back(r);
                for (const auto r : met(1 - p)) there.push_back(r);
                QVERIFY2(!here.empty() && !there.empty(), qPrintable(QString("M%1").arg(*b.wait)));
                QCOMPARE(gantt.rows[*std::max_element(here.begin(), here.end())][1],
                         gantt.rows[*std::max_element(there.begin(), there.end())][1]);
            }
        QVERIFY(waits >= 4);  // the taper's, counted on both paths
        // The dwells stand in the follower's column.
        for (const auto& b : c.paths[1].blocks)
            if (b.dwellSeconds > 0) {
                QString all;
                for (const auto& r : gantt.rows) all += QString::fromStdString(r[0] + " " + r[1] + " | " + r[2] + " | " + r[3] + "\n");
                QVERIFY2(!rowsWith(1, fmt::format("CB{} in, dwell {:.3f} s", b.number, b.dwellSeconds)).empty(), qPrintable(all));
            }
        QVERIFY2(sections[1].note.find("deadlocks: none.") != std::string::npos, sections[1].note.c_str());
        // Laid out in the sheet, after the steps.
        SheetOptions o;
        o.paths = sections;
        const std::string html = sheetHtml(plan, o);
        const auto steps = html.find("<h2>Process steps</h2>"), pathsAt = html.find("<h2>Paths</h2>"),
                   timeline = html.find("<h2>Balanced roughing on the timeline</h2>");
        QVERIFY(steps != std::string::npos && pathsAt != std::string::npos && timeline != std::string::npos);
        QVERIFY(steps < pathsAt && pathsAt < timeline);
        QVERIFY(sheetHtml(plan, {}).find("<h2>Paths</h2>") == std::string::npos);
    }

    // planJob balances the roughing once (Plan::balance): the post, the
    // sheet and the station (balancedRoughing) and the verification read
    // that balance and balance nothing of their own. A plan whose balance
    // is replaced by a refusal, or taken away, shows it in each of them.
    void theBalanceIsMadeOnceWithThePlan()
    {
        QVERIFY(!test::samplePlan("lathe-bushing.taiwa").balance);  // one path: none
        Plan plan = planOf(kTaper);
        QVERIFY(plan.balance && plan.balance->cut);
        QCOMPARE(plan.steps[plan.balance->step].kind, StepKind::TurnRoughing);
        // The job's dwell is the balance's: the follower's blocks keep it.
        Job slow = plan.job;
        slow.twoPath.dwellRevolutions = 2.5;
        const Plan slowPlan = planJob(slow, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(slowPlan.balance && slowPlan.balance->cut);
        int dwells = 0;
        for (const BalancedPath& p : slowPlan.balance->cut->paths)
            for (const BalancedBlock& b : p.blocks)
                if (b.dwellSeconds > 0) {
                    QVERIFY2(b.dwellRevolutions >= 2.5 - 1e-9, qPrintable(QString::number(b.dwellRevolutions)));
                    ++dwells;
                }
        QVERIFY(dwells > 0);
        const auto again = turning::balancePlanRoughing(plan, twoPath());
        QVERIFY(again && again->cut && again->step == plan.balance->step);
        QVERIFY(*again->cut == *plan.balance->cut);
        const PostOptions o = postOptions(plan, "fanuc", std::nullopt, 1000, "t");
        const auto posted = postTwoPath(plan, o);
        QVERIFY(posted && *posted && (**posted).cut == *plan.balance->cut && (**posted).roughing == plan.balance->step);

        const std::string why = "waitCodes: a refusal the test put in the plan";
        plan.balance->cut = Failure{why};
        const auto refused = postTwoPath(plan, o);
        QVERIFY(refused && !*refused);
        QCOMPARE(refused->error(), why);
        const auto check = verify::checkTwoPath(plan);
        QVERIFY(check);
        QCOMPARE(check->findings, std::vector<std::string>{"balanced cut: " + why});
        const auto sheet = balancedRoughing(plan);
        QVERIFY(sheet && sheet->cut && !*sheet->cut);
        QCOMPARE(sheet->cut->error(), why);

        plan.balance.reset();
        const auto none = postTwoPath(plan, o);
        QVERIFY(none && !*none);
        QVERIFY2(none->error().find("has no roughing step to balance") != std::string::npos, none->error().c_str());
        const auto unchecked = verify::checkTwoPath(plan);
        QVERIFY(unchecked && unchecked->findings.size() == 1);
        QVERIFY2(unchecked->findings[0].find("no roughing step to balance") != std::string::npos, unchecked->findings[0].c_str());
        const auto unbalanced = balancedRoughing(plan);
        QVERIFY(unbalanced && !unbalanced->cut);
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
    // FANUC's pair: golden files, read by hand (tests/golden/STEM.pN.fanuc.nc, the export's too: test_golden).
    // The gang change on the tape (post/gang_post.h): a gang-tool job's
    // tape, and for every ordered pair of the slide's tools a job of two
    // steps with those tools, in FANUC's and LinuxCNC's words, run by the
    // test's own reading (runSlide): no X motion of a change while any tool
    // on the slide is inside the bar grown by the clearance, whether the
    // control applies a new offset at the T word or with the next motion;
    // each change's Z clear, X and approach in that order; in FANUC's
    // words every block of the tape numbered and within the line limit
    // (the change is a link of the post's sink chain). The lathe post's
    // own tape (X and Z at once to the change point) is caught on a slide
    // with a wider clearance; a tool not on the slide is refused.
    void gangToolTapeNeverSweepsThroughThePart()
    {
        const auto read = readJobFile(test::dataPath("gang/lathe-gang-shaft.taiwa").toStdString());
        QVERIFY(read.job);
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QString why;
        for (const auto& d : plan.diagnostics) why += QString::fromStdString(d.field + ": " + d.message + "\n");
        QVERIFY2(plan.ok() && plan.steps.size() >= 3, qPrintable(why));
        const BarStock& bar = *plan.mmJob.bar;
        const PartEnvelope part{bar.face, bar.face - bar.length, bar.diameter / 2.0};
        const GangSlide& shipped = *findMachine("lathe-gang")->layout.gang;
        const std::vector<Tool> library = defaultToolLibrary();  // every tool of the slide
        GangSlide wide = shipped;
        wide.clearance = 5.0;
        for (const char* dialect : {"fanuc", "linuxcnc"}) {
            const PostOptions o = postOptions(plan, dialect, std::nullopt, 1000, "gang");
            // What postProcess writes for a job on the gang-tool lathe.
            const PostedProgram tape = postProcess(plan.steps, plan.tools, o);
            QCOMPARE(tape.nc, postGangTool(plan.steps, plan.tools, shipped, pathsEnvelope(plan.steps), o).nc);
            for (const bool atT : {false, true}) {
                const SlideRun r = runSlide(tape, shipped, part, atT);
                QVERIFY2(r.sweeps.isEmpty(), qPrintable(r.sweeps.join("\n") + "\n" + QString::fromStdString(tape.nc)));
                QCOMPARE(r.changes, 3);  // T101, T102, T106
                QVERIFY(r.xMoves >= 3);  // two changes between tools, the end
            }
            // Each change: Z clear, the T word, X, then the approach along Z.
            const QString nc = QString::fromStdString(tape.nc);
            const auto change = QRegularExpression(R"(\n(?:N\d+ )?G0 Z(-?[0-9.]+)\n(?:N\d+ )?T[0-9][^\n]*\n(?:[^\n]*\n)*?)"
                                                   R"((?:N\d+ )?G0 X(-?[0-9.]+) Z(-?[0-9.]+)\n)");
            QCOMPARE(static_cast<int>(nc.count(change)), 3);
            // The change's blocks are the block tape's like every other:
            // in FANUC's words each block numbered, one after the other by
            // the dialect's increment, within its line length, and a G71's
            // P and Q name blocks of the tape.
            if (std::string(dialect) == "fanuc") {
                const QStringList faults = blockFaults(tape.nc, post::dialectNamed(dialect));
                QVERIFY2(faults.isEmpty(), qPrintable(faults.join("\n") + "\n" + nc));
                // Negative control: a block written past the tape (as the
                // gang post once inserted its own), and one too long.
                std::string unnumbered = tape.nc, tooLong = tape.nc;
                unnumbered.insert(unnumbered.find("\nN") + 1, "G0 X20.\n");
                tooLong.insert(tooLong.find("\nN") + 1, "N5 G0 X" + std::string(140, '1') + ".\n");
                QVERIFY(blockFaults(unnumbered, post::dialectNamed(dialect)).join("\n").contains("no N word"));
                QVERIFY(blockFaults(tooLong, post::dialectNamed(dialect)).join("\n").contains("characters"));
            }
            // Every pair of the slide's tools, on a slide with the shipped clearance and a wider one.
            int pairs = 0;
            for (const GangSlide* slide : {&shipped, static_cast<const GangSlide*>(&wide)})
                for (const auto& a : slide->places)
                    for (const auto& b : slide->places) {
                        if (a.tool == b.tool) continue;
                        std::vector<Step> two{plan.steps[0], plan.steps[2]};
                        two[0].tool->toolId = a.tool;
                        two[1].tool->toolId = b.tool;
                        const PostedProgram p = postGangTool(two, library, *slide, pathsEnvelope(two), o);
                        for (const bool atT : {false, true}) {
                            const SlideRun r = runSlide(p, *slide, part, atT);
                            QVERIFY2(r.sweeps.isEmpty(), qPrintable(QString("T%1 to T%2: ").arg(a.tool).arg(b.tool) + r.sweeps.join("\n")));
                            QCOMPARE(r.changes, 2);
                        }
                        ++pairs;
                    }
            QCOMPARE(pairs, static_cast<int>(2 * shipped.places.size() * (shipped.places.size() - 1)));
            // Negative control: the lathe post's tape, X and Z at once to the change point.
            const SlideRun lathe = runSlide(postLathe(plan.steps, plan.tools, o), wide, part, false);
            QVERIFY2(!lathe.sweeps.isEmpty(), dialect);
            qInfo("%s: the lathe post's own tape sweeps: %s", dialect, qPrintable(lathe.sweeps.front()));
            // A tool not on the slide.
            std::vector<Step> bore = plan.steps;
            bore[2].tool->toolId = 104;
            try {
                postGangTool(bore, library, shipped, pathsEnvelope(bore), o);
                QFAIL("tool 104 posted");
            } catch (const Refusal& e) {
                QCOMPARE(QString(e.what()), QString("tools.T104: tool 104 has no mounting offset on the gang slide (gangSlide.tools)"));
            }
        }
    }

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
        const BalancedCut c = balanced(*turnOf(plan.steps[index]), set);
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
            const QString golden = test::sourcePath(QString("tests/golden/%1.p%2.fanuc.nc").arg(stem).arg(p + 1));
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
    // Every two-path sample (resources/samples/lathe-two-path-*.taiwa): no deadlock, no
    // follower closer than one revolution, the pair faster than one path,
    // alone and meeting before and after (the job's programs).
    void everyTwoPathSampleIsProven()
    {
        const auto files = QDir(test::sourcePath("resources/samples")).entryInfoList({"lathe-two-path-*.taiwa"}, QDir::Files, QDir::Name);
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
