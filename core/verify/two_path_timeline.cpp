// The two-path timeline (two_path_timeline.h).
#include "verify/two_path_timeline.h"

#include "turning/balanced_roughing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

namespace taiwa {

namespace {

using turning::ZR;

// One thing a path does, in path 1's coordinates.
struct Op {
    enum Kind { Move, Wait, Dwell, BlockStart, CutStart, CutEnd, BlockEnd } kind = Move;
    TurnMove move;  // end, centre in path 1's coordinates
    ZR from{};
    int code = 0;
    double seconds = 0.0;
    int block = 0;
    int index = -1;  // Move: its index among its block's moves (block 0: the tail's)
};

double arcLength(ZR a, const TurnMove& m)
{
    const double r = std::hypot(a.z - m.centre.z, a.r - m.centre.r);
    double sweep = std::atan2(m.end.r - m.centre.r, m.end.z - m.centre.z) - std::atan2(a.r - m.centre.r, a.z - m.centre.z);
    if (m.kind == TurnMove::ArcCW) sweep = -sweep;
    while (sweep <= 0) sweep += 2 * std::numbers::pi;
    return r * sweep;
}

struct Clock {
    const TurnCutting& cutting;
    const Machine& machine;
    double limit;
    double seconds(ZR a, const TurnMove& m) const
    {
        if (m.kind == TurnMove::Rapid) {
            const double rz = machine.rapid.count("z") ? machine.rapid.at("z") : machine.slowestRapid();
            const double rx = machine.rapid.count("x") ? machine.rapid.at("x") : machine.slowestRapid();
            return 60.0 * std::max(std::abs(m.end.z - a.z) / rz, std::abs(m.end.r - a.r) / rx);
        }
        const double len = m.kind == TurnMove::Feed ? std::hypot(m.end.z - a.z, m.end.r - a.r) : arcLength(a, m);
        const double d = 2.0 * std::min(std::abs(a.r), std::abs(m.end.r));
        const double rpm = cutting.rpmAt(std::max(d, 1e-3), limit);
        const double f = m.feed == FeedKind::Plunge ? cutting.plungeFeedPerRev : cutting.feedPerRev;
        return 60.0 * len / std::max(f * rpm, 1e-9);
    }
};

TurnMove back(const TurnMove& m, const MultiPath& mp, std::size_t p)
{
    TurnMove c = m;
    c.end = mp.toPath1(m.end, p);
    c.centre = mp.toPath1(m.centre, p);
    if (turning::flipsArcs(mp, p) && m.kind != TurnMove::Rapid && m.kind != TurnMove::Feed)
        c.kind = m.kind == TurnMove::ArcCW ? TurnMove::ArcCCW : TurnMove::ArcCW;
    return c;
}

// Where a block's cut is: the index of its longest feed along Z.
std::size_t cutMoveOf(const BalancedBlock& b, ZR from)
{
    std::size_t best = b.cutFrom;
    double longest = -1.0;
    ZR p = from;
    for (std::size_t i = 0; i < b.moves.size(); ++i) {
        if (i >= b.cutFrom && b.moves[i].kind != TurnMove::Rapid && std::abs(b.moves[i].end.z - p.z) > longest) {
            longest = std::abs(b.moves[i].end.z - p.z);
            best = i;
        }
        p = b.moves[i].end;
    }
    return best;
}

struct CutTrace {
    double t0 = 0.0, t1 = 0.0, z0 = 0.0, z1 = 0.0, level = 0.0;
};

// Each path's program as operations, in path 1's coordinates; where each starts.
std::vector<std::vector<Op>> operationsOf(const BalancedCut& cut, const Machine& machine, std::vector<ZR>& startOf)
{
    const MultiPath* mp = machine.layout.multiPath ? &*machine.layout.multiPath : nullptr;
    const std::size_t n = cut.paths.size();
    auto toP1 = [&](const TurnMove& m, std::size_t p) { return mp ? back(m, *mp, p) : m; };
    auto pointToP1 = [&](ZR z, std::size_t p) { return mp ? mp->toPath1(z, p) : z; };
    // Each path's program as operations, in path 1's coordinates.
    std::vector<std::vector<Op>> ops(n);
    startOf.assign(n, ZR{});
    for (std::size_t p = 0; p < n; ++p) {
        const BalancedPath& bp = cut.paths[p];
        ZR at = startOf[p] = pointToP1(bp.start, p);
        auto move = [&](const TurnMove& m, int block, int index) {
            Op o;
            o.kind = Op::Move;
            o.move = toP1(m, p);
            o.from = at;
            o.block = block;
            o.index = index;
            at = o.move.end;
            ops[p].push_back(o);
        };
        auto mark = [&](Op::Kind k, int block, int code = 0, double s = 0.0) {
            Op o;
            o.kind = k;
            o.block = block;
            o.code = code;
            o.seconds = s;
            ops[p].push_back(o);
        };
        ZR pathAt = bp.start;
        for (const auto& b : bp.blocks) {
            const std::size_t cm = cutMoveOf(b, pathAt);
            mark(Op::BlockStart, b.number);
            for (std::size_t i = 0; i < b.moves.size(); ++i) {
                if (i == b.cutFrom) {
                    if (b.wait) mark(Op::Wait, b.number, *b.wait);
                    if (b.dwellSeconds > 0) mark(Op::Dwell, b.number, 0, b.dwellSeconds);
                }
                if (i == cm) mark(Op::CutStart, b.number);
                move(b.moves[i], b.number, static_cast<int>(i));
                if (i == cm) mark(Op::CutEnd, b.number);
                pathAt = b.moves[i].end;
            }
            mark(Op::BlockEnd, b.number);
        }
        if (bp.tailWait) mark(Op::Wait, 0, *bp.tailWait);
        for (std::size_t i = 0; i < bp.tail.size(); ++i) move(bp.tail[i], 0, static_cast<int>(i));
        if (bp.endWait) mark(Op::Wait, 0, *bp.endWait);
    }
    return ops;
}

// One spindle: its speed is what path 1 (the master, which commands
// G96) sets at its own X, and every path's feed per revolution runs at
// it. The clock steps to the next end of a move, dwell or wait, at most
// kStep seconds at a time while the speed may change.
constexpr double kStep = 0.002;

// The paths run together: where each is in its operations and how far into
// the current one (done: the fraction of the move or dwell; -1 standing at
// a wait, -2 ended), when it came to its wait or ended, the clock, the
// spindle's revolutions, and when each block and cut began and ended.
struct Run {
    const BalancedCut& cut;
    const Clock clk;
    std::vector<ZR> startOf;
    std::vector<std::vector<Op>> ops;
    std::size_t n;
    std::vector<std::size_t> pc;
    std::vector<double> done, arrived, ended;
    std::vector<ZR> pos;
    double t = 0.0, revs = 0.0;
    std::map<int, TimelineBlock> blocks;
    std::map<int, CutTrace> traces;
    std::map<int, std::pair<double, double>> revsAt;  // cut: revolutions at its start and end
    // Called after a step of the clock for each move a path ended in it
    // (path, its operation), every path's position up to date.
    std::function<void(std::size_t, const Op&)> moveEnded;

    Run(const BalancedCut& c, const Machine& m)
        : cut(c), clk{c.cutting, m, c.spindleLimit > 0 ? c.spindleLimit : m.maxSpindleSpeed},
          ops(operationsOf(c, m, startOf)), n(c.paths.size()), pc(n, 0), done(n, 0.0), arrived(n, 0.0),
          ended(n, 0.0), pos(startOf)
    {
    }

    static double lengthOf(const Op& o)
    {
        return o.move.kind == TurnMove::Feed || o.move.kind == TurnMove::Rapid
                   ? std::hypot(o.move.end.z - o.from.z, o.move.end.r - o.from.r)
                   : arcLength(o.from, o.move);
    }
    bool hasCode(std::size_t p, int code) const
    {
        for (std::size_t i = pc[p]; i < ops[p].size(); ++i)
            if (ops[p][i].kind == Op::Wait && ops[p][i].code == code) return true;
        return false;
    }
    bool atWait(std::size_t p) const { return pc[p] < ops[p].size() && ops[p][pc[p]].kind == Op::Wait; }

    // The markers at once; a path at a wait notes when it came.
    void markers()
    {
        for (std::size_t p = 0; p < n; ++p) {
            for (; pc[p] < ops[p].size(); ++pc[p]) {
                const Op& o = ops[p][pc[p]];
                if (o.kind == Op::Move || o.kind == Op::Dwell) break;
                if (o.kind == Op::Wait) {
                    if (done[p] == 0.0) arrived[p] = t;
                    done[p] = -1.0;  // standing at it
                    break;
                }
                TimelineBlock& b = blocks[o.block];
                switch (o.kind) {
                case Op::BlockStart:
                    b.number = o.block;
                    b.path = p;
                    b.start = b.waitFrom = b.waitTo = t;
                    break;
                case Op::CutStart: {
                    b.cutStart = t;
                    const Op& m = ops[p][pc[p] + 1];
                    traces[o.block] = {t, 0.0, m.from.z, m.move.end.z, m.move.end.r};
                    revsAt[o.block].first = revs;
                    break;
                }
                case Op::CutEnd:
                    b.cutEnd = traces[o.block].t1 = t;
                    revsAt[o.block].second = revs;
                    break;
                case Op::BlockEnd: b.end = t; break;
                default: break;
                }
            }
            if (pc[p] >= ops[p].size() && done[p] != -2.0) {
                ended[p] = t;
                done[p] = -2.0;
            }
        }
    }

    // Releases a code every path that has it stands at; whether one was.
    bool release()
    {
        bool released = false;
        for (std::size_t p = 0; p < n && !released; ++p) {
            if (!atWait(p)) continue;
            const int code = ops[p][pc[p]].code;
            std::vector<std::size_t> party;
            bool all = true;
            for (std::size_t q = 0; q < n; ++q) {
                if (!hasCode(q, code)) continue;
                party.push_back(q);
                if (!atWait(q) || ops[q][pc[q]].code != code) all = false;
            }
            if (!all || party.size() < 2) continue;
            for (std::size_t q : party) {
                const Op& w = ops[q][pc[q]];
                if (w.block) {
                    blocks[w.block].waitFrom = arrived[q];
                    blocks[w.block].waitTo = t;
                    blocks[w.block].wait = code;
                }
                done[q] = 0.0;
                ++pc[q];
            }
            released = true;
        }
        return released;
    }

    // Every path standing at a wait no other path will come to, and why.
    void deadlocks(Timeline& tl) const
    {
        for (std::size_t p = 0; p < n; ++p) {
            if (!atWait(p)) continue;
            const int code = ops[p][pc[p]].code;
            std::string why;
            for (std::size_t q = 0; q < n; ++q) {
                if (q == p) continue;
                if (pc[q] >= ops[q].size()) why = fmt::format("path {} ended without M{}", q + 1, code);
                else if (!hasCode(q, code)) why = fmt::format("path {} has no M{}", q + 1, code);
                else why = fmt::format("path {} waits at M{}", q + 1, ops[q][pc[q]].code);
            }
            tl.deadlocks.push_back({p, code, why});
        }
    }

    // The clock moved on by one step (at most `cap` seconds) for the running paths.
    void advance(const std::vector<std::size_t>& running, double cap)
    {
        // The spindle's speed now, and how long each running path's move
        // or dwell still takes at it.
        const double rpm = cut.cutting.rpmAt(std::max(2.0 * std::abs(pos[0].r), 1e-3), clk.limit);
        std::vector<double> left(n, 0.0);
        double dt = kStep;
        bool speedMayChange = false;
        for (std::size_t p : running) {
            const Op& o = ops[p][pc[p]];
            double whole;
            if (o.kind == Op::Dwell) whole = o.seconds;
            else if (o.move.kind == TurnMove::Rapid) whole = clk.seconds(o.from, o.move);
            else {
                const double f = o.move.feed == FeedKind::Plunge ? cut.cutting.plungeFeedPerRev : cut.cutting.feedPerRev;
                whole = 60.0 * lengthOf(o) / std::max(f * rpm, 1e-9);
            }
            left[p] = whole;
            const double remaining = (1.0 - done[p]) * whole;
            if (p == 0 && o.kind == Op::Move && std::abs(o.move.end.r - o.from.r) > 1e-9 && cut.cutting.constantSurfaceSpeed)
                speedMayChange = true;
            dt = std::min(dt, remaining);
        }
        if (!speedMayChange) {
            dt = 1e300;
            for (std::size_t p : running) dt = std::min(dt, (1.0 - done[p]) * left[p]);
        }
        dt = std::max(std::min(dt, cap), 0.0);
        std::vector<std::pair<std::size_t, const Op*>> endedMoves;
        for (std::size_t p : running) {
            const Op& o = ops[p][pc[p]];
            done[p] = left[p] > 0 ? std::min(1.0, done[p] + dt / left[p]) : 1.0;
            if (o.kind == Op::Move)
                pos[p] = {o.from.z + done[p] * (o.move.end.z - o.from.z), o.from.r + done[p] * (o.move.end.r - o.from.r)};
            if (done[p] >= 1.0 - 1e-12) {
                if (o.kind == Op::Move) {
                    pos[p] = o.move.end;
                    endedMoves.emplace_back(p, &o);
                }
                done[p] = 0.0;
                ++pc[p];
            }
        }
        t += dt;
        revs += rpm / 60.0 * dt;
        if (moveEnded)
            for (const auto& [p, o] : endedMoves) moveEnded(p, *o);
    }

    // Runs until every path has ended or stands at a wait no partner meets
    // (those noted in `tl`, if given), or the clock reaches `until`.
    void run(Timeline* tl, double until = std::numeric_limits<double>::infinity())
    {
        for (int guard = 0; guard < 50'000'000; ++guard) {
            markers();
            if (release()) continue;
            if (t >= until - 1e-12) return;
            std::vector<std::size_t> running;
            for (std::size_t p = 0; p < n; ++p)
                if (pc[p] < ops[p].size() && !atWait(p)) running.push_back(p);
            if (running.empty()) {
                if (tl) deadlocks(*tl);
                return;
            }
            advance(running, until - t);
        }
    }
};

// The lag of every cut behind the one before it, over the Z both cover:
// along a cut the tool's Z goes with the spindle's revolutions (feed
// per revolution), so the lag in revolutions is linear in Z between
// the ends of the stretch.
void addLags(Run& run, Timeline& tl)
{
    const auto& traces = run.traces;
    auto& revsAt = run.revsAt;
    for (auto it = traces.begin(); it != traces.end(); ++it) {
        const auto next = std::next(it);
        if (next == traces.end()) break;
        const CutTrace& a = it->second;
        const CutTrace& b = next->second;
        const double lo = std::max(std::min(a.z0, a.z1), std::min(b.z0, b.z1));
        const double hi = std::min(std::max(a.z0, a.z1), std::max(b.z0, b.z1));
        if (hi < lo) continue;
        auto along = [](double v0, double v1, const CutTrace& c, double z) {
            return c.z1 == c.z0 ? v0 : v0 + (v1 - v0) * (z - c.z0) / (c.z1 - c.z0);
        };
        const auto ra = revsAt[it->first], rb = revsAt[next->first];
        double least = std::numeric_limits<double>::max(), seconds = least;
        for (const double z : {lo, hi}) {
            least = std::min(least, along(rb.first, rb.second, b, z) - along(ra.first, ra.second, a, z));
            seconds = std::min(seconds, along(b.t0, b.t1, b, z) - along(a.t0, a.t1, a, z));
        }
        tl.lags.push_back({it->first, next->first, least, seconds});
    }
}

}  // namespace

double Timeline::seconds() const
{
    double s = 0.0;
    for (double e : pathEnd) s = std::max(s, e);
    return s;
}

double Timeline::leastLag() const
{
    double least = std::numeric_limits<double>::max();
    for (const auto& l : lags) least = std::min(least, l.revolutions);
    return least;
}

Timeline runTimeline(const BalancedCut& cut, const Machine& machine)
{
    Timeline tl;
    Run run(cut, machine);
    run.run(&tl);
    tl.pathEnd = run.ended;
    // Each block's dwell as the cut says it (run above as a dwell before the cut).
    for (const auto& path : cut.paths)
        for (const auto& b : path.blocks)
            if (const auto it = run.blocks.find(b.number); it != run.blocks.end()) it->second.dwell = b.dwellSeconds;
    for (auto& [k, b] : run.blocks)
        if (k > 0) tl.blocks.push_back(b);
    addLags(run, tl);
    return tl;
}

std::vector<ZR> toolsAt(const BalancedCut& cut, const Machine& machine, double seconds)
{
    Run run(cut, machine);
    run.run(nullptr, seconds);
    return run.pos;
}

ToolPlaces toolPlaces(const BalancedCut& cut, const Machine& machine)
{
    // Each block's first move among the single path's: the blocks cut it
    // into pieces in CB order, none lost or doubled, path 1's tail after them.
    std::vector<std::size_t> sizes(static_cast<std::size_t>(std::max(cut.blockCount, 0)) + 1, 0);
    for (const BalancedPath& p : cut.paths)
        for (const BalancedBlock& b : p.blocks) sizes.at(static_cast<std::size_t>(b.number)) = b.moves.size();
    std::vector<std::size_t> first(sizes.size(), 0);
    std::size_t count = 0;
    for (std::size_t k = 1; k < sizes.size(); ++k) {
        first[k] = count;
        count += sizes[k];
    }
    const std::size_t tailFrom = count;
    count += cut.paths.empty() ? 0 : cut.paths.front().tail.size();
    Run run(cut, machine);
    ToolPlaces places;
    places.start = run.pos;
    places.afterMove.assign(count, {});
    run.moveEnded = [&](std::size_t p, const Op& o) {
        if (o.block == 0 && p != 0) return;  // another path's tail: no move of the single path
        const std::size_t at = (o.block > 0 ? first[static_cast<std::size_t>(o.block)] : tailFrom) + static_cast<std::size_t>(o.index);
        places.afterMove.at(at) = run.pos;
    };
    run.run(nullptr);
    // A move no path ran (a deadlock stopped it): the places where the run stopped.
    for (auto& a : places.afterMove)
        if (a.empty()) a = run.pos;
    return places;
}

double singlePathSeconds(const TurnPath& path, const TurnCutting& cutting, const Machine& machine)
{
    const Clock clk{cutting, machine, cutting.maxRpm > 0 ? std::min(cutting.maxRpm, machine.maxSpindleSpeed) : machine.maxSpindleSpeed};
    double s = 0.0;
    ZR at = path.start;
    for (const auto& m : path.moves) {
        s += clk.seconds(at, m);
        at = m.end;
    }
    return s;
}

}  // namespace taiwa
