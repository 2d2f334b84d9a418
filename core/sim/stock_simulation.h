// The stock as it is before and after each step of a plan, simulated on a
// height field. Snapshots are computed on first request, from the nearest
// one already known, and kept, so stepping through the steps is fast.
#pragma once

#include "pipeline/pipeline.h"
#include "sim/height_field.h"

#include <cstddef>
#include <map>

namespace taiwa::sim {

class StockSimulation {
public:
    // Copies the stock, the steps' paths and their tools from the plan. The
    // grid has at most `maxCells` cells (HeightField::cellSizeFor).
    explicit StockSimulation(const Plan& plan, std::size_t maxCells = 500'000);

    int stepCount() const { return static_cast<int>(cuts_.size()); }
    const HeightField& initial() const { return initial_; }
    // The stock after steps 0..k (k in 0..stepCount()-1). A step without a
    // path or whose tool is not in the plan removes nothing.
    const HeightField& after(int k);
    // The stock before step k: after(k - 1), or the fresh stock for k = 0.
    const HeightField& before(int k);
    // After the last step: the finished part.
    const HeightField& finished() { return cuts_.empty() ? initial_ : after(stepCount() - 1); }

private:
    struct Cut {
        bool hasPath = false;
        ToolPath path;
        Tool tool;
    };
    HeightField initial_;
    std::vector<Cut> cuts_;
    std::map<int, HeightField> snapshots_;
};

}  // namespace taiwa::sim
