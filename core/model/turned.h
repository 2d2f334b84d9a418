// A turned part's profile as plain values: its half cross-section in the +XZ
// plane as the operator enters it (rows in cutting order, diameters as a
// lathe control prints them) and as the core computes with it (exact lines
// and arcs in Z and radius, each edge with a stable id); the
// grinding-allowance table (seed 001) and what applying it made: the
// deformed profile, each edge saying where it came from (TurnedPart, a
// plan's result for one TURN unit). The computations are in core/turning/,
// the exact line/arc geometry in model/turned_geometry.h, OpenCASCADE only
// behind core/occt/.
//
// Conventions, everywhere in Taiwa's turning code:
// - Z runs along the spindle axis, X across it; the operator reads and types
//   X as a diameter, the geometry works with the radius r = X / 2.
// - The profile view shows Z to the right and X upward (+Y toward the
//   viewer), so an arc drawn clockwise there is G2 in G18 and
//   counter-clockwise is G3.
#pragma once

#include "model/module.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::turning {

// A point of the half-section: z along the axis, r the radius (>= 0).
struct ZR {
    double z = 0.0;
    double r = 0.0;
    friend bool operator==(const ZR&, const ZR&) = default;
};

enum class ProfileSide { Outer, Inner };           // OD: material toward the axis; ID: away from it
enum class ElementKind { Line, ArcCW, ArcCCW };    // as seen in the profile view (G2 / G3 in G18)
enum class CornerKind { None, Chamfer, Rounding };  // at the end of a row, toward the next row

// An external thread cut on a straight row along the axis
// (docs/turning.md "Threading"): its pitch and, when the drawing gives it,
// its depth on the radius (none: ISO metric, kIsoThreadDepth × pitch).
struct ThreadSpec {
    double pitch = 0.0;            // [mm]
    std::optional<double> depth;   // on the radius [mm]
    friend bool operator==(const ThreadSpec&, const ThreadSpec&) = default;
};
// The depth of an ISO metric external thread on the radius, per pitch
// (ISO 68-1: h3 = 0.61343 P).
inline constexpr double kIsoThreadDepth = 0.6134;
// The pitches a thread may have [mm] (ISO metric coarse and fine: 0.2 to 6).
inline constexpr double kMinThreadPitch = 0.2, kMaxThreadPitch = 6.0;

// What an edge must meet once turned and ground.
struct EdgeAttributes {
    std::optional<double> roughness;  // Ra [µm]
    std::string tolerance;            // an ISO 286 fit ("h6", "H7") or limits ("+0.01/-0.02"); empty: none
    std::optional<ThreadSpec> thread; // a thread cut on the edge
    bool empty() const { return !roughness && tolerance.empty() && !thread; }
    // The thread's depth on the radius: as given, or ISO metric's.
    double threadDepth() const { return thread ? thread->depth.value_or(kIsoThreadDepth * thread->pitch) : 0.0; }
    friend bool operator==(const EdgeAttributes&, const EdgeAttributes&) = default;
};

// One row of the profile table: an element from the previous row's end (or
// the profile's start) to this row's end point.
struct ProfileRow {
    int id = 0;                     // stable; the edge id is "E<id>", its corner "E<id>.c"
    ElementKind kind = ElementKind::Line;
    double x = 0.0;                 // end point: diameter
    double z = 0.0;                 // end point: Z
    // Arcs: the radius (the arc of less than half a turn), or the centre
    // (diameter and Z) when the arc is longer or the operator has it.
    std::optional<double> radius;
    std::optional<double> centreX, centreZ;
    CornerKind corner = CornerKind::None;
    double cornerSize = 0.0;        // chamfer leg (along both lines) or rounding radius
    EdgeAttributes attributes;
    friend bool operator==(const ProfileRow&, const ProfileRow&) = default;
};

enum class GrooveKind { Auto, None, Lateral, Longitudinal, Ring };

// One row of the grinding-allowance table (seed 001, Fig. 2).
struct AllowanceRow {
    std::string edge;                  // "E3"
    double allowance = 0.0;            // stock left for grinding, normal to the edge [mm]
    std::optional<double> adjustment;  // at a tangent (180°) joint; none: the finishing tool's nose radius
    GrooveKind groove = GrooveKind::Auto;
    std::optional<double> grooveWidth;  // none: no relief groove
    std::optional<double> grooveDepth;  // none: the allowance
    friend bool operator==(const AllowanceRow&, const AllowanceRow&) = default;
};

struct TurnedProfile {
    ProfileSide side = ProfileSide::Outer;
    double startX = 0.0;  // start point: diameter
    double startZ = 0.0;
    std::vector<ProfileRow> rows;
    std::vector<AllowanceRow> allowances;

    int nextRowId() const
    {
        int id = 0;
        for (const auto& r : rows) id = std::max(id, r.id);
        return id + 1;
    }
    void convertLengths(const LengthMap& f)
    {
        startX = f(startX);
        startZ = f(startZ);
        for (auto& r : rows) {
            r.x = f(r.x);
            r.z = f(r.z);
            if (r.radius) r.radius = f(*r.radius);
            if (r.centreX) r.centreX = f(*r.centreX);
            if (r.centreZ) r.centreZ = f(*r.centreZ);
            r.cornerSize = f(r.cornerSize);
            if (r.attributes.thread) {
                r.attributes.thread->pitch = f(r.attributes.thread->pitch);
                if (r.attributes.thread->depth) r.attributes.thread->depth = f(*r.attributes.thread->depth);
            }
            // roughness stays in µm Ra, tolerance as typed
        }
        for (auto& a : allowances) {
            a.allowance = f(a.allowance);
            if (a.adjustment) a.adjustment = f(*a.adjustment);
            if (a.grooveWidth) a.grooveWidth = f(*a.grooveWidth);
            if (a.grooveDepth) a.grooveDepth = f(*a.grooveDepth);
        }
    }
    friend bool operator==(const TurnedProfile&, const TurnedProfile&) = default;
};

// An exact edge of the half-section, in z and radius.
struct Segment {
    bool arc = false;
    ZR a, b;          // start and end, in the direction of travel
    ZR centre;        // arcs
    double radius = 0.0;
    bool ccw = false;  // arcs: counter-clockwise in the profile view (G3)
    friend bool operator==(const Segment&, const Segment&) = default;
};

// A resolved edge of the profile: its geometry, id and attributes.
struct Edge {
    std::string id;      // "E3", "E3.c" for the chamfer or rounding at row E3's end
    Segment geometry;
    EdgeAttributes attributes;
    int row = 0;         // 0-based row of the profile table it comes from
    bool corner = false; // a chamfer or rounding made from the row's corner field
    friend bool operator==(const Edge&, const Edge&) = default;
};

struct ResolvedProfile {
    ProfileSide side = ProfileSide::Outer;
    std::vector<Edge> edges;  // one chain, in cutting order
    const Edge* find(const std::string& id) const
    {
        for (const auto& e : edges)
            if (e.id == id) return &e;
        return nullptr;
    }
};

std::string edgeId(int rowId);  // "E3"
std::string cornerEdgeId(int rowId);  // "E3.c"

const char* toKey(ElementKind k);  // "line", "cw", "ccw"
const char* toKey(CornerKind k);   // "none", "chamfer", "rounding"
const char* toKey(GrooveKind k);   // "auto", "none", "lateral", "longitudinal", "ring"
const char* toKey(ProfileSide s);  // "outer", "inner"
std::optional<ElementKind> elementKindFromKey(const std::string& s);
std::optional<CornerKind> cornerKindFromKey(const std::string& s);
std::optional<GrooveKind> grooveKindFromKey(const std::string& s);
std::optional<ProfileSide> profileSideFromKey(const std::string& s);

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

}  // namespace taiwa::turning

namespace taiwa {

struct TurnedPart {
    int unit = 0;  // 0-based unit index
    std::string name;
    turning::ResolvedProfile profile;
    turning::DeformedProfile deformed;
    std::string noseRadiusTool;  // the finishing tool whose nose radius gave adjustments ("" when none was needed)
    // Every row resolved and every allowance row applied; false: `deformed`
    // is as far as it got (the unit's check refuses it, the profile
    // editor draws no deformed profile).
    bool complete = true;
};

}  // namespace taiwa
