// What the contour units' decomposition asks of a pocket region before any
// tool is chosen (the paths themselves are in generators.h): how large a
// cutter reaches every part of it.
#pragma once

#include "model/contour.h"

namespace taiwa::paths {

// The radius of the largest circle inside the region: stepping in from
// the last non-empty inset by halving steps, with Clipper on the region
// flattened to 1 µm chords (to about 1 µm a step): the widest a pocket tool
// may be is about this much, as for a four-cornered pocket (half its width).
double inscribedRadius(const Region& region);

// The largest tool radius whose round cutter, kept inside the region, still
// sweeps all of it: limited by the narrowest channel (half its width) and the
// smallest inside corner radius, at most `inscribed` (inscribedRadius of the
// same region). Small radii are tried first, doubling, then bisection to
// 1 µm: a radius reaches everywhere when shrinking the region by it and
// growing it back leaves out nothing thicker than 4 µm. 0 when the region is
// empty or has a sharp inside corner.
double reachRadius(const Region& region, double inscribed);

}  // namespace taiwa::paths
