// The setup picture of the instruction sheet (setup_picture.h): its own
// small VTK scene (the stock, the jaws, the origin) in an offscreen window.
#include "viz/setup_picture.h"

#include "machine/machine.h"
#include "sheet/sheet.h"
#include "viz/camera_presets.h"
#include "viz/palette.h"
#include "viz/render.h"
#include "viz/solids.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace taiwa::viz {

namespace {

vtkSmartPointer<vtkActor> solid(vtkPolyDataAlgorithm* source, Rgb colour, double opacity = 1.0)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.red(), colour.green(), colour.blue());
    actor->GetProperty()->SetOpacity(opacity);
    return actor;
}

vtkSmartPointer<vtkActor> box(const std::array<double, 6>& bounds, Rgb colour, double opacity = 1.0)
{
    auto cube = vtkSmartPointer<vtkCubeSource>::New();
    cube->SetBounds(bounds.data());
    return solid(cube, colour, opacity);
}

// The work offset's origin: its axes `length` long, labelled as the
// machine's axes (`x`, `y`, `z`: the view's X, Y, Z), and its name beside
// it, above left of the origin or (`below`) below right.
void markOrigin(vtkRenderer* renderer, double length, const char* x, const char* y, const char* z, const std::string& name,
                bool below)
{
    renderer->AddActor(labelledAxes(length, 13, x, y, z));
    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(name.c_str());
    label->SetPosition(0, 0, 0);
    label->SetDisplayOffset(below ? 10 : -12, below ? -24 : 8);
    label->GetTextProperty()->SetFontSize(15);
    label->GetTextProperty()->BoldOn();
    label->GetTextProperty()->SetJustification(below ? VTK_TEXT_LEFT : VTK_TEXT_RIGHT);
    label->GetTextProperty()->SetColor(palette::kTool.red(), palette::kTool.green(), palette::kTool.blue());
    renderer->AddActor(label);
}

// A block in the vice: the jaws along the gripped faces, as thick as a
// tenth of the block's larger side, from its bottom up to their height.
std::array<double, 6> millingSetup(const Job& job, vtkRenderer* renderer)
{
    const Stock& s = job.stock;
    auto stock = vtkSmartPointer<vtkCubeSource>::New();
    stock->SetBounds(s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0);
    renderer->AddActor(solid(stock, palette::kStock));
    std::array<double, 6> bounds{std::min(s.x, 0.0), std::max(s.x + s.width, 0.0), std::min(s.y, 0.0),
                                 std::max(s.y + s.length, 0.0), -s.height, 0.0};
    if (job.clamping) {
        const double t = 0.1 * std::max(s.width, s.length), bottom = -s.height, top = bottom + job.clamping->height;
        const bool x = job.clamping->grip == Clamping::Grip::X;
        for (const double side : {0.0, 1.0}) {
            std::array<double, 6> jaw = x ? std::array{s.x - t + side * (s.width + t), s.x + side * (s.width + t), s.y - t,
                                                       s.y + s.length + t, bottom, top}
                                          : std::array{s.x - t, s.x + s.width + t, s.y - t + side * (s.length + t),
                                                       s.y + side * (s.length + t), bottom, top};
            renderer->AddActor(box(jaw, palette::kClamp, 0.55));
            for (int k = 0; k < 6; k += 2) bounds[k] = std::min(bounds[k], jaw[k]), bounds[k + 1] = std::max(bounds[k + 1], jaw[k + 1]);
        }
    }
    const double axes = 0.25 * std::min(s.width, s.length);
    markOrigin(renderer, axes, "X", "Y", "Z", job.workOffset, false);
    // Room for the axes above the top and for the name left of the origin.
    bounds[0] = std::min(bounds[0], -0.15 * std::max(s.width, s.length));
    bounds[2] = std::min(bounds[2], -0.15 * std::max(s.width, s.length));
    bounds[5] = std::max(bounds[5], axes);
    return bounds;
}

// A bar in a three-jaw chuck (the scene's lathe axes: the spindle along
// the view's X, Z0 at the finished face), out of the jaws by the sheet's
// stick-out; the chuck as wide as the machine's, seen up to its jaws.
std::array<double, 6> latheSetup(const Plan& plan, vtkRenderer* renderer)
{
    const BarStock& bar = *plan.mmJob.bar;
    const double r = bar.diameter / 2, jawsFront = bar.face - barStickOut(plan);
    const double back = std::min(bar.face - bar.length, jawsFront - r);
    auto rod = vtkSmartPointer<vtkCylinderSource>::New();  // along Y: turned onto X
    rod->SetRadius(r);
    rod->SetHeight(bar.face - back);
    rod->SetResolution(72);
    auto barActor = solid(rod, palette::kStock, 0.6);  // the origin on the face shows through
    barActor->SetOrientation(0, 0, 90);
    barActor->SetPosition((bar.face + back) / 2, 0, 0);
    renderer->AddActor(barActor);
    const Machine* machine = findMachine(plan.mmJob.machine);
    const double chuckR = machine && machine->chuckDiameter > 2 * r ? machine->chuckDiameter / 2 : 2.5 * r;
    const double jawLength = std::max(0.6 * r, 10.0), jawHeight = 0.45 * (chuckR - r), chuckFront = jawsFront - jawLength;
    for (int k = 0; k < 3; ++k) {
        auto jaw = box({chuckFront, jawsFront, r, r + jawHeight, -0.2 * r, 0.2 * r}, palette::kClamp, 0.8);
        jaw->RotateX(90.0 + 120.0 * k);  // one jaw on top, the others 120° apart
        renderer->AddActor(jaw);
    }
    auto body = vtkSmartPointer<vtkCylinderSource>::New();
    body->SetRadius(chuckR);
    body->SetHeight(0.6 * chuckR);
    body->SetResolution(72);
    auto chuck = solid(body, palette::kChuck);
    chuck->SetOrientation(0, 0, 90);
    chuck->SetPosition(chuckFront - 0.3 * chuckR, 0, 0);
    renderer->AddActor(chuck);
    markOrigin(renderer, std::max(1.3 * r, 5.0), "Z", "", "X", plan.job.workOffset, true);
    // The bar and the jaws filling the picture, the chuck's rim cut off; the axes too.
    const double reach = 1.3 * (r + jawHeight);
    return {chuckFront - 0.3 * chuckR, std::max(bar.face, 0.0) + 1.5 * r, -reach, reach, -reach, reach};
}

}  // namespace

Result<std::string> setupPicture(const Plan& plan, int width, int height)
{
    const OffscreenWindow offscreen(width, height);
    if (offscreen.problem()) return Failure{*offscreen.problem()};
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(palette::kBackground.red(), palette::kBackground.green(), palette::kBackground.blue());
    const std::array<double, 6> bounds = plan.mmJob.bar ? latheSetup(plan, renderer) : millingSetup(plan.mmJob, renderer);
    applyViewPreset(renderer->GetActiveCamera(), plan.mmJob.bar ? ViewPreset::Front : ViewPreset::Iso, bounds,
                    static_cast<double>(width) / height);
    renderer->ResetCameraClippingRange();
    offscreen.window()->AddRenderer(renderer);
    offscreen.window()->Render();
    std::string png = pngOf(offscreen.window());
    if (png.empty()) return Failure{"cannot encode the picture of the setup"};
    return png;
}

}  // namespace taiwa::viz
