// The module kinds this program knows, by name: the job reader, the input
// checks, the planning and the station find a module's door here.
#pragma once

#include "modules/module_kind.h"

#include <string_view>
#include <vector>

namespace taiwa {

// Every kind, in the palette's order.
const std::vector<const ModuleKind*>& moduleKinds();
// The kind named `name` ("M4"); nullptr when unknown.
const ModuleKind* findModuleKind(std::string_view name);
// The kind of a module input; throws std::logic_error for an empty input.
const ModuleKind& moduleKind(const ModuleInput& m);
// The names of every kind ("M4", "M2D"), for messages.
std::vector<std::string> moduleNames();

}  // namespace taiwa
