// What a tool of the library may be: every value a planner, the post and
// the preview rely on, checked before a tool is saved (the tool library
// dialog) and when the library is read. Each problem names the field, in
// the words the sheet and the dialog use.
#pragma once

#include "model/tool.h"

#include <string>
#include <vector>

namespace taiwa {

struct ToolProblem {
    std::string field;    // "diameter", "cornerRadius", "cutting[aluminium-6061].surfaceSpeed"
    std::string message;  // "diameter 0 mm must be greater than zero"
};

// The T numbers a control takes: 1 to 999.
constexpr int kMaxToolNumber = 999;

std::vector<ToolProblem> toolProblems(const Tool& tool);

}  // namespace taiwa
