// The run behind the two-path timeline (two_path_run.h): both paths'
// programs turned into operations in path 1's coordinates (each block's
// wait, dwell and cut marked), and the clock that runs them together block
// by block, the one spindle's speed set by path 1, the waits met or
// deadlocked.
#include "verify/two_path_run.h"

#include "turning/balanced_roughing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::detail {

namespace {

using turning::ZR;

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

double arcLength(ZR a, const TurnMove& m)
{
    const double r = std::hypot(a.z - m.centre.z, a.r - m.centre.r);
    double sweep = std::atan2(m.end.r - m.centre.r, m.end.z - m.centre.z) - std::atan2(a.r - m.centre.r, a.z - m.centre.z);
    if (m.kind == TurnMove::ArcCW) sweep = -sweep;
    while (sweep <= 0) sweep += 2 * std::numbers::pi;
    return r * sweep;
}

}  // namespace

double Clock::seconds(ZR a, const TurnMove& m) const
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

Run::Run(const BalancedCut& c, const Machine& m)
    : cut(c), clk{c.cutting, m, c.spindleLimit > 0 ? c.spindleLimit : m.maxSpindleSpeed},
      ops(operationsOf(c, m, startOf)), n(c.paths.size()), pc(n, 0), done(n, 0.0), arrived(n, 0.0),
      ended(n, 0.0), pos(startOf)
{
}

double Run::lengthOf(const Op& o)
{
    return o.move.kind == TurnMove::Feed || o.move.kind == TurnMove::Rapid
               ? std::hypot(o.move.end.z - o.from.z, o.move.end.r - o.from.r)
               : arcLength(o.from, o.move);
}

bool Run::hasCode(std::size_t p, int code) const
{
    for (std::size_t i = pc[p]; i < ops[p].size(); ++i)
        if (ops[p][i].kind == Op::Wait && ops[p][i].code == code) return true;
    return false;
}

void Run::markers()
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

bool Run::release()
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

void Run::deadlocks(Timeline& tl) const
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

void Run::advance(const std::vector<std::size_t>& running, double cap)
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

void Run::run(Timeline* tl, double until)
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

}  // namespace taiwa::detail
