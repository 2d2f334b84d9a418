// The finished part of a plan simulated unit by unit and kept (issue 11): a
// value typed in one unit re-cuts only that unit. Every cut only lowers
// cells, so the finished part is the fresh stock met with each unit's cuts
// made alone, cell for cell the same as StockSimulation::finished(). Each
// unit's cuts are kept as the rectangle of cells they lowered, looked up by
// the cuts themselves (paths and tools, in plan order; not the unit's index).
// Only the last plan's units are kept. Not thread-safe: one caller at a time.
#pragma once

#include "model/plan.h"
#include "sim/height_field.h"
#include "sim/stock_simulation.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace taiwa::sim {

class StockCache {
public:
    // The finished part of `plan` on `grid`.
    StockSimulation::Snapshot finished(const std::shared_ptr<const Plan>& plan, StockGrid grid);
    // finished() and a simulation of the plan that starts from it.
    std::shared_ptr<StockSimulation> simulation(const std::shared_ptr<const Plan>& plan, StockGrid grid);

    struct Counts {
        int unitsCut = 0, unitsReused = 0;
    };
    const Counts& lastCounts() const { return counts_; }
    void clear();

private:
    // The cells one unit's cuts lowered: columns i0.., rows j0.., row-major.
    struct Patch {
        int i0 = 0, j0 = 0, nx = 0, ny = 0;
        std::vector<float> z;
    };
    struct Entry {
        std::shared_ptr<const Plan> plan;  // holds the paths and tools of `steps`
        std::vector<int> steps;
        std::shared_ptr<const Patch> patch;
        std::uint64_t used = 0;
    };
    static Patch cutUnit(HeightField& scratch, const Plan& plan, const std::vector<int>& steps);
    static bool sameCuts(const Plan& a, const std::vector<int>& as, const Plan& b, const std::vector<int>& bs);

    std::optional<Stock> stock_;
    StockGrid grid_;
    std::unordered_multimap<std::size_t, Entry> units_;  // by a hash of the cuts
    std::uint64_t generation_ = 0;
    Counts counts_;
};

}  // namespace taiwa::sim
