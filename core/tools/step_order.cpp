// Job-wide step order: a topological order of the steps that keeps the
// spindle on the same tool as long as any step ready to run uses it, and
// otherwise follows the units' machining order.
#include "tools/tool_choice.h"

#include <map>
#include <set>

namespace taiwa {

namespace {

// Rank of a step within its unit: the pilot hole, then roughing, then the
// finishing steps (which depend on all roughing, not on each other, except
// wall passes that follow their number).
int rank(const Step& s)
{
    switch (s.kind) {
    case StepKind::PilotHole: return 0;
    case StepKind::Roughing: return 1;
    default: return 2;
    }
}

bool dependsOn(const Step& later, const Step& earlier)
{
    if (later.unit != earlier.unit) return false;
    if (rank(earlier) < rank(later)) return true;
    // Roughing layers in order; wall passes (semi-finish, middle, final) in order.
    return later.kind == earlier.kind && (later.kind == StepKind::Roughing || later.kind == StepKind::WallFinishing) &&
           earlier.number < later.number;
}

int toolOf(const Step& s) { return s.tool ? s.tool->toolId : 0; }

}  // namespace

std::vector<int> orderSteps(const std::vector<Step>& steps)
{
    const int n = static_cast<int>(steps.size());
    std::map<int, std::vector<int>> byUnit;
    for (int i = 0; i < n; ++i) byUnit[steps[static_cast<std::size_t>(i)].unit].push_back(i);
    std::vector<int> waiting(static_cast<std::size_t>(n), 0);
    std::vector<std::vector<int>> next(static_cast<std::size_t>(n));
    for (const auto& [unit, members] : byUnit)
        for (const int a : members)
            for (const int b : members)
                if (dependsOn(steps[static_cast<std::size_t>(b)], steps[static_cast<std::size_t>(a)])) {
                    next[static_cast<std::size_t>(a)].push_back(b);
                    ++waiting[static_cast<std::size_t>(b)];
                }
    std::set<int> ready;
    std::map<int, std::set<int>> readyByTool;
    const auto release = [&](int i) {
        ready.insert(i);
        readyByTool[toolOf(steps[static_cast<std::size_t>(i)])].insert(i);
    };
    for (int i = 0; i < n; ++i)
        if (waiting[static_cast<std::size_t>(i)] == 0) release(i);
    std::vector<int> order;
    int current = -1;
    while (!ready.empty()) {
        auto same = readyByTool.find(current);
        const int i = same != readyByTool.end() && !same->second.empty() ? *same->second.begin() : *ready.begin();
        ready.erase(i);
        current = toolOf(steps[static_cast<std::size_t>(i)]);
        readyByTool[current].erase(i);
        order.push_back(i);
        for (const int j : next[static_cast<std::size_t>(i)])
            if (--waiting[static_cast<std::size_t>(j)] == 0) release(j);
    }
    return order;
}

}  // namespace taiwa
