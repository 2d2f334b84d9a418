// The preview scene: actors for the paths, the highlight and the axes,
// rebuilt or restyled as the selection changes (the stock:
// scene_stock.cpp; a lathe job: scene_lathe.cpp; the tool: scene_tool.cpp).
#include "viz/scene.h"

#include "sim/stock_simulation.h"
#include "sim/turned_stock.h"
#include "viz/actors.h"
#include "viz/camera_presets.h"
#include "viz/palette.h"
#include "viz/path_lod.h"
#include "viz/scene_surface.h"
#include "viz/solids.h"
#include "verify/deviation.h"

#include <vtkAxesActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkCoordinate.h>
#include <vtkLight.h>
#include <vtkMatrix4x4.h>
#include <vtkOutlineSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace taiwa::viz {

namespace {

void setColour(vtkActor* a, Rgb c) { a->GetProperty()->SetColor(c.red(), c.green(), c.blue()); }


}  // namespace

void Scene::setScaleNoteText(std::function<std::string(int mm)> text, std::string fontFile)
{
    scaleNoteText_ = std::move(text);
    scaleNoteFont_ = std::move(fontFile);
    if (scaleNote_) writeScaleNote();
}

void Scene::writeScaleNote()
{
    scaleNote_->SetInput(scaleNoteText_(static_cast<int>(axisLength_)).c_str());
    if (!scaleNoteFont_.empty()) {
        scaleNote_->GetTextProperty()->SetFontFamily(VTK_FONT_FILE);
        scaleNote_->GetTextProperty()->SetFontFile(scaleNoteFont_.c_str());
    }
}

std::string Scene::scaleNote() const
{
    const char* text = scaleNote_ ? scaleNote_->GetInput() : nullptr;
    return text ? text : "";
}

Scene::Scene() : renderer_(vtkSmartPointer<vtkRenderer>::New())
{
    renderer_->SetBackground(palette::kBackground.red(), palette::kBackground.green(), palette::kBackground.blue());
    // A headlight alone lights the three faces of a block in iso view
    // alike (each at the same angle to the view): one flat grey. A key
    // light from above and to the left of the viewer, with a weaker
    // headlight, shades top, left and right faces apart in every view and
    // still lights a face seen head-on at full strength.
    renderer_->AutomaticLightCreationOff();
    auto head = vtkSmartPointer<vtkLight>::New();
    head->SetLightTypeToHeadlight();
    head->SetIntensity(0.45);
    auto key = vtkSmartPointer<vtkLight>::New();
    key->SetLightTypeToCameraLight();  // camera at (0, 0, 1) looking at the origin, Y up
    key->SetPosition(-0.5, 0.8, 1.0);
    key->SetFocalPoint(0.0, 0.0, 0.0);
    key->SetIntensity(0.6);
    renderer_->AddLight(head);
    renderer_->AddLight(key);
    // Before each frame, the stock surface lit for the camera.
    auto relight = vtkSmartPointer<vtkCallbackCommand>::New();
    relight->SetClientData(this);
    relight->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
        auto* scene = static_cast<Scene*>(self);
        scene->stockLight_.update(scene->renderer_);
    });
    lightObserver_ = renderer_->AddObserver(vtkCommand::StartEvent, relight);
}

// The renderer may outlive the scene in a window that still draws it.
Scene::~Scene() { renderer_->RemoveObserver(lightObserver_); }

void Scene::clear()
{
    // The steps' own actors shown before (out of the renderer
    // now) may hold GPU buffers.
    if (vtkRenderWindow* window = renderer_->GetRenderWindow())
        for (const StepActors& a : steps_)
            for (vtkActor* actor : {a.feeds.Get(), a.rapids.Get()})
                if (actor) actor->ReleaseGraphicsResources(window);
    renderer_->RemoveAllViewProps();
    steps_.clear();
    blocks_.clear();
    blockOf_.clear();
    outlines_ = {};
    shownStep_ = -1;
    twins_.clear();
    pathSegments_ = 0;
    simulation_.reset();
    stock_ = stockEdges_ = partEdges_ = tool_ = highlight_ = cap_ = nullptr;
    surface_ = nullptr;
    probe_ = nullptr;
    surfaceTriangles_ = 0;
    stockLight_.set(nullptr, 0, 0);
    deviation_.reset();  // a map is of one plan
    latheParts_.clear();
    latheStep_.clear();
    turrets_.reset();  // of one plan
    turretTools_.clear();
    turretAt_.clear();
    axes_ = nullptr;
    scaleNote_ = nullptr;
}

void Scene::setPlan(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock)
{
    if (plan && canUpdateInPlace(*plan)) {
        updateInPlace(std::move(plan), std::move(stock));
        return;
    }
    lastUpdate_ = {};
    clear();
    plan_ = std::move(plan);
    if (!plan_) return;
    const int n = static_cast<int>(plan_->steps.size());
    if (stock && stock->stepCount() == n) simulation_ = std::move(stock);
    if (selected_ >= n) selected_ = -1;
    if (highlighted_.step >= n) highlighted_ = {};
    if (playhead_.step >= n) playhead_ = {};
    lathe_ = plan_->mmJob.bar.has_value();
    if (lathe_) {
        buildLathe();
        return;
    }

    const Stock& s = plan_->mmJob.stock;
    auto outline = vtkSmartPointer<vtkOutlineSource>::New();
    outline->SetBounds(s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0);
    outline->Update();
    stockEdges_ = lineActor(outline->GetOutput(), palette::kStockEdges, 1.0);
    renderer_->AddActor(stockEdges_);
    partEdges_ = lineActor(pocketOutlines(plan_->steps, &outlines_), palette::kPartEdges, 1.5);
    partEdges_->SetVisibility(partShown_);
    renderer_->AddActor(partEdges_);
    surface_ = machinedSurfaces(plan_->steps, &surfaceTriangles_);
    if (surface_) renderer_->AddActor(surface_);
    probe_ = probeMarks();
    if (probe_) renderer_->AddActor(probe_);

    steps_.resize(plan_->steps.size());
    mergePaths();
    // All feeds, then all rapids (drawn over them where they meet).
    for (const PathBlock& b : blocks_) renderer_->AddActor(b.feeds);
    for (const PathBlock& b : blocks_) renderer_->AddActor(b.rapids);

    makeAxes(niceLength(std::max(s.width, s.length)));
    renderer_->AddActor(axes_);
    renderer_->AddActor2D(scaleNote_);

    updateStock();
    updateEmphasis();
    updateTool();
    updateHighlight();
}

void Scene::makeAxes(double axisLength)
{
    axisLength_ = axisLength;
    axes_ = labelledAxes(axisLength, 14);
    scaleNote_ = vtkSmartPointer<vtkTextActor>::New();
    scaleNote_->GetTextProperty()->SetFontSize(14);
    writeScaleNote();
    scaleNote_->GetTextProperty()->SetColor(palette::kText.red(), palette::kText.green(), palette::kText.blue());
    scaleNote_->GetTextProperty()->SetJustificationToRight();  // clear of the axes at the work zero
    scaleNote_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    scaleNote_->SetPosition(0.99, 0.015);
    showWhenStill();
}

Scene::StepActors& Scene::stepActors(int k)
{
    StepActors& a = steps_[static_cast<std::size_t>(k)];
    const Step& step = plan_->steps[static_cast<std::size_t>(k)];
    if (!a.feeds && step.path) {
        a.geometry = makePathGeometry(*step.path);
        a.feeds = lineActor(a.geometry.feeds, palette::kFeed, 2.0);
        a.rapids = lineActor(a.geometry.rapids, palette::kRapid, 1.0);
    }
    return a;
}

void Scene::setSelectedStep(int index)
{
    const int selected = plan_ && index >= 0 && index < static_cast<int>(plan_->steps.size()) ? index : -1;
    if (selected == selected_) return;  // the step list re-announces its selection after every plan
    selected_ = selected;
    updateStock();
    updateEmphasis();
    updateTool();
}

void Scene::setOtherPathsHidden(bool hidden)
{
    othersHidden_ = hidden;
    updateEmphasis();
}

void Scene::highlightMove(int step, int move)
{
    highlighted_ = {step, move};
    updateHighlight();
    updateTool();
}

void Scene::updateEmphasis()
{
    if (lathe_) {  // a lathe job's step is drawn with the bar (scene_lathe.cpp)
        updateLod();
        return;
    }
    // Everything in the blocks' actors, the selected step drawn over them
    // with its own.
    for (const PathBlock& b : blocks_) {
        setColour(b.feeds, selected_ < 0 ? palette::kFeed : palette::kDimmed);
        b.feeds->GetProperty()->SetLineWidth(pathWidth(selected_ < 0 ? 2.0f : 1.0f));
        b.feeds->SetVisibility(pathsShown_ && (selected_ < 0 || !othersHidden_));
        b.rapids->SetVisibility(pathsShown_ && selected_ < 0);
    }
    if (shownStep_ >= 0 && shownStep_ < static_cast<int>(steps_.size()) && steps_[static_cast<std::size_t>(shownStep_)].feeds) {
        detach(steps_[static_cast<std::size_t>(shownStep_)].feeds);
        detach(steps_[static_cast<std::size_t>(shownStep_)].rapids);
    }
    shownStep_ = -1;
    if (selected_ >= 0 && stepActors(selected_).feeds) {
        StepActors& a = stepActors(selected_);
        setColour(a.feeds, palette::kFeed);
        a.feeds->GetProperty()->SetLineWidth(pathWidth(3.0f));
        a.feeds->SetVisibility(pathsShown_);
        a.rapids->SetVisibility(pathsShown_);
        renderer_->AddActor(a.feeds);
        renderer_->AddActor(a.rapids);
        shownStep_ = selected_;
    }
    updateLod();
}

void Scene::setPlayhead(int step, int move)
{
    if (!plan_ || step >= static_cast<int>(plan_->steps.size())) step = -1;
    playhead_ = step < 0 ? MoveRef{} : MoveRef{step, move};
    if (step >= 0 && step != selected_) {
        selected_ = step;
        updateEmphasis();
    }
    highlightMove(step, step < 0 ? -1 : move);
    updateStock();
}

void Scene::updateHighlight()
{
    if (highlight_) renderer_->RemoveActor(highlight_);
    highlight_ = nullptr;
    const int k = highlighted_.step;
    if (k < 0 || k >= static_cast<int>(steps_.size()) || !stepActors(k).feeds) return;
    highlight_ = lineActor(movePieces(steps_[k].geometry, highlighted_.move), palette::kHighlight, 5.0);
    highlight_->SetVisibility(pathsShown_);
    renderer_->AddActor(highlight_);
}

std::array<double, 6> Scene::bounds() const
{
    std::array<double, 6> b{0, 1, 0, 1, -1, 0};
    if (!plan_) return b;
    if (plan_->mmJob.bar) {
        // The bar, and every turning path's points (where the tools stand:
        // the approach in front of the face, above the bar), on both sides
        // of the axis (a two-path lathe's other turret's tool is drawn there).
        const BarStock& bar = *plan_->mmJob.bar;
        double z0 = bar.face - bar.length, z1 = bar.face, r = bar.diameter / 2;
        auto grow = [&](turning::ZR p) {
            z0 = std::min(z0, p.z);
            z1 = std::max(z1, p.z);
            r = std::max(r, std::abs(p.r));
        };
        for (const Step& step : plan_->steps)
            if (const TurnStep* turn = turnOf(step)) {
                grow(turn->path.start);
                for (const TurnMove& m : turn->path.moves) grow(m.end);
            }
        return {z0, z1, -r, r, -r, r};
    }
    const Stock& s = plan_->mmJob.stock;
    b = {s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0};
    std::vector<vtkPoints*> pointSets;
    for (const PathBlock& block : blocks_) pointSets.push_back(block.paths.points);
    for (const auto& a : steps_)
        if (a.geometry.points) pointSets.push_back(a.geometry.points);
    for (vtkPoints* points : pointSets) {
        if (points->GetNumberOfPoints() == 0) continue;
        double pb[6];
        points->GetBounds(pb);
        for (int i = 0; i < 6; i += 2) {
            b[i] = std::min(b[i], pb[i]);
            b[i + 1] = std::max(b[i + 1], pb[i + 1]);
        }
    }
    return b;
}

void Scene::setView(ViewPreset preset, double aspect)
{
    applyViewPreset(renderer_->GetActiveCamera(), preset, bounds(), aspect);
    renderer_->ResetCameraClippingRange();
}

}  // namespace taiwa::viz
