// The probing units' touches and fitted centres in the 3-D view
// (viz::Scene::probeMarks; docs/preview.md "Probing in the 3-D view"):
// each touch a ball of the stylus's radius where the ball's centre was,
// at the touch depth below the top face, and the centre the fit found as a
// vertical line through the part with a cross on the top face. In work
// coordinates: the fitted centre is the work origin the setting block sets
// (X Y 0 at the centre, Z 0 on the top face).
#include "viz/scene.h"

#include "modules/registry.h"
#include "viz/actors.h"
#include "viz/palette.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include <algorithm>

namespace taiwa::viz {

vtkSmartPointer<vtkActor> Scene::probeMarks() const
{
    if (!plan_ || plan_->setups.empty()) return nullptr;
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    auto lines = vtkSmartPointer<vtkPolyData>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    const auto line = [&](double x0, double y0, double z0, double x1, double y1, double z1) {
        cells->InsertNextCell(2);
        cells->InsertCellPoint(points->InsertNextPoint(x0, y0, z0));
        cells->InsertCellPoint(points->InsertNextPoint(x1, y1, z1));
    };
    bool any = false;
    for (const WorkSetup& setup : plan_->setups) {
        if (setup.unit < 0 || setup.unit >= static_cast<int>(plan_->mmJob.units.size())) continue;
        const MachiningUnit& unit = plan_->mmJob.units[static_cast<std::size_t>(setup.unit)];
        // The probe as the plan found it (its number and ball): the plan's
        // tools are the machining steps' only.
        Tool probe;
        probe.id = setup.tool;
        probe.type = ToolType::Probe;
        probe.diameter = 2 * setup.ballRadius;
        const auto sketch = moduleKind(unit.module).sketch(unit.module, LengthUnit::Millimetre, {probe});
        if (!sketch || !sketch->centre) continue;  // too few touches for a fit: nothing to place them by
        const Point2 c = *sketch->centre;
        const double z = -setup.touchDepth, r = setup.ballRadius > 0 ? setup.ballRadius : 1.0;
        for (const Sketch::Mark& m : sketch->marks) {
            auto ball = vtkSmartPointer<vtkSphereSource>::New();
            ball->SetCenter(m.at.x - c.x, m.at.y - c.y, z);
            ball->SetRadius(r);
            ball->SetThetaResolution(16);
            ball->SetPhiResolution(10);
            ball->Update();
            append->AddInputData(ball->GetOutput());
            any = true;
        }
        // The centre: down through the part to the touches' depth, a cross on the top face.
        const double arm = std::max({setup.sizeX, setup.sizeY, 10.0}) / 8;
        line(0, 0, arm / 2, 0, 0, z - 2 * r);
        line(-arm, 0, 0, arm, 0, 0);
        line(0, -arm, 0, 0, arm, 0);
        any = true;
    }
    if (!any) return nullptr;
    lines->SetPoints(points);
    lines->SetLines(cells);
    append->AddInputData(lines);
    append->Update();
    auto actor = actorFor(append->GetOutput(), palette::kProbe);
    actor->GetProperty()->SetLineWidth(2.0f);
    return actor;
}

}  // namespace taiwa::viz
