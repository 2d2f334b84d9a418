// Tool path of the face milling of module FACE (a placeholder until the module lands).
#include "paths/generators.h"

#include <stdexcept>

namespace taiwa::paths {

ToolPath faceMilling(const Step& step, const Tool&, const TechnologyData&, const PathParameters&)
{
    throw std::logic_error("no tool path yet for step " + step.label());
}

}  // namespace taiwa::paths
