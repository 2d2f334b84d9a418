// StockCache: the finished part as the fresh stock met with each unit's
// kept rectangle of lowered cells.
#include "sim/stock_cache.h"

#include "sim/material_removal.h"

#include <algorithm>
#include <functional>
#include <future>
#include <map>
#include <thread>

namespace taiwa::sim {

namespace {

void combine(std::size_t& h, std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); }

// The steps that cut (a path and a tool in the plan), as StockSimulation has them.
const Tool* cutter(const Plan& plan, const Step& s) { return s.path && s.tool ? plan.tool(s.tool->toolId) : nullptr; }

std::size_t hashCuts(const Plan& plan, const std::vector<int>& steps)
{
    std::size_t h = steps.size();
    for (const int k : steps) {
        const Step& s = plan.steps[static_cast<std::size_t>(k)];
        combine(h, s.path->moves.size());
        combine(h, static_cast<std::size_t>(s.tool->toolId));
        if (!s.path->moves.empty()) {
            combine(h, std::hash<double>{}(s.path->moves.back().end.x));
            combine(h, std::hash<double>{}(s.path->moves.back().end.y));
            combine(h, std::hash<double>{}(s.path->moves.back().end.z));
        }
    }
    return h;
}

}  // namespace

void StockCache::clear()
{
    stock_.reset();
    units_.clear();
}

bool StockCache::sameCuts(const Plan& a, const std::vector<int>& as, const Plan& b, const std::vector<int>& bs)
{
    if (as.size() != bs.size()) return false;
    for (std::size_t n = 0; n < as.size(); ++n) {
        const Step& sa = a.steps[static_cast<std::size_t>(as[n])];
        const Step& sb = b.steps[static_cast<std::size_t>(bs[n])];
        if (!(*sa.path == *sb.path) || !(*cutter(a, sa) == *cutter(b, sb))) return false;
    }
    return true;
}

StockCache::Patch StockCache::cutUnit(HeightField& scratch, const Plan& plan, const std::vector<int>& steps)
{
    for (const int k : steps) {
        const Step& s = plan.steps[static_cast<std::size_t>(k)];
        cut(scratch, *s.path, *cutter(plan, s));
    }
    // The rectangle of lowered cells (fresh stock is at 0), copied out and
    // put back to fresh stock for the next unit.
    const int nx = scratch.columns(), ny = scratch.rows();
    const float* z = scratch.data();
    int i0 = nx, i1 = -1, j0 = ny, j1 = -1;
    for (int j = 0; j < ny; ++j) {
        const float* row = z + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
        const auto first = std::find_if(row, row + nx, [](float v) { return v != 0.0f; });
        if (first == row + nx) continue;
        int last = nx - 1;
        while (row[last] == 0.0f) --last;
        i0 = std::min(i0, static_cast<int>(first - row));
        i1 = std::max(i1, last);
        j0 = std::min(j0, j);
        j1 = j;
    }
    Patch p;
    if (j1 < 0) return p;
    p.i0 = i0;
    p.j0 = j0;
    p.nx = i1 - i0 + 1;
    p.ny = j1 - j0 + 1;
    p.z.resize(static_cast<std::size_t>(p.nx) * static_cast<std::size_t>(p.ny));
    float* w = scratch.data();
    for (int j = 0; j < p.ny; ++j) {
        float* row = w + scratch.indexOf(i0, j0 + j);
        std::copy(row, row + p.nx, p.z.begin() + static_cast<std::ptrdiff_t>(j) * p.nx);
        std::fill(row, row + p.nx, 0.0f);
    }
    return p;
}

StockSimulation::Snapshot StockCache::finished(const std::shared_ptr<const Plan>& plan, StockGrid grid)
{
    ++generation_;
    counts_ = {};
    const Stock& stock = plan->mmJob.stock;
    if (!stock_ || !(*stock_ == stock) || !(grid_ == grid)) {
        units_.clear();
        stock_ = stock;
        grid_ = grid;
    }
    HeightField field(stock, HeightField::cellSizeFor(stock, grid.maxCells, grid.finest));

    // Each unit's cuts, in plan order.
    std::map<int, std::vector<int>> byUnit;
    for (std::size_t k = 0; k < plan->steps.size(); ++k)
        if (cutter(*plan, plan->steps[k])) byUnit[plan->steps[k].unit].push_back(static_cast<int>(k));

    std::vector<std::shared_ptr<const Patch>> patches;
    std::vector<std::vector<int>> missing;
    std::vector<std::size_t> missingHash;
    for (auto& [unit, steps] : byUnit) {
        const std::size_t h = hashCuts(*plan, steps);
        auto [first, last] = units_.equal_range(h);
        auto it = std::find_if(first, last, [&](auto& e) { return sameCuts(*e.second.plan, e.second.steps, *plan, steps); });
        if (it != last) {
            it->second.used = generation_;
            patches.push_back(it->second.patch);
            ++counts_.unitsReused;
        } else {
            missing.push_back(std::move(steps));
            missingHash.push_back(h);
        }
    }
    // The units not kept: cut on every core, each thread on its own fresh stock.
    std::vector<std::shared_ptr<const Patch>> cut(missing.size());
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, std::max<std::size_t>(missing.size(), 1));
    const auto work = [&](std::size_t first) {
        HeightField scratch = field;
        for (std::size_t m = first; m < missing.size(); m += threads)
            cut[m] = std::make_shared<const Patch>(cutUnit(scratch, *plan, missing[m]));
    };
    std::vector<std::future<void>> running;
    for (std::size_t t = 1; t < threads; ++t) running.push_back(std::async(std::launch::async, work, t));
    work(0);
    for (auto& r : running) r.get();
    for (std::size_t m = 0; m < missing.size(); ++m) {
        units_.emplace(missingHash[m], Entry{plan, std::move(missing[m]), cut[m], generation_});
        patches.push_back(cut[m]);
        ++counts_.unitsCut;
    }
    std::erase_if(units_, [this](const auto& e) { return e.second.used != generation_; });

    float* z = field.data();
    for (const auto& p : patches)
        for (int j = 0; j < p->ny; ++j) {
            float* row = z + field.indexOf(p->i0, p->j0 + j);
            const float* from = p->z.data() + static_cast<std::ptrdiff_t>(j) * p->nx;
            for (int i = 0; i < p->nx; ++i) row[i] = std::min(row[i], from[i]);
        }
    return std::make_shared<const HeightField>(std::move(field));
}

std::shared_ptr<StockSimulation> StockCache::simulation(const std::shared_ptr<const Plan>& plan, StockGrid grid)
{
    auto sim = std::make_shared<StockSimulation>(*plan, grid);
    sim->setFinished(finished(plan, grid));
    return sim;
}

}  // namespace taiwa::sim
