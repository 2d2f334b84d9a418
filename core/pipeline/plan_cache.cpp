// PlanCache: each unit's module result and each step's path kept from one
// plan to the next, looked up by everything they depend on.
#include "pipeline/plan_cache.h"

#include <functional>
#include <iterator>
#include <utility>

namespace taiwa {

namespace {

void combine(std::size_t& h, std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); }

}  // namespace

Plan PlanCache::plan(CheckedJob checked, const std::vector<Tool>& library, const PlanOptions& options)
{
    return planJob(std::move(checked), library, options, this);
}

void PlanCache::clear()
{
    unitContext_.reset();
    pathContext_.reset();
    units_.clear();
    paths_.clear();
}

void PlanCache::begin(const Plan& plan, const std::vector<Tool>& library, const PathParameters& params)
{
    ++generation_;
    counts_ = {};
    UnitContext units{plan.technology,    library,           plan.mmJob.material, plan.mmJob.machine,
                      plan.job.workOffset, plan.job.lengthUnit, plan.mmJob.stock,  plan.mmJob.bar};
    if (unitContext_ != units) {
        units_.clear();
        unitContext_ = std::move(units);
    }
    PathContext paths{plan.technology, library, params, plan.mmJob.material, plan.mmJob.machine};
    if (pathContext_ != paths) {
        paths_.clear();
        pathContext_ = std::move(paths);
    }
}

const UnitPlan& PlanCache::unit(const Plan& plan, int u, const std::vector<Tool>& /*library*/,
                                const std::function<UnitPlan()>& compute)
{
    const auto i = static_cast<std::size_t>(u);
    UnitKey key{u, plan.mmJob.units[i], plan.job.units[i].name, {}};
    if (plan.mmJob.bar) key.others = plan.mmJob.units;
    if (auto it = units_.find(u); it != units_.end() && it->second.key == key) {
        it->second.used = generation_;
        ++counts_.unitsReused;
        return it->second.plan;
    }
    ++counts_.unitsPlanned;
    UnitEntry& e = units_[u];
    e = {std::move(key), compute(), generation_};
    return e.plan;
}

Step PlanCache::pathKey(const Step& step)
{
    Step key = step;
    key.unit = 0;  // no path reads it: a unit moved in the job keeps its paths
    key.path.reset();
    key.minutes.reset();
    key.machineMinutes.reset();
    return key;
}

std::size_t PlanCache::hashStep(const Step& key)
{
    const MillingGeometry& g = millingOf(key);
    std::size_t h = std::hash<std::string>{}(key.module);
    combine(h, static_cast<std::size_t>(key.kind));
    combine(h, static_cast<std::size_t>(key.number));
    combine(h, std::hash<double>{}(g.cutDepth));
    combine(h, std::hash<double>{}(g.startDepth));
    combine(h, std::hash<double>{}(g.position.x));
    combine(h, std::hash<double>{}(g.position.y));
    if (g.outline) combine(h, std::hash<double>{}(g.outline->corners[0].x + 3.0 * g.outline->corners[2].y));
    if (key.tool) combine(h, static_cast<std::size_t>(key.tool->toolId));
    return h;
}

const StepPath* PlanCache::findPath(const Step& step)
{
    const Step key = pathKey(step);
    auto [first, last] = paths_.equal_range(hashStep(key));
    for (auto it = first; it != last; ++it)
        if (it->second.step == key) {
            it->second.used = generation_;
            ++counts_.pathsReused;
            return &it->second.path;
        }
    return nullptr;
}

void PlanCache::keepPath(const Step& step, StepPath path)
{
    ++counts_.pathsComputed;
    Step key = pathKey(step);
    const std::size_t h = hashStep(key);
    paths_.emplace(h, PathEntry{std::move(key), std::move(path), generation_});
}

void PlanCache::end()
{
    std::erase_if(units_, [this](const auto& e) { return e.second.used != generation_; });
    std::erase_if(paths_, [this](const auto& e) { return e.second.used != generation_; });
}

}  // namespace taiwa
