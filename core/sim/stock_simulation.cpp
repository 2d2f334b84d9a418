// Per-step snapshots of the simulated stock.
#include "sim/stock_simulation.h"

#include "sim/material_removal.h"
#include "sim/path_samples.h"

#include <algorithm>
#include <future>
#include <iterator>
#include <stdexcept>
#include <string>

namespace taiwa::sim {

StockSimulation::StockSimulation(const Plan& plan, StockGrid grid)
    : initial_(std::make_shared<const HeightField>(plan.mmJob.stock,
                                                   HeightField::cellSizeFor(plan.mmJob.stock, grid.maxCells, grid.finest))),
      stride_(std::max(1, (static_cast<int>(plan.steps.size()) + kCheckpoints - 1) / kCheckpoints))
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

void StockSimulation::cutSteps(HeightField& field, int from, int to) const
{
    for (int i = from; i < to; ++i)
        if (cuts_[i].hasPath) cut(field, cuts_[i].path, cuts_[i].tool);
}

const StockSimulation::Snapshot& StockSimulation::keep(int k, HeightField field)
{
    const Snapshot& kept =
        snapshots_.insert_or_assign(k, std::make_shared<const HeightField>(std::move(field))).first->second;
    if (!isCheckpoint(k)) {
        recent_.push_back(k);
        while (recent_.size() > kRecent) {
            snapshots_.erase(recent_.front());
            recent_.pop_front();
        }
    }
    return kept;
}

StockSimulation::Snapshot StockSimulation::after(int k)
{
    if (k < 0 || k >= stepCount())
        throw std::out_of_range("StockSimulation::after: step " + std::to_string(k) + " of " + std::to_string(stepCount()));
    if (auto it = snapshots_.find(k); it != snapshots_.end()) return it->second;
    // Start from the latest snapshot before k; keep the checkpoints passed.
    auto base = snapshots_.lower_bound(k);
    HeightField field = base == snapshots_.begin() ? *initial_ : *std::prev(base)->second;
    const int from = base == snapshots_.begin() ? 0 : std::prev(base)->first + 1;
    for (int i = from; i <= k; ++i) {
        cutSteps(field, i, i + 1);
        if (i < k && isCheckpoint(i)) snapshots_.insert_or_assign(i, std::make_shared<const HeightField>(field));
    }
    return keep(k, std::move(field));
}

StockSimulation::Snapshot StockSimulation::finished()
{
    const int n = stepCount();
    if (n == 0) return initial_;
    if (auto it = snapshots_.find(n - 1); it != snapshots_.end()) return it->second;
    if (n < 2 || !snapshots_.empty()) return after(n - 1);
    const int half = n / 2;
    auto secondHalf = std::async(std::launch::async, [this, half, n] {
        HeightField field = *initial_;
        cutSteps(field, half, n);
        return field;
    });
    HeightField field = *after(half - 1);  // on this thread, keeping its checkpoints
    field.meet(secondHalf.get());
    return keep(n - 1, std::move(field));
}

void StockSimulation::setFinished(Snapshot part)
{
    if (stepCount() == 0) return;  // the fresh stock
    if (!part || part->columns() != initial_->columns() || part->rows() != initial_->rows())
        throw std::logic_error("StockSimulation::setFinished: not a part on this simulation's grid");
    snapshots_.insert_or_assign(stepCount() - 1, std::move(part));
}

StockSimulation::Snapshot StockSimulation::afterMove(int k, int move)
{
    if (k < 0 || k >= stepCount())
        throw std::out_of_range("StockSimulation::afterMove: step " + std::to_string(k) + " of " + std::to_string(stepCount()));
    const Cut& c = cuts_[static_cast<std::size_t>(k)];
    const int last = c.hasPath ? static_cast<int>(c.path.moves.size()) - 1 : -1;
    move = std::clamp(move, -1, last);
    if (move < 0) return before(k);
    // From the last one asked for when it is earlier in this step, else
    // from the stock before the step. Each move cuts from where the one
    // before it left the tool: cutting the moves in runs is cutting them at once.
    const bool onward = playStep_ == k && played_ && playMove_ <= move;
    HeightField field = onward ? *played_ : *before(k);
    const int from = onward ? playMove_ + 1 : 0;
    if (from <= move) {
        ToolPath part{positionAfter(c.path, from - 1), {c.path.moves.begin() + from, c.path.moves.begin() + move + 1}};
        cut(field, part, c.tool);
    }
    playStep_ = k;
    playMove_ = move;
    played_ = std::make_shared<const HeightField>(std::move(field));
    return played_;
}

StockSimulation::Snapshot StockSimulation::before(int k)
{
    if (k == 0) return initial_;
    return after(k - 1);
}

}  // namespace taiwa::sim
