// What the scene does to draw fast: the glass tray as a backdrop; while the
// camera moves, path lines one pixel wide, the tray, the axes' labels, the
// scale note and the tool hidden and, for a
// large plan, the paths drawn from decimated twins of their geometry
// (viz/path_lod.h). Each twin has a mapper of its own, so switching between
// full detail and the twin uploads nothing: both stay on the GPU.
#include "viz/path_lod.h"
#include "viz/scene.h"

#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>

#include <algorithm>
#include <cmath>
#include <vtkAxesActor.h>
#include <vtkTextActor.h>
#include <map>

namespace taiwa::viz {

// In the opaque pass (where VTK blends all the same: the tray's 12 % comes
// out as before) and at the far plane's depth, so that it hides nothing
// drawn before or after it. As translucent geometry it made VTK 9.1 run its
// order-independent translucency pass every frame (window-sized textures, a
// depth copy, a compositing pass): ~9 ms of a 10,000-segment frame's 42 on
// llvmpipe (docs/preview.md). Lines on or behind the far faces (the stock's
// three hidden edges) are no longer tinted by it.
void Scene::drawAsBackdrop(vtkActor* actor)
{
    actor->ForceOpaqueOn();
    actor->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Coincident::Impl", true,
                                                             "//VTK::Coincident::Impl\n  gl_FragDepth = 1.0;\n", false);
}

std::vector<vtkActor*> Scene::pathActors() const
{
    std::vector<vtkActor*> actors;
    for (const PathBlock& b : blocks_)
        for (vtkActor* a : {b.feeds.Get(), b.rapids.Get()}) actors.push_back(a);
    for (const StepActors& s : steps_)
        for (vtkActor* a : {s.feeds.Get(), s.rapids.Get()})
            if (a) actors.push_back(a);
    return actors;
}

void Scene::setMoving(bool moving)
{
    if (moving == moving_) return;
    moving_ = moving;
    if (tray_ && stock_) stock_->SetVisibility(!moving_);
    showWhenStill();
    if (plan_ && !lathe_) updateEmphasis();  // the widths; it ends with updateLod()
}

void Scene::updateLod()
{
    const bool lod = moving_ && pathSegments_ > kLodAbove;
    double tolerance = 0;
    if (lod) {
        const auto b = bounds();
        tolerance = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]) / 1000.0;
        // Twins made for other bounds (before an edit that moved them) go.
        if (tolerance != twinTolerance_) {
            vtkRenderWindow* window = renderer_->GetRenderWindow();
            for (auto& [actor, twin] : twins_) {
                if (actor->GetMapper() != twin.full) actor->SetMapper(twin.full);
                if (twin.lod && window) twin.lod->ReleaseGraphicsResources(window);
            }
            twins_.clear();
            twinTolerance_ = tolerance;
        }
    }
    // A merged block is decimated whatever its size, within its share of
    // the budget; a step's own actor from kLodMin segments.
    std::map<vtkActor*, std::size_t> share;
    for (const PathBlock& b : blocks_)
        for (vtkActor* a : {b.feeds.Get(), b.rapids.Get()}) share[a] = 0;
    for (vtkActor* actor : pathActors()) {
        auto found = twins_.find(actor);
        if (!lod) {
            if (found != twins_.end() && actor->GetMapper() != found->second.full) actor->SetMapper(found->second.full);
            continue;
        }
        if (found == twins_.end()) {
            auto* full = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
            vtkPolyData* data = full ? full->GetInput() : nullptr;
            Twin twin{full, nullptr};
            const std::size_t segments = data ? lineSegmentCount(data) : 0;
            const bool block = share.count(actor) != 0;
            if (segments > 0 && (block || segments >= kLodMin)) {
                const std::size_t budget =
                    block ? std::max<std::size_t>(1, kLodBudget * segments / std::max<std::size_t>(pathSegments_, 1)) : kLodBudget;
                auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
                mapper->SetInputData(decimateLinesWithin(data, tolerance, budget));
                mapper->ScalarVisibilityOff();
                mapper->StaticOn();
                twin.lod = mapper;
            }
            found = twins_.emplace(actor, std::move(twin)).first;
        }
        if (found->second.lod && actor->GetMapper() != found->second.lod) actor->SetMapper(found->second.lod);
    }
}

// While the camera moves: the axes' labels (three captions laid out again
// every frame), the scale note and the tool are left out; the axes' arrows
// and the stock's edges show the orientation. At 10,000 segments they were
// the difference between the moving scene and raw VTK (processor time a
// frame 89-91 % of raw with them, 95-98 % without; docs/preview.md).
void Scene::showWhenStill()
{
    if (axes_) axes_->SetAxisLabels(!moving_);
    if (scaleNote_) scaleNote_->SetVisibility(!moving_);
    if (tool_) tool_->SetVisibility(!moving_);
    for (auto& a : turretTools_) a->SetVisibility(!moving_);
}

std::size_t Scene::drawnPathSegments() const
{
    std::size_t n = 0;
    for (vtkActor* actor : pathActors()) {
        if (!actor->GetVisibility() || !renderer_->HasViewProp(actor)) continue;
        auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
        if (mapper) n += lineSegmentCount(mapper->GetInput());
    }
    return n;
}

}  // namespace taiwa::viz
