// The two-path timeline (docs/two-path-lathe.md "Timeline"): both paths'
// programs of a balanced cut run block by block against one clock, rapids
// at the machine's axis rates, feeds per revolution at the one spindle's
// speed (G97's, or G96's surface speed at path 1's X, capped by the limit:
// path 1 is the master), the dwells, and the waits (a wait M-code holds its
// path until every path whose program has that code stands at it). It reports each
// block's times on each path, the deadlocks (a wait that never meets its
// partner), and for every cut after the first the lag of its tool behind
// the cut before it (the leader: the level above) in spindle revolutions,
// the least over the stretch of Z both cut; the roughing's time on one
// path for the ratio; and, by the same run, where each path's tool stands
// at a moment (the station's 3-D view draws both turrets' tools there).
#pragma once

#include "machine/machine.h"
#include "model/two_path.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct TimelineBlock {
    int number = 0;        // CB number
    std::size_t path = 0;
    double start = 0.0;    // the block's first move [s]
    double waitFrom = 0.0, waitTo = 0.0;  // stood at the wait (equal: no wait, or it met at once) [s]
    double cutStart = 0.0, cutEnd = 0.0;  // the cut (the block's longest feed along Z) [s]
    double end = 0.0;      // after the return [s]
    std::optional<int> wait;
    double dwell = 0.0;    // [s]
};

struct CutLag {
    int leader = 0, follower = 0;  // CB numbers
    double revolutions = 0.0;      // the least lag over the Z both cut
    double seconds = 0.0;
};

struct Deadlock {
    std::size_t path = 0;
    int waitCode = 0;
    std::string why;  // "path 2 ended without M103", "path 2 waits at M104"
};

struct Timeline {
    std::vector<TimelineBlock> blocks;  // by CB number
    std::vector<double> pathEnd;        // each path's program end [s]
    std::vector<Deadlock> deadlocks;
    std::vector<CutLag> lags;
    double seconds() const;             // the last path's end
    double leastLag() const;            // revolutions; a large number with no lag to measure
};

// Runs the balanced cut's paths (each in its own program coordinates,
// converted back to path 1's with the machine's layout).
Timeline runTimeline(const BalancedCut& cut, const Machine& machine);

// Where each path's tool tip stands `seconds` after both programs start
// (by path, in path 1's coordinates; after the end, where each ended), by
// the same run as runTimeline: at a block's cut, timeline.blocks[k].cutStart.
std::vector<turning::ZR> toolsAt(const BalancedCut& cut, const Machine& machine, double seconds);

// Where each path's tool tip stands (by path, in path 1's coordinates)
// before anything moves, and at every move of the roughing the cut was
// made from (the single path's: its blocks' moves in CB order, then path
// 1's tail) at the moment the path that runs the move ends it: the one
// tool at the move's end, the others where they are then. By one run, the
// same as runTimeline.
struct ToolPlaces {
    std::vector<turning::ZR> start;                   // by path
    std::vector<std::vector<turning::ZR>> afterMove;  // by the single path's move, by path
};
ToolPlaces toolPlaces(const BalancedCut& cut, const Machine& machine);

// The seconds the same roughing takes on one path, by the same clock.
double singlePathSeconds(const TurnPath& path, const TurnCutting& cutting, const Machine& machine);

}  // namespace taiwa
