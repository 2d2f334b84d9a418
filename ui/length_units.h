// Switching a job between mm and inch: every length of the job (stock,
// corners, radii, depths, L1/L2, scallop, technology allowances) is
// converted so that the part stays the same; angles, codes and γ do not
// change. Values are kept exact (the forms round what they show), so the
// plan does not change with the unit, and mm -> inch -> mm gives back the
// values typed.
#pragma once

#include "model/job.h"

namespace taiwa::ui {

Job convertLengthUnit(const Job& job, LengthUnit to);

}  // namespace taiwa::ui
