// A milling plan's paths drawn merged in blocks of units: each block is one
// point list with a feeds and a rapids actor (viz::makeMergedPaths) for the
// steps of a run of consecutive units (at most Scene::kMaxBlocks blocks).
// An edit of one unit makes anew only its block; the others keep their
// actors, their GPU buffers and their decimated twins. Blocks follow units
// rather than runs of the machining order because a unit's steps lie
// scattered through that order (each tool's steps of every unit together):
// a run of steps would hold a few of them in several blocks.
#include "viz/actors.h"
#include "viz/palette.h"
#include "viz/path_lod.h"
#include "viz/scene.h"

#include <vtkMapper.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <functional>
#include <unordered_map>

namespace taiwa::viz {

namespace {

std::size_t blockKey(const Plan& plan, const std::vector<int>& steps)
{
    std::size_t h = steps.size();
    for (int k : steps) h ^= pathKey(*plan.steps[static_cast<std::size_t>(k)].path) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
}

// The same paths, one for one, in the same order.
bool samePaths(const Plan& a, const std::vector<int>& as, const Plan& b, const std::vector<int>& bs)
{
    if (as.size() != bs.size()) return false;
    for (std::size_t i = 0; i < as.size(); ++i)
        if (!(*a.steps[static_cast<std::size_t>(as[i])].path == *b.steps[static_cast<std::size_t>(bs[i])].path)) return false;
    return true;
}

}  // namespace

void Scene::mergePaths(std::vector<PathBlock> kept, const Plan* old)
{
    const std::vector<Step>& steps = plan_->steps;
    int units = 1;
    for (const Step& s : steps) units = std::max(units, s.unit + 1);
    const int perBlock = (units + kMaxBlocks - 1) / kMaxBlocks;
    std::vector<std::vector<int>> groups(static_cast<std::size_t>((units + perBlock - 1) / perBlock));
    for (int k = 0; k < static_cast<int>(steps.size()); ++k)
        if (steps[static_cast<std::size_t>(k)].path)
            groups[static_cast<std::size_t>(std::clamp(steps[static_cast<std::size_t>(k)].unit, 0, units - 1) / perBlock)].push_back(k);

    std::unordered_multimap<std::size_t, std::size_t> byKey;
    for (std::size_t i = 0; i < kept.size(); ++i) byKey.emplace(kept[i].key, i);
    blocks_.clear();
    blockOf_.assign(steps.size(), {-1, -1});
    pathSegments_ = 0;
    for (std::vector<int>& group : groups) {
        if (group.empty()) continue;
        const std::size_t key = blockKey(*plan_, group);
        PathBlock block;
        const auto [first, last] = byKey.equal_range(key);
        for (auto it = first; it != last && old; ++it) {
            PathBlock& candidate = kept[it->second];
            if (candidate.feeds && samePaths(*old, candidate.steps, *plan_, group)) {
                block = std::move(candidate);
                candidate = {};
                ++lastUpdate_.blocksKept;
                break;
            }
        }
        if (!block.feeds) {
            std::vector<const ToolPath*> paths;
            paths.reserve(group.size());
            for (int k : group) paths.push_back(&*steps[static_cast<std::size_t>(k)].path);
            block.paths = makeMergedPaths(paths);
            block.feeds = lineActor(block.paths.feeds, palette::kFeed, 2.0);
            block.rapids = lineActor(block.paths.rapids, palette::kRapid, 1.0);
            ++lastUpdate_.blocksMade;
        }
        block.key = key;
        block.steps = std::move(group);
        const int b = static_cast<int>(blocks_.size());
        for (std::size_t i = 0; i < block.steps.size(); ++i)
            blockOf_[static_cast<std::size_t>(block.steps[i])] = {b, static_cast<int>(i)};
        pathSegments_ += lineSegmentCount(block.paths.feeds) + lineSegmentCount(block.paths.rapids);
        blocks_.push_back(std::move(block));
    }
    for (PathBlock& block : kept)
        if (block.feeds) releaseBlock(block);
}

void Scene::releaseBlock(PathBlock& block)
{
    vtkRenderWindow* window = renderer_->GetRenderWindow();
    for (vtkActor* actor : {block.feeds.Get(), block.rapids.Get()}) {
        if (!actor) continue;
        if (auto twin = twins_.find(actor); twin != twins_.end()) {
            for (vtkMapper* m : {twin->second.full.Get(), twin->second.lod.Get()})
                if (m && window) m->ReleaseGraphicsResources(window);
            twins_.erase(twin);
        }
        if (window) actor->ReleaseGraphicsResources(window);
    }
    block = {};
}

std::vector<std::array<const vtkActor*, 2>> Scene::pathBlockActors() const
{
    std::vector<std::array<const vtkActor*, 2>> actors;
    for (const PathBlock& b : blocks_) actors.push_back({b.feeds.Get(), b.rapids.Get()});
    return actors;
}

std::vector<std::vector<int>> Scene::pathBlockSteps() const
{
    std::vector<std::vector<int>> steps;
    for (const PathBlock& b : blocks_) steps.push_back(b.steps);
    return steps;
}

}  // namespace taiwa::viz
