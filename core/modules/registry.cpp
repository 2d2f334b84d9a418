// The registration of the module kinds: one line in TAIWA_MODULES a module,
// naming the function `<name>Module()` its folder defines
// (core/modules/<name>/<name>_kind.cpp). See docs/modules.md.
#include "modules/registry.h"

#include <stdexcept>

#define TAIWA_MODULES(X) \
    X(m4)                \
    X(m2d)               \
    X(probe)             \
    X(turn)              \
    X(cp)                \
    X(holes)             \
    X(area)              \
    X(face)              \
    X(side)              \
    X(surface)

namespace taiwa {

#define TAIWA_DECLARE_MODULE(name) const ModuleKind& name##Module();
TAIWA_MODULES(TAIWA_DECLARE_MODULE)
#undef TAIWA_DECLARE_MODULE

const std::vector<const ModuleKind*>& moduleKinds()
{
#define TAIWA_LIST_MODULE(name) &name##Module(),
    static const std::vector<const ModuleKind*> kinds{TAIWA_MODULES(TAIWA_LIST_MODULE)};
#undef TAIWA_LIST_MODULE
    return kinds;
}

const ModuleKind* findModuleKind(std::string_view name)
{
    for (const ModuleKind* k : moduleKinds())
        if (name == k->name()) return k;
    return nullptr;
}

const ModuleKind& moduleKind(const ModuleInput& m)
{
    if (const ModuleKind* k = findModuleKind(m.name())) return *k;
    throw std::logic_error(std::string("no module kind named '") + m.name() + "'");
}

const ModuleKind& moduleKind(const Step& step)
{
    if (const ModuleKind* k = findModuleKind(step.module)) return *k;
    throw std::logic_error("step " + step.label() + " names no module kind ('" + step.module + "')");
}

ToolPath makeToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    return moduleKind(step).toolPath(step, tool, tech, params);
}

double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    return moduleKind(step).estimateMoves(step, tool, tech, params);
}

double estimateWork(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    const ModuleKind& kind = moduleKind(step);
    return kind.estimateMoves(step, tool, tech, params) * kind.workPerMove();
}

std::vector<int> orderSteps(const std::vector<Step>& steps)
{
    // Each step's door looked up once: the rules are asked of every pair of
    // a unit's steps, and orderStepsBy hands them the steps of `steps`.
    std::vector<const ModuleKind*> kinds;
    kinds.reserve(steps.size());
    for (const Step& s : steps) kinds.push_back(&moduleKind(s));
    const auto kindOf = [&](const Step& s) { return kinds[static_cast<std::size_t>(&s - steps.data())]; };
    const StepOrderRules rules{
        [&](const Step& later, const Step& earlier) { return kindOf(later)->stepWaitsFor(later, earlier); },
        [&](const Step& s) { return kindOf(s)->cutsBeforeOtherUnits(); }};
    return orderStepsBy(steps, rules);
}

std::vector<std::string> moduleNames()
{
    std::vector<std::string> names;
    for (const ModuleKind* k : moduleKinds()) names.emplace_back(k->name());
    return names;
}

}  // namespace taiwa
