// Lathe tools as the turning paths see them (docs/turning.md "Tool choice"):
// an insert's nose radius, the directions its holder lets it travel along
// the profile without back-cutting beyond the insert's clearance, its shape
// for the forbidden region, its tip orientation and the programmed point; a
// blade's width and reach. And the choice among the library's tools for
// each turning step, with the reason in words.
#pragma once

#include "model/tool.h"
#include "model/turned.h"
#include "turning/turn_region.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::turning {

// Degrees kept free between a profile element and the insert's cutting edge.
constexpr double kEdgeClearanceDeg = 2.0;

struct InsertGeometry {
    double noseRadius = 0.0;
    double approach = 95.0;   // κr: leading edge from the feed direction (-Z) [deg]
    double tipAngle = 80.0;   // ε [deg]
    bool inside = false;      // a boring bar
    // Travel toward -Z along the profile: the element's angle θ from -Z,
    // positive away from the material (outer: up), may lie in [minRise, maxRise].
    double minRise() const { return -(180.0 - approach - tipAngle - kEdgeClearanceDeg); }
    double maxRise() const { return approach - kEdgeClearanceDeg; }
};

// The insert's geometry from its ISO code and holder; nullopt for a tool
// that is not a turning insert or whose code does not read.
std::optional<InsertGeometry> insertGeometry(const Tool& t);

// The element's direction of travel at a point as θ [deg] (see InsertGeometry).
double riseDegrees(ZR tangent, ProfileSide side);
// Whether the insert can cut the edge travelling toward -Z (arcs checked
// over their whole sweep).
bool reaches(const InsertGeometry& g, const Segment& s, ProfileSide side);

// The insert's shape about its nose centre (nose and both cutting edges).
ToolShape insertShape(const InsertGeometry& g);
// A blade's shape about its front corner (toward +Z, on the cutting side).
ToolShape bladeShape(double width, double reach, bool inside);

// The tip orientation (LinuxCNC tool table Q, FANUC's imaginary tip number)
// and the programmed point relative to the nose centre.
int insertOrientation(bool inside);
ZR tipFromCentre(double noseRadius, bool inside);

}  // namespace taiwa::turning
