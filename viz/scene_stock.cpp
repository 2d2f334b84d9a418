// The preview scene's stock (viz/scene.h): the glass tray with the stock
// hidden, the simulated stock after the selected step (or before it, or as
// played to a move), the verification's colour map in its place, a
// section through either, and the light of the surfaces shown
// (viz/surface_light.h).
#include "viz/scene.h"

#include "sim/stock_simulation.h"
#include "verify/deviation.h"
#include "viz/actors.h"
#include "viz/palette.h"
#include "viz/solids.h"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkMapper.h>
#include <vtkPlane.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace taiwa::viz {

void Scene::setShowStock(bool show)
{
    showStock_ = show;
    updateStock();
}

void Scene::setStockBefore(bool before)
{
    stockBefore_ = before;
    updateStock();
}

void Scene::updateStock()
{
    if (!plan_) return;
    if (lathe_) {
        updateLatheStep();
        return;
    }
    if (stock_) renderer_->RemoveActor(stock_);
    if (cap_) renderer_->RemoveActor(cap_);
    tray_ = false;
    cap_ = nullptr;
    if (surface_) surface_->SetVisibility(!deviation_);  // the map shows the part itself
    // The solid a section cuts open: the colour map, or the simulated stock.
    std::shared_ptr<const sim::HeightField> shown;
    const bool solid = deviation_ || showStock_ || section_;
    if (deviation_) {
        stock_ = actorFor(deviationSurface(*deviation_), palette::kStock);
        shown = std::shared_ptr<const sim::HeightField>(deviation_, &deviation_->stock);
    } else if (solid) {
        if (!simulation_) simulation_ = std::make_shared<sim::StockSimulation>(*plan_);
        // A step's own cut in its colour: after the step (or the blocks
        // played of it) against the stock before it.
        sim::StockSimulation::Snapshot field, before;
        if (playhead_.step >= 0) {
            field = simulation_->afterMove(playhead_.step, playhead_.move);
            before = simulation_->before(playhead_.step);
        } else if (selected_ < 0) {
            field = stockBefore_ ? simulation_->initial() : simulation_->finished();
        } else if (stockBefore_) {
            field = simulation_->before(selected_);
        } else {
            field = simulation_->after(selected_);
            before = simulation_->before(selected_);
        }
        stock_ = actorFor(heightFieldSurface(*field, before.get()), palette::kStock);
        shown = field;
    } else {
        stock_ = actorFor(stockBlock(plan_->mmJob.stock), palette::kStock);
        tray_ = true;
        // Only the far faces: a glass tray behind the paths, which keep their colours.
        stock_->GetProperty()->SetOpacity(0.12);
        stock_->GetProperty()->FrontfaceCullingOn();
        drawAsBackdrop(stock_);  // not as translucent geometry (scene_lod.cpp)
        // While the camera moves the stock's edges alone show it.
        stock_->SetVisibility(!moving_);
    }
    stockLight_.set(nullptr, 0, 0);
    if (shown) {  // the surface's own colours
        stock_->GetMapper()->ScalarVisibilityOn();
        stock_->GetMapper()->SetColorModeToDirectScalars();
        constexpr double ambient = 0.25, diffuse = 0.75;
        if (lightOnProcessor_) {
            stockLight_.set(stock_, ambient, diffuse);
        } else {
            auto* surface = vtkPolyData::SafeDownCast(stock_->GetMapper()->GetInputDataObject(0, 0));
            surface->GetCellData()->SetNormals(surface->GetCellData()->GetArray(kQuadNormals));
            stock_->GetProperty()->SetAmbient(ambient);
            stock_->GetProperty()->SetDiffuse(diffuse);
        }
    }
    if (section_ && shown) {
        // VTK keeps the side its plane's normal points to: ours points away.
        const SectionPlane& p = *section_;
        auto clip = vtkSmartPointer<vtkPlane>::New();
        clip->SetOrigin(p.origin.x, p.origin.y, p.origin.z);
        clip->SetNormal(-p.normal.x, -p.normal.y, -p.normal.z);
        stock_->GetMapper()->AddClippingPlane(clip);
        cap_ = lineActor(sectionCap(*shown, p), palette::kSection, 1.0);  // unlit: one flat colour
        renderer_->AddActor(cap_);
    }
    renderer_->AddActor(stock_);
    stockEdges_->SetVisibility(!solid);
}

void Scene::setLightOnProcessor(bool on)
{
    if (on == lightOnProcessor_) return;
    lightOnProcessor_ = on;
    updateStock();
}

void Scene::setSection(std::optional<SectionPlane> plane)
{
    if (plane == section_) return;
    section_ = plane;
    updateStock();
}

void Scene::setDeviationMap(std::shared_ptr<const verify::DeviationMap> map)
{
    if (map && map->empty()) map = nullptr;
    if (map == deviation_) return;
    deviation_ = std::move(map);
    updateStock();
}

}  // namespace taiwa::viz
