// Whether a tool's name still says its size: the shop's names state it
// ("Flat end mill 8 mm carbide", "Ball end mill R5 carbide", "Ø10"), and a
// diameter edited from 8 to 12 mm under an unchanged name would send the
// operator to the wrong pocket of the magazine. The tool library dialog
// warns with it before the edit is applied.
#pragma once

#include "model/tool.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// The diameters a name states, in mm: "8 mm", "Ø8", "D8" as 8 and "R5" (a
// ball's radius) as 10.
std::vector<double> diametersInName(const std::string& name);

// A message when the edit from `before` (none: a new tool) to `after` leaves
// a name (the shop's, or one in another language) stating a diameter that
// is not the tool's; nothing for inserts and blades (their names state the
// insert, not a diameter), for names stating no size, and for an edit that
// changed neither the diameter nor the names.
std::optional<std::string> nameSizeWarning(const std::optional<Tool>& before, const Tool& after);

}  // namespace taiwa
