// What the contour units' decomposition asks of a pocket region before any
// tool is chosen (the paths themselves are in generators.h): how large a
// cutter reaches every part of it.
#pragma once

#include "model/contour.h"

namespace taiwa::paths {

// The radius of the largest circle inside the region, from below: the
// pole of inaccessibility (polylabel) over RegionDistance, to 1 µm or 10⁻⁵
// of the box's longer side, whichever is larger, splitting at most 40,000
// cells and 5·10⁷ segment distances (a long ridge: the best centre found
// then, within the last cells' size). The widest a pocket
// tool may be is about this much, as for a four-cornered pocket (half its
// width). No Clipper offsets (a 2,000-edge outline had taken minutes in
// Clipper's intersection ordering).
double inscribedRadius(const Region& region);

// The largest tool radius whose round cutter, kept inside the region, still
// sweeps all of it: limited by the narrowest channel (half its width) and the
// smallest inside corner radius, at most `inscribed` (inscribedRadius of the
// same region). Small radii are tried first, doubling, then bisection to
// 1 µm: a radius reaches everywhere when the cutter rolling along the whole
// boundary stays inside to 2 µm (rollsAround, paths/region_offset.h: exact
// parallels and corner arcs, near-linear in the segments). At most
// kMaxReach: no pocket tool is wider, and the rolling test's grid grows
// with the radius (a 2,000-edge near-circle reached 321 mm in 2 minutes).
// 0 when the region is empty or has a sharp inside corner.
constexpr double kMaxReach = 100.0;  // mm
double reachRadius(const Region& region, double inscribed);

}  // namespace taiwa::paths
