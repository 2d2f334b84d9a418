// Turning process steps of one turned-profile unit (docs/turning.md
// "Turning steps"): the decomposition of the deformed profile into facing,
// centre drilling and drilling (a bore in a solid bar), roughing that leaves
// the finishing allowance in X and Z, finishing with nose-radius
// compensation, grooving where the finishing insert cannot reach (withdrawn
// along the surface normal at the end, seed 002), threading the rows that
// ask for a thread (G76) and parting off; the tool
// of each from the library with the reason; every path in the XZ half-plane.
// Inputs in mm, checked.
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/turned.h"
#include "model/turn_path.h"
#include "turning/profile_resolve.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace taiwa::turning {

// The step keys a unit's "skip" list and "tools" pins name.
const std::vector<std::string>& turnStepKeys();  // "facing", "centre-drill", "drill", "turn-rough", "turn-finish", "groove", "thread", "part"

struct TurnPlanRequest {
    int unit = 0;
    const DeformedProfile* deformed = nullptr;
    BarStock bar;
    double maxRpm = 4000.0;         // the machine's spindle limit
    double rapid = 10000.0;         // the machine's slowest rapid [mm/min]
    double maxFeed = 0.0;           // the machine's feed limit [mm/min] (threading: pitch × rpm); 0: none
    const std::vector<Tool>* library = nullptr;
    std::string material;
    ToolPins pins;                   // by turnStepKeys()
    std::map<std::string, CuttingOverride> cutting;  // the operator's S (m/min; drills rpm) and F [mm/rev], by turnStepKeys()
    std::set<std::string> skip;      // steps turned off
    TurningTechnology tech;
    bool facing = true;              // this unit faces the bar (the job's first turned unit)
    bool parting = true;             // this unit parts the part off (the job's last outer unit)
    double boreBefore = 0.0;         // diameter of the hole already there (the bar's bore)
    LengthUnit shown = LengthUnit::Millimetre;
};

struct TurnPlanResult {
    std::vector<Step> steps;              // in cutting order, tools chosen, paths made, minutes set
    std::vector<FieldProblem> problems;   // refusals on the unit's fields ("rows", "tools.groove")
    std::vector<std::string> notes;       // what the plan left or decided, for the sheet
};

TurnPlanResult planTurnedUnit(const TurnPlanRequest& request);

// The insert planTurnedUnit's finishing step takes (a pin, else the one
// reaching most, then the smallest nose radius); nullptr when the step is
// turned off or no insert serves.
const Tool* finishingInsert(const TurnPlanRequest& request);

}  // namespace taiwa::turning
