// A tool path flattened into straight pieces for simulation and drawing:
// arcs and helices sampled within a chord tolerance, drill cycles unrolled
// into their approach, feed and retract. Each piece remembers its move.
#pragma once

#include "model/toolpath.h"

#include <vector>

namespace taiwa::sim {

struct PathPiece {
    Point3 from{};
    Point3 to{};
    int move = 0;        // index into ToolPath::moves
    bool rapid = false;  // G0 travel (also the approach and retract of a drill cycle)
};

// A piece of path as the verification sweeps it: straight, or an arc (a
// helix when its ends differ in Z) kept exact.
struct SweptPiece {
    Point3 from{};
    Point3 to{};
    int move = 0;
    bool rapid = false;
    bool arc = false;
    Point2 centre{};     // arcs: the centre
    double sweep = 0.0;  // arcs: signed angle, counter-clockwise positive [rad]
};

// The path's pieces in order, arcs whole (drill cycles unrolled as in
// flattenPath).
std::vector<SweptPiece> sweptPieces(const ToolPath& path);

// Straight pieces of the path in order; consecutive pieces join end to start.
// Arcs are sampled so that no chord is further than `chordTolerance` [mm]
// from the true arc; a full circle (end == start) is swept once.
std::vector<PathPiece> flattenPath(const ToolPath& path, double chordTolerance = 0.01);

// Where the tool is after the move `index` (drill cycles return to the
// level they started from, above the hole).
Point3 positionAfter(const ToolPath& path, int index);

}  // namespace taiwa::sim
