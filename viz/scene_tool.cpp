// The tool in the preview scene (viz::Scene): where the selected path
// starts or where the NC block the operator is on leaves it; a milling
// cutter as its solid, a lathe tool as its section in the half-section,
// and a two-path lathe's turrets each with its own tool (setTurretTools).
#include "viz/scene.h"

#include "model/turn_path.h"
#include "model/turned_geometry.h"
#include "viz/actors.h"
#include "viz/palette.h"
#include "viz/solids.h"

#include <vtkProperty.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace taiwa::viz {

void Scene::updateTool()
{
    if (tool_) renderer_->RemoveActor(tool_);
    tool_ = nullptr;
    toolAt_.reset();
    for (auto& a : turretTools_) renderer_->RemoveActor(a);
    turretTools_.clear();
    turretAt_.clear();
    if (!plan_) return;
    const auto& steps = plan_->steps;
    const int nSteps = static_cast<int>(steps.size());
    // On an NC block: that block's step, the tool where the block leaves it.
    const bool onBlock = highlighted_.step >= 0 && highlighted_.step < nSteps;
    int k = onBlock ? highlighted_.step : selected_;
    if (k < 0) {  // all steps: the tool of the first step that has a path
        const auto it = std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.path && s.tool; });
        k = it == steps.end() ? -1 : static_cast<int>(it - steps.begin());
    }
    if (k < 0) return;
    const Step& step = steps[static_cast<std::size_t>(k)];
    const Tool* tool = step.tool ? plan_->tool(step.tool->toolId) : nullptr;
    if (tool && turnOf(step) && lathe_ && k == selected_) {
        // In the section: the insert (or blade, or drill) at the path's
        // start, or where the NC block the operator is on leaves it.
        const TurnPath& p = turnOf(step)->path;
        if (updateTurretTools(*tool, *turnOf(step), onBlock ? highlighted_.move : -1)) return;
        turning::ZR at = p.start;
        if (onBlock && highlighted_.move >= 0 && highlighted_.move < static_cast<int>(p.moves.size()))
            at = p.moves[static_cast<std::size_t>(highlighted_.move)].end;
        std::vector<turning::ZR> outline = latheToolOutline(*tool, *turnOf(step));
        if (outline.empty()) return;
        for (auto& q : outline) q = q + at;
        tool_ = actorFor(sectionFace(outline, -0.1), palette::kTool);
        tool_->GetProperty()->SetAmbient(0.6);
        tool_->GetProperty()->SetDiffuse(0.4);
        toolAt_ = Point3{at.z, 0.0, at.r};  // VTK's X along the spindle, the radius up
        showWhenStill();
        renderer_->AddActor(tool_);
        return;
    }
    if (!tool || !step.path) return;
    Point3 at = step.path->start;
    // A drilling cycle's end is the hole's bottom: the tool is drawn there.
    if (onBlock && highlighted_.move >= 0 && highlighted_.move < static_cast<int>(step.path->moves.size()))
        at = step.path->moves[static_cast<std::size_t>(highlighted_.move)].end;
    tool_ = actorFor(toolSolid(*tool), palette::kTool);
    tool_->SetPosition(at.x, at.y, at.z);
    toolAt_ = at;
    tool_->GetProperty()->SetAmbient(0.35);
    tool_->GetProperty()->SetDiffuse(0.65);
    showWhenStill();
    renderer_->AddActor(tool_);
}

void Scene::setTurretTools(std::optional<TurretTools> tools)
{
    turrets_ = std::move(tools);
    updateTool();
}

bool Scene::updateTurretTools(const Tool& tool, const TurnStep& step, int move)
{
    if (!turrets_ || turrets_->step != selected_) return false;
    const ToolPlaces& places = turrets_->places;
    const std::vector<turning::ZR>& at =
        move >= 0 && move < static_cast<int>(places.afterMove.size()) ? places.afterMove[static_cast<std::size_t>(move)] : places.start;
    const std::vector<turning::ZR> outline = latheToolOutline(tool, step);
    if (outline.empty() || at.size() != turrets_->side.size()) return false;
    static constexpr Rgb kColours[] = {palette::kTool, palette::kTool2, palette::kTool3};
    for (std::size_t p = 0; p < at.size() && p < std::size(kColours); ++p) {
        // The path's tip on its side of the axis, the insert mirrored with it.
        const double side = turrets_->side[p] < 0 ? -1.0 : 1.0;
        std::vector<turning::ZR> drawn = outline;
        for (auto& q : drawn) q = turning::ZR{at[p].z + q.z, side * (at[p].r + q.r)};
        auto actor = actorFor(sectionFace(drawn, -0.1), kColours[p]);
        actor->GetProperty()->SetAmbient(0.6);
        actor->GetProperty()->SetDiffuse(0.4);
        const Point3 tip{at[p].z, 0.0, side * at[p].r};  // VTK's X along the spindle, the radius up
        turretAt_.push_back(tip);
        if (p == 0) {
            tool_ = actor;
            toolAt_ = tip;
        } else {
            turretTools_.push_back(actor);
        }
    }
    showWhenStill();
    renderer_->AddActor(tool_);
    for (auto& a : turretTools_) renderer_->AddActor(a);
    return true;
}

}  // namespace taiwa::viz
