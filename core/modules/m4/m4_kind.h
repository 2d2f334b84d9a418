// Internal to module M4: the pieces its door (m4_kind.cpp) puts together.
#pragma once

#include "modules/m4/m4.h"
#include "modules/module_kind.h"

namespace taiwa {
namespace check {
// Input checks of one M4 unit (lengths in mm): m4_check.cpp.
UnitReport checkM4(const M4Pocket& mm, int unitNo, const Context& ctx);
}  // namespace check
}  // namespace taiwa
