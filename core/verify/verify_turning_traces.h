// The programmed point's path of a turning step's moves with the nose
// compensation applied as the control applies it (verify_turning_traces.cpp),
// for the lathe verification. Internal to core/verify.
#pragma once

#include "model/turn_path.h"

#include <vector>

namespace taiwa::verify {

// One polyline per move of the step's path: arcs as chords within `tol`;
// along the compensated stretch the point where the tool would be
// programmed without compensation for its nose (radius `nose`) to be where
// the control puts it.
std::vector<std::vector<turning::ZR>> traces(const TurnStep& ts, double nose, double tol);

}  // namespace taiwa::verify
