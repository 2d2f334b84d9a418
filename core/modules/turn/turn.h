// Module TURN: a turned profile (outer or inner) of a lathe job with its
// grinding-allowance table (spec "Turning", seed 001). Its input as the job
// keeps it is the profile table of core/turning/profile.h; the rest is
// behind its door (turn_kind.cpp). No machining steps yet: the deformed
// profile the lathe must cut is the plan's result (model/turned.h).
#pragma once

#include "model/module.h"
#include "model/turned.h"

namespace taiwa {

struct TurnUnit {
    static constexpr const char* kName = "TURN";
    turning::TurnedProfile profile;
    void convertLengths(const LengthMap& f) { profile.convertLengths(f); }
    friend bool operator==(const TurnUnit&, const TurnUnit&) = default;
};

}  // namespace taiwa
