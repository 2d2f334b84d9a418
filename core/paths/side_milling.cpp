// Tool path of the side milling of module SIDE (a placeholder until the module lands).
#include "paths/generators.h"

#include <stdexcept>

namespace taiwa::paths {

ToolPath sideMilling(const Step& step, const Tool&, const TechnologyData&, const PathParameters&)
{
    throw std::logic_error("no tool path yet for step " + step.label());
}

}  // namespace taiwa::paths
