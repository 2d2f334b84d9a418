// The job-wide step order that saves tool changes without breaking the
// order each module sets for its own steps, and tool life accounting along
// that order.
#pragma once

#include "model/step.h"
#include "model/tool.h"

#include <functional>
#include <string>
#include <vector>

namespace taiwa {

// What the order must keep, as the modules' doors say it
// (ModuleKind::stepWaitsFor, cutsBeforeOtherUnits).
struct StepOrderRules {
    // True when `later` must wait for `earlier`; both are steps of one unit.
    std::function<bool(const Step& later, const Step& earlier)> waitsFor;
    // True for a step of a unit whose steps come before every other unit's
    // (the top faced first): the other units' steps wait for its last step.
    std::function<bool(const Step&)> cutsFirst;
};

// Job-wide order: a permutation of indices into `steps` (the rules are
// asked of elements of `steps` itself), a topological order
// that keeps the spindle on the same tool as long as any step ready to run
// uses it and otherwise follows the steps' order (the units' machining
// order).
std::vector<int> orderStepsBy(const std::vector<Step>& steps, const StepOrderRules& rules);

// Tool life: walks the ordered steps adding each step's minutes to its tool's
// used life; where a step would exceed the remaining life, returns a note
// ("T5 reaches its life in step ...: change it before ...").
struct ToolLifeNote {
    int stepIndex = 0;  // index into the ordered steps
    int toolId = 0;
    std::string message;
};
std::vector<ToolLifeNote> planToolLife(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library);

}  // namespace taiwa
