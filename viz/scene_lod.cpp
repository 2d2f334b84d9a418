// The scene while the camera moves: path lines one pixel wide, the glass
// tray hidden and, for a
// large plan, the paths drawn from decimated twins of their geometry
// (viz/path_lod.h). Each twin has a mapper of its own, so switching between
// full detail and the twin uploads nothing: both stay on the GPU.
#include "viz/path_lod.h"
#include "viz/scene.h"

#include <vtkPolyDataMapper.h>

#include <cmath>

namespace taiwa::viz {

std::vector<vtkActor*> Scene::pathActors() const
{
    std::vector<vtkActor*> actors;
    for (vtkActor* a : {allFeeds_.Get(), allRapids_.Get()})
        if (a) actors.push_back(a);
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
    if (plan_ && !lathe_) updateEmphasis();  // the widths; it ends with updateLod()
}

void Scene::updateLod()
{
    const bool lod = moving_ && pathSegments_ > kLodAbove;
    double tolerance = 0;
    if (lod) {
        const auto b = bounds();
        tolerance = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]) / 1000.0;
    }
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
            if (data && lineSegmentCount(data) >= kLodMin) {
                auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
                mapper->SetInputData(decimateLinesWithin(data, tolerance, kLodBudget));
                mapper->ScalarVisibilityOff();
                mapper->StaticOn();
                twin.lod = mapper;
            }
            found = twins_.emplace(actor, std::move(twin)).first;
        }
        if (found->second.lod && actor->GetMapper() != found->second.lod) actor->SetMapper(found->second.lod);
    }
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
