// Module TURN: a turned profile (outer or inner) of a lathe job with its
// grinding-allowance table (spec "Turning", seed 001). Its input as the job
// keeps it is the profile table of core/turning/profile.h; the rest is
// behind its door (turn_kind.cpp): the deformed profile is the plan's
// result (model/turned.h), the turning steps come from core/modules/turn/turn_plan.h.
#pragma once

#include "model/module.h"
#include "model/job.h"
#include "model/turned.h"

#include <string>
#include <vector>

namespace taiwa {

struct TurnUnit {
    static constexpr const char* kName = "TURN";
    static constexpr int kSinceFormatVersion = 3;  // the job format that brought it
    turning::TurnedProfile profile;
    ToolPins tools;                 // pinned tools by step key (turning::turnStepKeys())
    std::vector<std::string> skip;  // steps turned off, by step key
    void convertLengths(const LengthMap& f) { profile.convertLengths(f); }
    friend bool operator==(const TurnUnit&, const TurnUnit&) = default;
};

}  // namespace taiwa
