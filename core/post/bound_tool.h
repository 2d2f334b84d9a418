// The tool a step was bound to when it was planned (planJob's bindTools),
// read back from the plan's own tool list (Plan::tools): the posts and the
// tool tables read a step's tool here and never choose or look one up in a
// library, so that a library edited after planning changes nothing posted.
// A tool id the list lacks is the caller's bug (std::logic_error).
#pragma once

#include "model/tool.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace taiwa::post {

inline const Tool& boundTool(const std::vector<Tool>& planTools, int id)
{
    if (const Tool* t = findTool(planTools, id)) return *t;
    throw std::logic_error("post-processor: tool " + std::to_string(id) + " is not among the plan's tools");
}

}  // namespace taiwa::post
