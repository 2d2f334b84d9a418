// Tool choice (pipeline stage 3, second half): the tool of every step with
// the reason recorded, tool life accounting, and the job-wide step order that
// saves tool changes without breaking dependencies.
#pragma once

#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
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
std::vector<std::string> chooseTools(std::vector<Step>& unitSteps, const ToolPins& pins,
                                     const std::vector<Tool>& library, const std::string& material);

// Job-wide order: a permutation of indices into `steps` that groups steps by
// tool to save tool changes, never putting a pilot hole after the roughing
// that plunges into it, nor a unit's finishing before its roughing, nor any
// other unit's step before the face milling of the stock top.
std::vector<int> orderSteps(const std::vector<Step>& steps);

// Tool life: walks the ordered steps adding each step's minutes to its tool's
// used life; where a step would exceed the remaining life, returns a note
// ("T5 reaches its life in step ...: change it before ...").
struct ToolLifeNote {
    int stepIndex = 0;  // index into the ordered steps
    int toolId = 0;
    std::string message;
};
std::vector<ToolLifeNote> planToolLife(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library);

}  // namespace taiwa
