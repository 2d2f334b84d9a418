// A roughing cut balanced between the paths of a two-path lathe (seed 003,
// docs/two-path-lathe.md): the single path's roughing analysed into one
// command block per cut (approach, cut, retract, return), the blocks handed
// round-robin to the paths, each path's in its own program coordinates,
// with the wait M-code both paths meet at before a cut and the dwell the
// follower keeps behind the leader. Made by core/turning/balanced_roughing.h
// (kept in Plan::balance by planJob), run on a timeline by
// core/verify/two_path_timeline.h, written by the posts.
#pragma once

#include "model/result.h"
#include "model/turn_path.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace taiwa {

struct BalancedBlock {
    int number = 0;                 // CB1, CB2 … in the single path's order
    std::size_t path = 0;           // 0: path 1
    std::vector<TurnMove> moves;    // in the path's program coordinates
    std::size_t cutFrom = 0;        // moves[cutFrom] is the first feed: the wait and the dwell stand before it
    std::optional<int> wait;        // the wait M-code (M101 …) both paths meet at before the cut
    double dwellSeconds = 0.0;      // the follower's G04 after the wait (0: the leader)
    double dwellRevolutions = 0.0;  // what the dwell is in spindle revolutions at the slower of the two cuts' speeds
    double level = 0.0;             // the cut's radius, in path 1's coordinates [mm]
    double infeed = 0.0;            // across the axis from the path's previous cut level (the first: from the stock) [mm]
    double cutLength = 0.0;         // the feeds' length (cut and retract) [mm]: the cycle's length
    friend bool operator==(const BalancedBlock&, const BalancedBlock&) = default;
};

struct BalancedPath {
    turning::ZR start{};                 // in the path's program coordinates
    std::vector<BalancedBlock> blocks;   // this path's, in order
    std::optional<int> tailWait;         // a wait before the tail (the last meeting, where this path has no block)
    std::vector<TurnMove> tail;          // back to the safe point
    std::optional<int> endWait;          // after the tail: all paths meet before path 1 goes on with the job
    friend bool operator==(const BalancedPath&, const BalancedPath&) = default;
};

struct BalancedCut {
    std::vector<BalancedPath> paths;  // path 1, path 2 (, path 3)
    TurnCutting cutting;
    double spindleLimit = 0.0;        // the rpm cap the speeds were computed with
    int blockCount = 0;
    friend bool operator==(const BalancedCut&, const BalancedCut&) = default;
};

// A two-path lathe job's roughing step balanced as the export's programs
// have it (the job's settings, the paths meeting at the ends): made once,
// by planJob (turning::balancePlanRoughing), and read by the post, the
// sheet, the two-path verification and the station.
struct PlannedBalance {
    std::size_t step = 0;     // the roughing step's index in Plan::steps
    Result<BalancedCut> cut;  // refused: the Failure naming the field
};

}  // namespace taiwa
