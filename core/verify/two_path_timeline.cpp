// The two-path timeline (two_path_timeline.h).
#include "verify/two_path_timeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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
    const LathePath& a = mp.paths[0];
    const LathePath& b = mp.paths[p];
    if (a.zDirection * b.zDirection * a.xDirection * b.xDirection < 0 && m.kind != TurnMove::Rapid && m.kind != TurnMove::Feed)
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
    const MultiPath* mp = machine.layout.multiPath ? &*machine.layout.multiPath : nullptr;
    const std::size_t n = cut.paths.size();
    auto toP1 = [&](const TurnMove& m, std::size_t p) { return mp ? back(m, *mp, p) : m; };
    auto pointToP1 = [&](ZR z, std::size_t p) { return mp ? mp->toPath1(z, p) : z; };

    // Each path's program as operations, in path 1's coordinates.
    std::vector<std::vector<Op>> ops(n);
    for (std::size_t p = 0; p < n; ++p) {
        const BalancedPath& bp = cut.paths[p];
        ZR at = pointToP1(bp.start, p);
        auto move = [&](const TurnMove& m) {
            Op o;
            o.kind = Op::Move;
            o.move = toP1(m, p);
            o.from = at;
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
                move(b.moves[i]);
                if (i == cm) mark(Op::CutEnd, b.number);
                pathAt = b.moves[i].end;
            }
            mark(Op::BlockEnd, b.number);
        }
        if (bp.tailWait) mark(Op::Wait, 0, *bp.tailWait);
        for (const auto& m : bp.tail) move(m);
    }

    const Clock clk{cut.cutting, machine, cut.spindleLimit > 0 ? cut.spindleLimit : machine.maxSpindleSpeed};
    std::vector<double> t(n, 0.0);
    std::vector<std::size_t> pc(n, 0);
    std::map<int, TimelineBlock> blocks;
    std::map<int, CutTrace> traces;
    auto hasCode = [&](std::size_t p, int code) {
        for (std::size_t i = pc[p]; i < ops[p].size(); ++i)
            if (ops[p][i].kind == Op::Wait && ops[p][i].code == code) return true;
        return false;
    };
    for (;;) {
        // Run every path up to its next wait or its end.
        for (std::size_t p = 0; p < n; ++p) {
            for (; pc[p] < ops[p].size() && ops[p][pc[p]].kind != Op::Wait; ++pc[p]) {
                const Op& o = ops[p][pc[p]];
                TimelineBlock& b = blocks[o.block];
                switch (o.kind) {
                case Op::Move: t[p] += clk.seconds(o.from, o.move); break;
                case Op::Dwell: t[p] += o.seconds; b.dwell = o.seconds; break;
                case Op::BlockStart:
                    b.number = o.block;
                    b.path = p;
                    b.start = b.waitFrom = b.waitTo = t[p];
                    break;
                case Op::CutStart: {
                    b.cutStart = t[p];
                    const Op& m = ops[p][pc[p] + 1];
                    traces[o.block] = {t[p], 0.0, m.from.z, m.move.end.z, m.move.end.r};
                    break;
                }
                case Op::CutEnd: b.cutEnd = traces[o.block].t1 = t[p]; break;
                case Op::BlockEnd: b.end = t[p]; break;
                case Op::Wait: break;
                }
            }
        }
        std::vector<std::size_t> waiting;
        for (std::size_t p = 0; p < n; ++p)
            if (pc[p] < ops[p].size()) waiting.push_back(p);
        if (waiting.empty()) break;
        // Release a code every path that has it stands at.
        bool released = false;
        for (std::size_t p : waiting) {
            const int code = ops[p][pc[p]].code;
            std::vector<std::size_t> party;
            bool all = true;
            for (std::size_t q = 0; q < n; ++q) {
                if (!hasCode(q, code)) continue;
                party.push_back(q);
                if (pc[q] >= ops[q].size() || ops[q][pc[q]].kind != Op::Wait || ops[q][pc[q]].code != code) all = false;
            }
            if (!all || party.size() < 2) continue;
            double meet = 0.0;
            for (std::size_t q : party) meet = std::max(meet, t[q]);
            for (std::size_t q : party) {
                const Op& w = ops[q][pc[q]];
                if (w.block) {
                    blocks[w.block].waitFrom = t[q];
                    blocks[w.block].waitTo = meet;
                    blocks[w.block].wait = code;
                }
                t[q] = meet;
                ++pc[q];
            }
            released = true;
            break;
        }
        if (released) continue;
        for (std::size_t p : waiting) {
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
        break;
    }
    tl.pathEnd = t;
    for (auto& [k, b] : blocks)
        if (k > 0) tl.blocks.push_back(b);

    // The lag of every cut behind the one before it, over the Z both cover.
    for (auto it = traces.begin(); it != traces.end(); ++it) {
        const auto next = std::next(it);
        if (next == traces.end()) break;
        const CutTrace& a = it->second;
        const CutTrace& b = next->second;
        const double lo = std::max(std::min(a.z0, a.z1), std::min(b.z0, b.z1));
        const double hi = std::min(std::max(a.z0, a.z1), std::max(b.z0, b.z1));
        if (hi < lo) continue;
        auto at = [](const CutTrace& c, double z) {
            return c.z1 == c.z0 ? c.t0 : c.t0 + (c.t1 - c.t0) * (z - c.z0) / (c.z1 - c.z0);
        };
        const double rpm = std::min(cut.cutting.rpmAt(2 * std::abs(a.level), clk.limit),
                                    cut.cutting.rpmAt(2 * std::abs(b.level), clk.limit));
        double least = std::numeric_limits<double>::max();
        for (const double z : {lo, hi}) least = std::min(least, at(b, z) - at(a, z));
        tl.lags.push_back({it->first, next->first, least * rpm / 60.0, least});
    }
    return tl;
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
