// Internal to decomposition: a step of a unit with its identity filled in
// (module, kind, number, machining type); the module decomposers add the
// geometry.
#pragma once

#include "model/step.h"

namespace taiwa::decompose {

inline Step makeStep(int unit, const char* module, StepKind kind, int number, MachiningType type)
{
    Step s;
    s.unit = unit;
    s.module = module;
    s.kind = kind;
    s.number = number;
    s.machiningType = type;
    return s;
}

}  // namespace taiwa::decompose
