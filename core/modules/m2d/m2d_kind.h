// Internal to module M2D: the pieces its door (m2d_kind.cpp) puts together.
#pragma once

#include "modules/m2d/m2d.h"
#include "modules/module_kind.h"

namespace taiwa {
namespace check {
// Input checks of one M2D unit (lengths in mm): m2d_check.cpp.
UnitReport checkM2D(const M2DPocket& mm, int unitNo, const Context& ctx);
}  // namespace check
}  // namespace taiwa
