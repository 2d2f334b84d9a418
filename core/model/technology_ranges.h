// The ranges of the technology values (model/technology.h): the shipped
// table's reader (io/technology_file.cpp) and the job's overrides
// (job/job_check.cpp) refuse a value outside them, with the same words.
#pragma once

#include "model/translate_noop.h"

namespace taiwa {

struct TechnologyRange {
    const char* key;   // as the files write it: "alpha1"
    const char* name;  // as messages say it: "α1"
    double low, high;  // mm, or a factor for γ; low itself is refused
    const char* why;
};

// α1, α2, α3, β2, γ in the order of TechnologyOverrides.
constexpr TechnologyRange kTechnologyRanges[] = {
    {"alpha1", "α1", 0.0, 50.0, "the pilot hole stops α1 above the floor"},
    {"alpha2", "α2", 0.0, 20.0, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the wall allowance roughing leaves")},
    {"alpha3", "α3", 0.0, 20.0, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the wall allowance semi-finishing leaves")},
    {"beta2", "β2", 0.0, 20.0, TAIWA_TRANSLATE_NOOP("taiwa::msg", "the floor allowance roughing leaves")},
    {"gamma", "γ", 0.01, 2.0, "the depth of cut as a multiple of the tool diameter; a smaller one multiplies the layers"},
};

// A material's turning values (TurningTechnology), mm.
constexpr TechnologyRange kTurningRanges[] = {
    {"depthOfCut", "depth of cut", 0.0, 50.0, "the roughing passes' depth of cut per side"},
    {"allowanceX", "allowance X", 0.0, 5.0, "what roughing leaves on a diameter, per side"},
    {"allowanceZ", "allowance Z", 0.0, 5.0, "what roughing leaves on a face"},
    {"retract", "retract", 0.0, 20.0, "the lift off the material after a pass"},
    {"clearance", "clearance", 0.0, 100.0, "the clearance of approaches"},
    {"withdrawal", "withdrawal", 0.0, 20.0, "grooving's withdrawal along the surface normal"},
};

}  // namespace taiwa
