// Offscreen rendering of the preview scene to a PNG: a vtkRenderWindow in
// offscreen mode, read back with vtkWindowToImageFilter, written by
// vtkPNGWriter. The X display is opened here first, so that a missing or
// unreachable display is an error message, not an abort inside VTK, and the
// window is given that connection (SetDisplayId): VTK opens none of its own,
// so a display that goes away between the check and the render cannot abort.
#include "viz/render.h"

#include "io/job_io.h"

#include "verify/deviation.h"
#include "viz/scene.h"

#include <X11/Xlib.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <thread>

namespace taiwa::viz {

namespace {

constexpr const char* kNeedsDisplay = "rendering needs an X display (run under xvfb-run)";

// An open connection to $DISPLAY, closed when it goes out of scope.
struct XConnection {
    Display* display = nullptr;
    std::string problem;  // why there is none
    XConnection()
    {
        const char* name = std::getenv("DISPLAY");
        if (!name || !*name) {
            problem = kNeedsDisplay;
            return;
        }
        // An X server refuses connections made in quick succession for a
        // moment (EAGAIN; Xvfb does after a few dozen): try again for up
        // to a second before calling the display unreachable.
        for (int attempt = 0; attempt < 50 && !display; ++attempt) {
            if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
            display = XOpenDisplay(nullptr);
        }
        if (!display) problem = std::string(kNeedsDisplay) + ": cannot open X display '" + name + "'";
    }
    ~XConnection()
    {
        if (display) XCloseDisplay(display);
    }
    XConnection(const XConnection&) = delete;
    XConnection& operator=(const XConnection&) = delete;
};

}  // namespace

struct OffscreenWindow::Impl {
    XConnection x;  // declared before the window: closed after it
    vtkSmartPointer<vtkRenderWindow> window;
    std::optional<std::string> problem;
};

OffscreenWindow::OffscreenWindow(int width, int height) : impl_(std::make_unique<Impl>())
{
    if (!impl_->x.display) {
        impl_->problem = impl_->x.problem;
        return;
    }
    auto w = vtkSmartPointer<vtkRenderWindow>::New();
    w->SetDisplayId(impl_->x.display);
    w->SetOffScreenRendering(1);
    w->SetMultiSamples(0);  // VTK's default multisampling costs 2.4-3.5x on software rendering
    w->SetSize(width, height);
    if (!w->SupportsOpenGL()) {
        impl_->problem = "no usable OpenGL (3.2 or later) on this display";
        return;
    }
    impl_->window = w;
}

OffscreenWindow::~OffscreenWindow()
{
    if (impl_->window) impl_->window->Finalize();  // its GL context, while the connection is open
}

const std::optional<std::string>& OffscreenWindow::problem() const { return impl_->problem; }

vtkRenderWindow* OffscreenWindow::window() const { return impl_->window; }

std::string pngOf(vtkRenderWindow* window)
{
    auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->WriteToMemoryOn();
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    vtkUnsignedCharArray* png = writer->GetResult();
    if (writer->GetErrorCode() != 0 || !png || png->GetNumberOfValues() == 0) return {};
    return std::string(reinterpret_cast<const char*>(png->GetPointer(0)), static_cast<std::size_t>(png->GetNumberOfValues()));
}

Result<void> renderToPng(const Plan& plan, const RenderOptions& o, const std::string& pngPath)
{
    if (o.width < 16 || o.height < 16 || o.width > kMaxRenderSide || o.height > kMaxRenderSide)
        return Failure{"image size " + std::to_string(o.width) + "x" + std::to_string(o.height) + " is outside 16.." +
                       std::to_string(kMaxRenderSide) + " pixels"};
    if (o.step < -1 || o.step >= static_cast<int>(plan.steps.size()))
        return Failure{"step " + std::to_string(o.step + 1) + " is out of range: the plan has " +
                       std::to_string(plan.steps.size()) + " steps"};
    // The folder first: VTK would report a missing one as "Ran out of disk space".
    const auto folder = std::filesystem::absolute(pngPath).parent_path();
    if (!std::filesystem::is_directory(folder)) return Failure{"cannot write " + pngPath + ": no folder " + folder.string()};
    const OffscreenWindow offscreen(o.width, o.height);
    if (offscreen.problem()) return Failure{*offscreen.problem()};
    vtkRenderWindow* window = offscreen.window();

    Scene scene;
    scene.setPlan(std::make_shared<const Plan>(plan));
    scene.setSelectedStep(o.step);
    scene.setShowStock(o.showStock);  // last: the stock is simulated once, for the right step
    if (o.step >= 0 && o.move >= 0) scene.setPlayhead(o.step, o.move);
    scene.setSection(o.section);
    if (o.deviation) {
        verify::Options v;
        v.resolution = o.resolution;
        try {
            const verify::Report report = verify::verifyPlan(plan, v);
            if (!report.skipped.empty()) return Failure{"no colour map: " + report.skipped};
            auto map = std::make_shared<const verify::DeviationMap>(verify::deviationMap(plan, report));
            if (map->empty()) return Failure{"no colour map: a lathe job's view is its half-section"};
            scene.setDeviationMap(std::move(map));
        } catch (const Refusal& e) {
            return Failure{std::string("no colour map: ") + e.what()};
        }
    }
    scene.setView(o.view, static_cast<double>(o.width) / o.height);
    window->AddRenderer(scene.renderer());
    window->Render();

    // Written like every other file: whole, synced, renamed.
    const std::string png = pngOf(window);
    if (png.empty()) return Failure{"cannot encode " + pngPath};
    return writeFileAtomically(pngPath, png);
}

}  // namespace taiwa::viz
