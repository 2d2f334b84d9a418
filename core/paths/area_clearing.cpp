// Tool path of the area clearing by drawn passes of module AREA (a placeholder until the module lands).
#include "paths/generators.h"

#include <stdexcept>

namespace taiwa::paths {

ToolPath areaClearing(const Step& step, const Tool&, const TechnologyData&, const PathParameters&)
{
    throw std::logic_error("no tool path yet for step " + step.label());
}

}  // namespace taiwa::paths
