// The offscreen render mode (`taiwa render`): the 3-D preview of a plan to a
// PNG without a window. Needs an X display with OpenGL (Mesa under
// `xvfb-run -a` will do); without one it returns an error, it never crashes.
#pragma once

#include "model/plan.h"
#include "model/result.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkRenderWindow;

namespace taiwa::viz {

enum class ViewPreset { Iso, Top, Front };

// A section through the stock: the plane through `origin` with `normal`
// (need not be of unit length); the material on the side the normal points
// to is taken away, so that the face the plane cuts shows (Scene::setSection).
struct SectionPlane {
    Point3 origin{};
    Point3 normal{1.0, 0.0, 0.0};
    friend bool operator==(const SectionPlane&, const SectionPlane&) = default;
};

struct RenderOptions {
    int step = -1;           // 0-based index into plan.steps; -1 = all
    int move = -1;           // with a step: the stock after its moves 0..move, the tool at that block (Scene::setPlayhead); -1: the whole step
    bool showStock = false;  // the simulated stock after the step (after all: the finished part)
    int width = 800, height = 600;
    ViewPreset view = ViewPreset::Iso;
    std::optional<SectionPlane> section;  // the stock cut open by this plane (the simulated stock shown)
    // The verification's colour map of the finished part (verified at
    // `resolution` mm) instead of the stock.
    bool deviation = false;
    double resolution = 0.25;
};

// Renders and writes the PNG; the error message, or nothing on success.
// The largest side of a picture `taiwa render` draws.
constexpr int kMaxRenderSide = 4096;

Result<void> renderToPng(const Plan& plan, const RenderOptions& options, const std::string& pngPath);

// The window's picture as PNG bytes; empty when it cannot be encoded.
std::string pngOf(vtkRenderWindow* window);

// An offscreen render window on a connection to the X display of its own,
// closed after the window: VTK opens no connection itself, so none is left
// behind however many windows come and go (benchmarks make hundreds).
class OffscreenWindow {
public:
    OffscreenWindow(int width, int height);
    ~OffscreenWindow();
    OffscreenWindow(const OffscreenWindow&) = delete;
    OffscreenWindow& operator=(const OffscreenWindow&) = delete;
    // Why there is no window (no display, no usable OpenGL), or nothing.
    const std::optional<std::string>& problem() const;
    // nullptr when problem() says why.
    vtkRenderWindow* window() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace taiwa::viz
