// The scene's in-place update for a new plan of the job it shows (an edit
// of a value): the merged blocks of units whose paths are unchanged keep
// their actors and GPU buffers, only the others are made
// (viz/scene_blocks.cpp); a step's own actors (made when it was selected)
// are kept while its path is unchanged (the path found by its moves,
// wherever the step now is in the machining order); the stock's edges and
// the axes stay while the stock does; the pockets' outlines are sampled
// anew only for the units whose outline changed; the stock surface, the
// tool and the highlight are made as a new scene makes them. The props
// are then put in the renderer in a new scene's order, so that what is
// drawn over what (lines on a floor at the same depth) is the same too.
#include "viz/scene.h"
#include "viz/scene_surface.h"

#include "sim/stock_simulation.h"
#include "viz/actors.h"
#include "viz/palette.h"
#include "viz/path_lod.h"
#include "viz/solids.h"

#include <vtkAxesActor.h>
#include <vtkMapper.h>
#include <vtkOutlineSource.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkTextActor.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

namespace taiwa::viz {

bool Scene::canUpdateInPlace(const Plan& next) const { return plan_ && !lathe_ && !next.mmJob.bar; }

void Scene::detach(vtkProp* prop)
{
    if (!prop) return;
    renderer_->GetViewProps()->RemoveItem(prop);
    prop->RemoveConsumer(renderer_);
}

void Scene::updateInPlace(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock)
{
    const std::shared_ptr<const Plan> old = std::move(plan_);
    plan_ = std::move(plan);
    lastUpdate_ = {true, 0, 0, 0};
    const int n = static_cast<int>(plan_->steps.size());
    simulation_.reset();
    if (stock && stock->stepCount() == n) simulation_ = std::move(stock);
    if (selected_ >= n) selected_ = -1;
    if (highlighted_.step >= n) highlighted_ = {};
    if (playhead_.step >= n) playhead_ = {};
    deviation_.reset();  // a map is of one plan

    vtkRenderWindow* window = renderer_->GetRenderWindow();
    if (window) window->MakeCurrent();
    std::vector<vtkSmartPointer<vtkProp>> dropped;  // their GPU resources freed below
    const auto drop = [&](auto& p) {
        if (p) dropped.emplace_back(p.Get());
        p = nullptr;
    };

    // What a new scene makes anew in any case: out of the renderer.
    for (auto* p : {&stock_, &cap_, &tool_, &highlight_, &partEdges_, &surface_, &probe_}) drop(*p);
    if (marker_) dropped.emplace_back(marker_.Get());  // a new scene shows no marker; markPoint may
    const Stock& s = plan_->mmJob.stock;
    if (!(old->mmJob.stock == s)) {
        drop(stockEdges_);
        auto outline = vtkSmartPointer<vtkOutlineSource>::New();
        outline->SetBounds(s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0);
        outline->Update();
        stockEdges_ = lineActor(outline->GetOutput(), palette::kStockEdges, 1.0);
    }
    if (const double axisLength = niceLength(std::max(s.width, s.length)); axisLength != axisLength_) {
        dropped.emplace_back(axes_.Get());
        dropped.emplace_back(scaleNote_.Get());
        makeAxes(axisLength);
    }
    partEdges_ = lineActor(pocketOutlines(plan_->steps, &outlines_), palette::kPartEdges, 1.5);
    partEdges_->SetVisibility(partShown_);
    surface_ = machinedSurfaces(plan_->steps, &surfaceTriangles_);
    probe_ = probeMarks();

    // The steps' path actors: kept where the path is the same.
    std::vector<StepActors> before = std::move(steps_);
    steps_.assign(plan_->steps.size(), {});
    std::unordered_multimap<std::size_t, int> byKey;
    for (int k = 0; k < static_cast<int>(before.size()); ++k)
        if (before[k].feeds) byKey.emplace(pathKey(*old->steps[static_cast<std::size_t>(k)].path), k);
    const auto take = [&](int from, int to) {
        steps_[static_cast<std::size_t>(to)] = std::move(before[static_cast<std::size_t>(from)]);
        before[static_cast<std::size_t>(from)] = {};
        ++lastUpdate_.pathsKept;
    };
    for (int k = 0; k < n; ++k) {
        const Step& step = plan_->steps[static_cast<std::size_t>(k)];
        if (!step.path) continue;
        // The same place in the order first, then anywhere.
        if (k < static_cast<int>(before.size()) && before[k].feeds && *old->steps[static_cast<std::size_t>(k)].path == *step.path) {
            take(k, k);
            continue;
        }
        const auto [first, last] = byKey.equal_range(pathKey(*step.path));
        for (auto it = first; it != last; ++it)
            if (before[static_cast<std::size_t>(it->second)].feeds && *old->steps[static_cast<std::size_t>(it->second)].path == *step.path) {
                take(it->second, k);
                break;
            }
    }
    for (StepActors& a : before) {
        drop(a.feeds);
        drop(a.rapids);
    }
    shownStep_ = -1;

    // The renderer's props in a new scene's order (scene.cpp setPlan).
    for (const auto& p : dropped) {
        if (auto* actor = vtkActor::SafeDownCast(p); actor && twins_.count(actor)) {
            for (vtkMapper* m : {twins_[actor].full.Get(), twins_[actor].lod.Get()})
                if (m && window) m->ReleaseGraphicsResources(window);
            twins_.erase(actor);
        }
        if (window) p->ReleaseGraphicsResources(window);
    }
    for (vtkProp* p : dropped) p->RemoveConsumer(renderer_);
    dropped.clear();
    vtkPropCollection* props = renderer_->GetViewProps();
    {
        std::vector<vtkProp*> all;
        props->InitTraversal();
        while (vtkProp* p = props->GetNextProp()) all.push_back(p);
        for (vtkProp* p : all) p->RemoveConsumer(renderer_);
        props->RemoveAllItems();
    }
    const auto add = [&](vtkProp* p) {
        props->AddItem(p);
        p->AddConsumer(renderer_);
    };
    add(stockEdges_);
    add(partEdges_);
    if (surface_) add(surface_);
    if (probe_) add(probe_);
    pathSegments_ = 0;
    // Blocks whose steps' paths are all unchanged keep their actors.
    mergePaths(std::move(blocks_), old.get());
    for (const PathBlock& b : blocks_) add(b.feeds);
    for (const PathBlock& b : blocks_) add(b.rapids);
    add(axes_);
    add(scaleNote_);

    updateStock();
    updateEmphasis();
    updateTool();
    updateHighlight();
}

}  // namespace taiwa::viz
