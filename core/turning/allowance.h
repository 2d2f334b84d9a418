// The grinding allowance of seed 001 (docs/turning.md): each picked edge is
// moved outward into the stock by its allowance, its neighbours extended or
// trimmed to meet it by the rule of the angle between them, the loop so made
// is united with the part, relief grooves are cut at concave corners, and
// the nose-radius adjustment shortens the allowance at tangent joints. The
// result is the deformed profile the lathe must cut, each edge saying where
// it came from. Arcs stay exact arcs (the booleans are OpenCASCADE's,
// behind core/occt/).
#pragma once

#include "model/job.h"
#include "model/tool.h"
#include "model/turned.h"
#include "turning/profile_resolve.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::turning {

struct AllowanceOptions {
    // The finishing tool's nose radius, the adjustment where a row gives none.
    std::optional<double> noseRadius;
    std::string toolName;  // for the sheet: "T102 (turning insert DNMG 150604)"
    LengthUnit shown = LengthUnit::Millimetre;
};

struct Deformation {
    DeformedProfile profile;
    std::vector<FieldProblem> problems;  // each on "allowances[N].<field>"
    bool ok() const { return problems.empty(); }
};

// The profile with every allowance row applied; lengths in mm. With no rows
// the profile comes back unchanged. A refused row leaves the profile as far
// as it got; the problems say which row and field.
Deformation applyAllowances(const ResolvedProfile& profile, const std::vector<AllowanceRow>& rows,
                            const AllowanceOptions& options = {});

// The options of `profile`'s deformation: the nose radius and name of the
// finishing insert of `library` for its side (tools/turning_tools.h), and
// messages quoting lengths in `shown`.
AllowanceOptions allowanceOptions(const TurnedProfile& profile, const std::vector<Tool>& library, LengthUnit shown);

// `resolved` (the profile table `profile` resolved) with its allowance rows
// applied by those options: the one computation of TURN's check, the plan's
// turned part and the station's profile editor.
Deformation deformProfile(const TurnedProfile& profile, const ResolvedProfile& resolved, const std::vector<Tool>& library,
                          LengthUnit shown);

}  // namespace taiwa::turning
