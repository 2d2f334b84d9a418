// The stock as it is before and after each step of a plan, simulated on a
// height field. Snapshots are computed on first request, from the nearest
// one already known. Kept are at most kCheckpoints evenly spaced ones (any
// step is then at most stepCount / kCheckpoints cuts away from one) and the
// kRecent last asked for, so stepping through the steps is fast and a
// 3,000-step job does not hold 3,000 copies of the stock. Snapshots are handed
// out as shared immutable values: one stays valid however many others are
// asked for later.
#pragma once

#include "model/plan.h"
#include "sim/height_field.h"

#include <cstddef>
#include <deque>
#include <map>
#include <memory>

namespace taiwa::sim {

// The grid of a simulation: cells of `finest` mm, coarser where the stock
// would need more than `maxCells` (HeightField::cellSizeFor).
struct StockGrid {
    double finest = 0.25;
    std::size_t maxCells = 500'000;
    friend bool operator==(const StockGrid&, const StockGrid&) = default;
};
// The station's choices, finest first; the second is the default
// (480,000 cells simulated in about 40 ms on two cores).
constexpr StockGrid kStockGrids[] = {{0.1, 4'000'000}, {0.25, 500'000}, {0.5, 200'000}};

class StockSimulation {
public:
    // Copies the stock, the steps' paths and their tools from the plan.
    explicit StockSimulation(const Plan& plan, StockGrid grid = {});

    static constexpr int kCheckpoints = 32;
    static constexpr std::size_t kRecent = 4;

    using Snapshot = std::shared_ptr<const HeightField>;

    int stepCount() const { return static_cast<int>(cuts_.size()); }
    const Snapshot& initial() const { return initial_; }
    // The stock after steps 0..k (k in 0..stepCount()-1). A step without a
    // path or whose tool is not in the plan removes nothing.
    Snapshot after(int k);
    // The stock before step k: after(k - 1), or the fresh stock for k = 0.
    Snapshot before(int k);
    // After the last step: the finished part. Asked first, the two halves
    // of the steps are cut on two threads and the results met (every cut
    // only lowers cells, so the order of the cuts does not matter: the
    // result is the same, cell for cell, as cutting them in order).
    Snapshot finished();
    // The finished part worked out elsewhere (sim/stock_cache.h), which must
    // be finished()'s, cell for cell: finished() then returns it.
    void setFinished(Snapshot part);
    // The stock after moves 0..move of step k (move -1: before the step; a
    // move past the last: after it): the material coming off block by
    // block. The last one asked for is kept, so that asking for a later
    // move of the same step cuts only the moves between.
    Snapshot afterMove(int k, int move);
    // How many snapshots are kept now (at most kCheckpoints + kRecent).
    std::size_t snapshotCount() const { return snapshots_.size(); }

private:
    struct Cut {
        bool hasPath = false;
        ToolPath path;
        Tool tool;
    };
    bool isCheckpoint(int k) const { return (k + 1) % stride_ == 0; }
    const Snapshot& keep(int k, HeightField field);
    void cutSteps(HeightField& field, int from, int to) const;  // steps from..to-1

    Snapshot initial_;
    std::vector<Cut> cuts_;
    int stride_ = 1;
    std::map<int, Snapshot> snapshots_;
    int playStep_ = -1, playMove_ = -1;  // the last afterMove
    Snapshot played_;
    std::deque<int> recent_;  // snapshots that are not checkpoints, oldest first
};

}  // namespace taiwa::sim
