// The grinding allowance of seed 001 (docs/turning.md): each picked edge is
// moved outward into the stock by its allowance, its neighbours extended or
// trimmed to meet it by the rule of the angle between them, the loop so made
// is united with the part, relief grooves are cut at concave corners, and
// the nose-radius adjustment shortens the allowance at tangent joints. The
// result is the deformed profile the lathe must cut, each edge saying where
// it came from. Arcs stay exact arcs (the booleans are OpenCASCADE's,
// behind core/occt/).
#pragma once

#include "model/job.h"
#include "turning/profile.h"
#include "turning/profile_resolve.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::turning {

// How a picked edge meets its neighbour at one end: the angle is the part's
// own (material-side) angle at the shared vertex.
enum class Joint {
    FreeEnd,   // the profile ends here: the allowance ends square to the edge
    UpTo90,    // 0°–90°: a new edge from the vertex, square to the picked edge
    Obtuse,    // 90°–180°: the new edge follows the neighbour's tangent
    Tangent,   // 180°: square to the picked edge, from the vertex shifted by the adjustment
    Concave,   // above 180°: the new edge follows the neighbour
    BothSet,   // convex up to 180°, neighbour ground too: the two moved edges meet
};
const char* toKey(Joint j);  // "free end", "0-90", "90-180", "180", "above 180", "both ground"

enum class Origin { Original, Moved, Side, Groove };
const char* toKey(Origin o);  // "original", "moved", "side", "groove"

struct DeformedEdge {
    std::string id;           // "E3" (unchanged or trimmed), "E3.moved", "E3.start", "E3.end", "E3.groove1"
    Segment geometry;
    EdgeAttributes attributes;  // the source edge's, kept on its moved edge
    Origin origin = Origin::Original;
    std::string from;         // the profile edge it comes from
    int allowanceRow = -1;    // 0-based row of the allowance table that made it; -1 for untouched edges
    friend bool operator==(const DeformedEdge&, const DeformedEdge&) = default;
};

struct GrooveMade {
    GrooveKind kind = GrooveKind::Lateral;  // never Auto or None
    bool identified = false;                // chosen by the rules, not typed
    std::string rule;                       // why this kind ("E3 runs along the axis")
    std::string inEdge;                     // the edge it is cut into (both for a ring: "E3, E2")
    double width = 0.0, depth = 0.0;
    ZR corner;
    friend bool operator==(const GrooveMade&, const GrooveMade&) = default;
};

struct EndOutcome {
    Joint joint = Joint::FreeEnd;
    double angle = 0.0;           // the part's angle at the vertex [deg]; 0 at a free end
    std::string neighbour;        // its id; empty at a free end
    double adjustment = 0.0;      // used at a tangent joint
    std::string adjustmentFrom;   // "typed", "nose radius of T102 (…)"
    std::optional<GrooveMade> groove;
    std::string grooveNote;       // why none was made at a concave corner of 90°–180°
    friend bool operator==(const EndOutcome&, const EndOutcome&) = default;
};

struct AllowanceOutcome {
    std::string edge;
    double allowance = 0.0;
    EndOutcome start, end;  // at the edge's start and end vertex, in cutting order
    friend bool operator==(const AllowanceOutcome&, const AllowanceOutcome&) = default;
};

struct DeformedProfile {
    ProfileSide side = ProfileSide::Outer;
    std::vector<DeformedEdge> edges;  // one chain in cutting order
    std::vector<AllowanceOutcome> rows;  // one per allowance row
};

struct AllowanceOptions {
    // The finishing tool's nose radius, the adjustment where a row gives none.
    std::optional<double> noseRadius;
    std::string toolName;  // for the sheet: "T102 (turning insert DNMG 150604)"
    LengthUnit shown = LengthUnit::Millimetre;
};

struct Deformation {
    DeformedProfile profile;
    std::vector<FieldProblem> problems;  // each on "allowances[N].<field>"
    bool ok() const { return problems.empty(); }
};

// The profile with every allowance row applied; lengths in mm. With no rows
// the profile comes back unchanged. A refused row leaves the profile as far
// as it got; the problems say which row and field.
Deformation applyAllowances(const ResolvedProfile& profile, const std::vector<AllowanceRow>& rows,
                            const AllowanceOptions& options = {});

}  // namespace taiwa::turning
