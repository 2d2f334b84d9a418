// Job-wide step order: a topological order of the steps that keeps the
// spindle on the same tool as long as any step ready to run uses it, and
// otherwise follows the units' machining order; what each unit's module
// says of its own steps' order is kept (tools/step_order.h).
#include "tools/step_order.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <unordered_map>

namespace taiwa {

namespace {

int toolOf(const Step& s) { return s.tool ? s.tool->toolId : 0; }

}  // namespace

std::vector<int> orderStepsBy(const std::vector<Step>& steps, const StepOrderRules& rules)
{
    const int n = static_cast<int>(steps.size());
    const auto at = [&](int i) -> const Step& { return steps[static_cast<std::size_t>(i)]; };
    // The steps of each unit (units are few steps each: the pairs within a
    // unit are all looked at).
    // Grouped by counting, in flat arrays: a job of 100,000 units has some
    // 400,000 steps, and a vector of its own for each would be a million
    // small blocks at the planner's peak.
    int units = 0;
    for (const Step& s : steps) units = std::max(units, s.unit + 1);
    std::vector<int> unitStart(static_cast<std::size_t>(units) + 1, 0), members(static_cast<std::size_t>(n));
    for (const Step& s : steps) ++unitStart[static_cast<std::size_t>(s.unit) + 1];
    for (std::size_t u = 0; u < static_cast<std::size_t>(units); ++u) unitStart[u + 1] += unitStart[u];
    {
        std::vector<int> filled(unitStart.begin(), unitStart.end() - 1);
        for (int i = 0; i < n; ++i) members[static_cast<std::size_t>(filled[static_cast<std::size_t>(at(i).unit)]++)] = i;
    }
    const auto unitMembers = [&](std::size_t u) {
        return std::pair{members.begin() + unitStart[u], members.begin() + unitStart[u + 1]};
    };
    // The edges a -> b (b waits for a), walked twice: to count each step's
    // followers, then to put them in one array (no list of the edges: a
    // large job has over a million).
    const auto forEachEdge = [&](auto&& edge) {
        for (std::size_t u = 0; u < static_cast<std::size_t>(units); ++u) {
            const auto [first, last] = unitMembers(u);
            for (auto a = first; a != last; ++a)
                for (auto b = first; b != last; ++b)
                    if (*a != *b && rules.waitsFor(at(*b), at(*a))) edge(*a, *b);
        }
        // A unit cut before the others (the top faced first, module FACE;
        // the others' depths are measured from Z0 either way): every other
        // unit's steps wait for its last step, those of units cut first
        // excepted.
        for (std::size_t u = 0; u < static_cast<std::size_t>(units); ++u) {
            const auto [first, end] = unitMembers(u);
            int last = -1;
            for (auto a = first; a != end; ++a)
                if (rules.cutsFirst(at(*a)) && (last < 0 || at(*a).number > at(last).number)) last = *a;
            if (last < 0) continue;
            for (int b = 0; b < n; ++b)
                if (at(b).unit != at(last).unit && !rules.cutsFirst(at(b))) edge(last, b);
        }
    };
    std::vector<int> waiting(static_cast<std::size_t>(n), 0), nextStart(static_cast<std::size_t>(n) + 1, 0);
    forEachEdge([&](int a, int b) {
        ++nextStart[static_cast<std::size_t>(a) + 1];
        ++waiting[static_cast<std::size_t>(b)];
    });
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) nextStart[i + 1] += nextStart[i];
    std::vector<int> next(static_cast<std::size_t>(nextStart.back()));
    {
        std::vector<int> filled(nextStart.begin(), nextStart.end() - 1);
        forEachEdge([&](int a, int b) { next[static_cast<std::size_t>(filled[static_cast<std::size_t>(a)]++)] = b; });
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
        for (int e = nextStart[static_cast<std::size_t>(i)]; e < nextStart[static_cast<std::size_t>(i) + 1]; ++e)
            if (const int j = next[static_cast<std::size_t>(e)]; --waiting[static_cast<std::size_t>(j)] == 0) release(j);
    }
    return order;
}

}  // namespace taiwa
