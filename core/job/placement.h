// Where a new or duplicated unit goes: the nearest place in the stock where
// its figure overlaps no other unit's, so that "Add" and "Duplicate" never
// turn a valid job red.
#pragma once

#include "model/job.h"

#include <optional>

namespace taiwa {

// `unit` (in the job's length unit) moved to the free place nearest to where
// it is, scanning the stock on a grid (a twentieth of the stock); nullopt
// when the stock has no room for it. A unit whose module has no figure in XY
// comes back unchanged.
std::optional<ModuleInput> placeInFreeStock(const Job& job, ModuleInput unit);

}  // namespace taiwa
