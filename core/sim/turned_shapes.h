// What the turning simulations share (the stock of the preview,
// turned_stock.h, and the verification, core/verify): a move's points, the
// shape a lathe tool cuts with about its programmed point, and a TURN
// unit's finished part, all as polygons in the (z, r) half-plane.
#pragma once

#include "model/plan.h"
#include "model/turned.h"
#include "model/turn_path.h"
#include "turning/turn_region.h"

#include <optional>
#include <vector>

namespace taiwa::sim {

// The points of a move from `from`: its two ends, an arc as chords of
// sagitta at most `tol`.
std::vector<turning::ZR> movePoints(turning::ZR from, const TurnMove& m, double tol = turning::kFlatten);

// The tool's cutting shape about its programmed point: a drill its body on
// the axis, a blade its rectangle, an insert its nose (a polygon of `sides`
// holding the circle) and, above it, the edge: everything over the nose
// along a cut is chip (the stock's surface is never above the edge).
std::vector<turning::ZR> shapeOf(const Step& s, const Tool& t, int sides = 16);

// The part of a unit (its deformed profile) as a polygon: an outer unit's
// closed toward the axis, with the bar behind it up to `heldEnd` (held in
// the chuck) when given, else closed straight down at both ends; an inner
// unit's out to `rOut`. Empty when the unit has no turned part.
std::vector<turning::ZR> partOf(const Plan& plan, int unit, double rOut, std::optional<double> heldEnd);

}  // namespace taiwa::sim
