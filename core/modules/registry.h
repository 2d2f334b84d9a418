// The module kinds this program knows, by name: the job reader, the input
// checks, the planning and the station find a module's door here.
#pragma once

#include "modules/module_kind.h"
#include "tools/step_order.h"

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

// A step's module kind, by the name it carries (Step::module); throws
// std::logic_error for a step of no known module.
const ModuleKind& moduleKind(const Step& step);
// The tool path of a milling step and its move estimate, through its
// module's door (ModuleKind::toolPath, estimateMoves).
ToolPath makeToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);
double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);
// What the step's moves cost, in moves of a pocket: estimateMoves weighed by
// its door's workPerMove (what the job's budget sums).
double estimateWork(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);
// The job-wide step order (tools/step_order.h) with what each step's module
// says of the order of its unit's steps.
std::vector<int> orderSteps(const std::vector<Step>& steps);

}  // namespace taiwa
