// Module TURN's unit in the job file: read (unknown keys refused, every
// problem on its field) and written in canonical order. Called by its door
// (turn_kind.cpp).
#pragma once

#include "io/json_fields.h"
#include "modules/turn/turn.h"

#include <nlohmann/json.hpp>

namespace taiwa {

TurnUnit readTurnUnit(const io::ObjectFields& f);
void writeTurnUnit(const TurnUnit& t, nlohmann::ordered_json& u);

}  // namespace taiwa
