// Tool choice for the pocket modules' steps (M4, M2D, CP): the tool of every
// step of one unit with the reason in words, the roughing end mill that
// enters the pilot hole or ramps in, the pilot drill last. Called from
// pocket_plan.cpp and the modules' doors.
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/tool.h"
#include "tools/tool_fit.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct ToolPick {
    std::optional<ToolChoice> choice;
    std::string problem;  // why no tool fits, when choice is empty
};

// A roughing tool chosen before the decomposition that depends on it (M2D:
// the layer count depends on its diameter): the largest end mill that fits
// `f`, the reason naming `what` it roughs ("roughing layers").
ToolPick chooseRoughingTool(const tools::Fit& f, const std::vector<Tool>& library, const std::string& material,
                            const std::string& what);

// Chooses tools for all steps of one unit (steps in decomposition order), in
// place: roughing the largest end mill that fits the roughing corner radius and
// enters through the pilot hole (or ramps in without one), finishing a tool of
// radius <= the finished corner radius, tapered walls a taper end mill of the
// wall's angle, the pilot hole a drill not smaller than the roughing tool.
// Pins name tool ids by step kind key ("pilot", "roughing", ...). Returns the
// problems (empty when every step got a tool).
// A finishing step of a contour (its region's narrow place limits the
// tool) left without a tool because the end mills that pass the narrow
// place have flutes shorter than the depth, while a larger one has flutes
// that reach it: the longest-fluted end mill that passes, the smallest
// whose flutes reach, and the step's corner radius (the reach it fits).
// Nothing when a tool fits or something else stops them (CP names the
// narrow place instead of the flutes, modules/cp/cp_check.cpp).
struct NarrowForcesShortFlutes {
    const Tool* passing = nullptr;
    const Tool* reaching = nullptr;
    double cornerRadius = 0.0, depth = 0.0;
};
std::optional<NarrowForcesShortFlutes> narrowForcesShortFlutes(const Step& s, const std::vector<Tool>& library,
                                                               const std::string& material);

std::vector<std::string> chooseTools(std::vector<Step>& unitSteps, const ToolPins& pins,
                                     const std::vector<Tool>& library, const std::string& material);

}  // namespace taiwa
