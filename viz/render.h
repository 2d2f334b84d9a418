// The offscreen render mode (`taiwa render`): the 3-D preview of a plan to a
// PNG without a window. Needs an X display with OpenGL (Mesa under
// `xvfb-run -a` will do); without one it returns an error, it never crashes.
#pragma once

#include "pipeline/pipeline.h"

#include <optional>
#include <string>

namespace taiwa::viz {

enum class ViewPreset { Iso, Top, Front };

struct RenderOptions {
    int step = -1;           // 0-based index into plan.steps; -1 = all
    bool showStock = false;  // the simulated stock after the step (after all: the finished part)
    int width = 800, height = 600;
    ViewPreset view = ViewPreset::Iso;
};

// Renders and writes the PNG; the error message, or nothing on success.
std::optional<std::string> renderToPng(const Plan& plan, const RenderOptions& options, const std::string& pngPath);

// Why offscreen rendering cannot work here (no X display), or nothing.
std::optional<std::string> displayProblem();

}  // namespace taiwa::viz
