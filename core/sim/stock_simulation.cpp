// Per-step snapshots of the simulated stock.
#include "sim/stock_simulation.h"

#include "sim/material_removal.h"

#include <iterator>
#include <stdexcept>
#include <string>

namespace taiwa::sim {

StockSimulation::StockSimulation(const Plan& plan, std::size_t maxCells)
    : initial_(plan.mmJob.stock, HeightField::cellSizeFor(plan.mmJob.stock, maxCells))
{
    cuts_.reserve(plan.steps.size());
    for (const Step& s : plan.steps) {
        const Tool* tool = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        if (s.path && tool)
            cuts_.push_back({true, *s.path, *tool});
        else
            cuts_.push_back({});
    }
}

const HeightField& StockSimulation::after(int k)
{
    if (k < 0 || k >= stepCount())
        throw std::out_of_range("StockSimulation::after: step " + std::to_string(k) + " of " + std::to_string(stepCount()));
    if (auto it = snapshots_.find(k); it != snapshots_.end()) return it->second;
    // Start from the latest snapshot before k.
    auto base = snapshots_.lower_bound(k);
    HeightField field = base == snapshots_.begin() ? initial_ : std::prev(base)->second;
    const int from = base == snapshots_.begin() ? 0 : std::prev(base)->first + 1;
    for (int i = from; i <= k; ++i) {
        if (cuts_[i].hasPath) cut(field, cuts_[i].path, cuts_[i].tool);
        if (i < k) snapshots_.emplace(i, field);
    }
    return snapshots_.emplace(k, std::move(field)).first->second;
}

const HeightField& StockSimulation::before(int k)
{
    if (k == 0) return initial_;
    return after(k - 1);
}

}  // namespace taiwa::sim
