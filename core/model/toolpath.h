// Cutter-location (CL) data: the tool-tip path of one step as a list of
// moves. Arcs stay arcs. Z is measured in the work coordinate system, the top
// of the stock being Z = 0 (so a depth T is Z = -T). All lengths in mm.
#pragma once

#include "model/geometry.h"

#include <vector>

namespace taiwa {

struct Point3 {
    double x = 0.0, y = 0.0, z = 0.0;
    friend bool operator==(const Point3&, const Point3&) = default;
};

enum class MoveKind {
    Rapid,      // G0 to `end`
    Feed,       // G1 to `end` at the feed of `feed`
    ArcCW,      // G2 in XY around `centre` (z of the end may differ: helix)
    ArcCCW,     // G3
    DrillCycle, // canned drilling at end.xy from `retractZ` down to end.z, peck `peck` (0 = none)
};

enum class FeedKind { Cut, Plunge, Ramp };

// What a DrillCycle move does at its hole (G98 each: back to the level it
// started from, or R when that is higher): drill (G81, or G83 pecking when
// `peck` > 0), tap right-hand at `pitch` per revolution (G84), ream (feed in,
// feed out: G85), bore (feed in, spindle stopped, out: G86).
enum class CycleKind { Drill, Tap, Ream, Bore };

struct Move {
    MoveKind kind = MoveKind::Rapid;
    Point3 end{};
    Point2 centre{};       // arcs only
    FeedKind feed = FeedKind::Cut;
    double retractZ = 0.0; // drill cycles: R plane
    double peck = 0.0;     // drill cycles: peck depth, 0 = straight drilling
    CycleKind cycle = CycleKind::Drill;  // drill cycles: what the cycle does
    double pitch = 0.0;    // tapping cycles: the thread's pitch [mm per revolution]
    friend bool operator==(const Move&, const Move&) = default;
};

struct ToolPath {
    Point3 start{};            // where the tool is before the first move (at safe height)
    std::vector<Move> moves;
    friend bool operator==(const ToolPath&, const ToolPath&) = default;
};

// The signed sweep [rad] in XY of an arc move (ArcCW or ArcCCW) that starts
// at `from`, around arc.centre to arc.end, the way a controller reads G2/G3:
// atan2(cross, dot) of the start and end radii, then counter-clockwise
// positive in (0, 2π] (a result <= 0 gains 2π), clockwise negative in
// [-2π, 0) (a result >= 0 loses 2π). An arc that ends where it starts is a
// full circle, +2π or -2π, never 0 (a start on the centre counts as that
// too). Z plays no part (a helix sweeps as its projection). The one place
// this convention is written; lengths, times, flattening and the post use it.
double arcSweep(Point3 from, const Move& arc);

// Length of the path, split into cutting and rapid travel.
struct PathLength {
    double feed = 0.0;
    double rapid = 0.0;
};
PathLength pathLength(const ToolPath& p);

}  // namespace taiwa
