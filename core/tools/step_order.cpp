// Job-wide step order: a topological order of the steps that keeps the
// spindle on the same tool as long as any step ready to run uses it, and
// otherwise follows the units' machining order; a faced top comes first.
#include "tools/tool_choice.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <unordered_map>

namespace taiwa {

namespace {

// Rank of a step within its unit: the pilot hole, then roughing, then the
// finishing steps (which depend on all roughing, not on each other, except
// wall passes that follow their number); holes: centre drilling, drilling,
// then tapping, reaming or boring.
int rank(const Step& s)
{
    switch (s.kind) {
    case StepKind::PilotHole: return 0;
    case StepKind::Roughing: return 1;
    // Hole patterns: centre drilling, drilling, then tapping, reaming, boring.
    case StepKind::CentreDrilling: return 0;
    case StepKind::Drilling: return 1;
    default: return 2;
    }
}

bool dependsOn(const Step& later, const Step& earlier)
{
    if (later.unit != earlier.unit) return false;
    if (rank(earlier) < rank(later)) return true;
    // Roughing layers in order; wall passes (semi-finish, middle, final) in
    // order; face-milling layers, then the finishing pass, in order; side
    // milling's roughing before its finishing pass.
    return later.kind == earlier.kind &&
           (later.kind == StepKind::Roughing || later.kind == StepKind::WallFinishing ||
            later.kind == StepKind::FaceMilling || later.kind == StepKind::SideMilling) &&
           earlier.number < later.number;
}

int toolOf(const Step& s) { return s.tool ? s.tool->toolId : 0; }

}  // namespace

std::vector<int> orderSteps(const std::vector<Step>& steps)
{
    const int n = static_cast<int>(steps.size());
    const auto at = [&](int i) -> const Step& { return steps[static_cast<std::size_t>(i)]; };
    // The steps of each unit (units are few steps each: the pairs within a
    // unit are all looked at).
    int units = 0;
    for (const Step& s : steps) units = std::max(units, s.unit + 1);
    std::vector<std::vector<int>> byUnit(static_cast<std::size_t>(units));
    for (int i = 0; i < n; ++i) byUnit[static_cast<std::size_t>(at(i).unit)].push_back(i);
    std::vector<int> waiting(static_cast<std::size_t>(n), 0);
    std::vector<std::vector<int>> next(static_cast<std::size_t>(n));
    for (const auto& members : byUnit)
        for (const int a : members)
            for (const int b : members)
                if (dependsOn(at(b), at(a))) {
                    next[static_cast<std::size_t>(a)].push_back(b);
                    ++waiting[static_cast<std::size_t>(b)];
                }
    // The top is faced before anything else is cut: every other unit's steps
    // wait for the last face-milling step of each facing unit (module FACE;
    // the others' depths are measured from Z0 either way).
    for (const auto& members : byUnit) {
        int lastFace = -1;
        for (const int a : members)
            if (at(a).kind == StepKind::FaceMilling && (lastFace < 0 || at(a).number > at(lastFace).number)) lastFace = a;
        if (lastFace < 0) continue;
        for (int b = 0; b < n; ++b)
            if (at(b).unit != at(lastFace).unit && at(b).kind != StepKind::FaceMilling) {
                next[static_cast<std::size_t>(lastFace)].push_back(b);
                ++waiting[static_cast<std::size_t>(b)];
            }
    }
    // The ready steps, lowest index first: all of them, and those of each
    // tool. A step taken through one heap stays in the other until it comes
    // to the top there and is seen to be taken.
    using Heap = std::priority_queue<int, std::vector<int>, std::greater<>>;
    Heap ready;
    std::unordered_map<int, Heap> readyByTool;
    std::vector<bool> taken(static_cast<std::size_t>(n), false);
    const auto release = [&](int i) {
        ready.push(i);
        readyByTool[toolOf(at(i))].push(i);
    };
    const auto top = [&](Heap& h) {
        while (!h.empty() && taken[static_cast<std::size_t>(h.top())]) h.pop();
        return h.empty() ? -1 : h.top();
    };
    for (int i = 0; i < n; ++i)
        if (waiting[static_cast<std::size_t>(i)] == 0) release(i);
    std::vector<int> order;
    order.reserve(static_cast<std::size_t>(n));
    int current = -1;
    while (true) {
        int i = -1;
        if (const auto same = readyByTool.find(current); same != readyByTool.end()) i = top(same->second);
        if (i < 0) i = top(ready);
        if (i < 0) break;
        taken[static_cast<std::size_t>(i)] = true;
        current = toolOf(at(i));
        order.push_back(i);
        for (const int j : next[static_cast<std::size_t>(i)])
            if (--waiting[static_cast<std::size_t>(j)] == 0) release(j);
    }
    return order;
}

}  // namespace taiwa
