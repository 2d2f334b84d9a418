// Internal to decomposition: a step of a unit with its identity filled in
// (module, kind, number, machining type); the module decomposers add the
// geometry.
#pragma once

#include "model/step.h"

namespace taiwa::decompose {

inline Step makeStep(int unit, const char* module, StepKind kind, int number, MachiningType type)
{
    return {.unit = unit, .module = module, .kind = kind, .number = number, .machiningType = type};
}

}  // namespace taiwa::decompose
