// Offscreen rendering of the preview scene to a PNG: a vtkRenderWindow in
// offscreen mode, read back with vtkWindowToImageFilter, written by
// vtkPNGWriter. The X display is checked first so that a missing display is
// an error message, not an abort inside VTK.
#include "viz/render.h"

#include "viz/scene.h"

#include <X11/Xlib.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

namespace taiwa::viz {

std::optional<std::string> displayProblem()
{
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name) return "no X display (DISPLAY is not set): run under `xvfb-run -a`";
    Display* d = XOpenDisplay(nullptr);
    if (!d) return std::string("cannot open X display '") + name + "': run under `xvfb-run -a`";
    XCloseDisplay(d);
    return std::nullopt;
}

std::optional<std::string> renderToPng(const Plan& plan, const RenderOptions& o, const std::string& pngPath)
{
    if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
        return "image size " + std::to_string(o.width) + "x" + std::to_string(o.height) + " is outside 16..8192 pixels";
    if (o.step < -1 || o.step >= static_cast<int>(plan.steps.size()))
        return "step " + std::to_string(o.step + 1) + " is out of range: the plan has " + std::to_string(plan.steps.size()) + " steps";
    if (auto problem = displayProblem()) return problem;

    Scene scene;
    scene.setPlan(std::make_shared<const Plan>(plan));
    scene.setSelectedStep(o.step);
    scene.setShowStock(o.showStock);  // last: the stock is simulated once, for the right step
    scene.setView(o.view, static_cast<double>(o.width) / o.height);

    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetSize(o.width, o.height);
    window->AddRenderer(scene.renderer());
    if (!window->SupportsOpenGL()) return std::string("no usable OpenGL (3.2 or later) on this display");
    window->Render();

    auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(pngPath.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    if (writer->GetErrorCode() != 0 || !std::filesystem::exists(pngPath)) return "cannot write " + pngPath;
    return std::nullopt;
}

}  // namespace taiwa::viz
