// The run behind the two-path timeline (two_path_timeline.h): each path's
// program as operations in path 1's coordinates, and the one clock that
// steps them together (the spindle's speed, the waits, each block's and
// cut's times, where each tool stands). Defined in two_path_run.cpp; the
// timeline, its lags and its place queries (two_path_timeline.cpp) read
// it. Internal to core/verify.
#pragma once

#include "verify/two_path_timeline.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace taiwa::detail {

// One thing a path does, in path 1's coordinates.
struct Op {
    enum Kind { Move, Wait, Dwell, BlockStart, CutStart, CutEnd, BlockEnd } kind = Move;
    TurnMove move;  // end, centre in path 1's coordinates
    turning::ZR from{};
    int code = 0;
    double seconds = 0.0;
    int block = 0;
    int index = -1;  // Move: its index among its block's moves (block 0: the tail's)
};

struct Clock {
    const TurnCutting& cutting;
    const Machine& machine;
    double limit;
    double seconds(turning::ZR a, const TurnMove& m) const;
};

struct CutTrace {
    double t0 = 0.0, t1 = 0.0, z0 = 0.0, z1 = 0.0, level = 0.0;
};

// The paths run together: where each is in its operations and how far into
// the current one (done: the fraction of the move or dwell; -1 standing at
// a wait, -2 ended), when it came to its wait or ended, the clock, the
// spindle's revolutions, and when each block and cut began and ended.
struct Run {
    const BalancedCut& cut;
    const Clock clk;
    std::vector<turning::ZR> startOf;
    std::vector<std::vector<Op>> ops;
    std::size_t n;
    std::vector<std::size_t> pc;
    std::vector<double> done, arrived, ended;
    std::vector<turning::ZR> pos;
    double t = 0.0, revs = 0.0;
    std::map<int, TimelineBlock> blocks;
    std::map<int, CutTrace> traces;
    std::map<int, std::pair<double, double>> revsAt;  // cut: revolutions at its start and end
    // Called after a step of the clock for each move a path ended in it
    // (path, its operation), every path's position up to date.
    std::function<void(std::size_t, const Op&)> moveEnded;

    Run(const BalancedCut& c, const Machine& m);

    static double lengthOf(const Op& o);
    bool hasCode(std::size_t p, int code) const;
    bool atWait(std::size_t p) const { return pc[p] < ops[p].size() && ops[p][pc[p]].kind == Op::Wait; }

    // The markers at once; a path at a wait notes when it came.
    void markers();
    // Releases a code every path that has it stands at; whether one was.
    bool release();
    // Every path standing at a wait no other path will come to, and why.
    void deadlocks(Timeline& tl) const;
    // The clock moved on by one step (at most `cap` seconds) for the running paths.
    void advance(const std::vector<std::size_t>& running, double cap);
    // Runs until every path has ended or stands at a wait no partner meets
    // (those noted in `tl`, if given), or the clock reaches `until`.
    void run(Timeline* tl, double until = std::numeric_limits<double>::infinity());
};

}  // namespace taiwa::detail
