// Switching a job between mm and inch: every length of the job (stock,
// corners, radii, depths, L1/L2, scallop, technology allowances) is
// converted so that the part stays the same; angles, codes and γ do not
// change. Values are rounded to 0.0001 mm / 0.000001 in so that the form
// shows what a machinist would type, and mm -> inch -> mm gives back the
// values typed with up to four decimals.
#pragma once

#include "model/job.h"

namespace taiwa::ui {

Job convertLengthUnit(const Job& job, LengthUnit to);

}  // namespace taiwa::ui
