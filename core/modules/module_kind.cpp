// The door's defaults that are more than a line (modules/module_kind.h).
#include "modules/module_kind.h"

#include <stdexcept>

namespace taiwa {

ToolPath ModuleKind::toolPath(const Step& step, const Tool&, const TechnologyData&, const PathParameters&) const
{
    throw std::logic_error(std::string("module ") + name() + " makes no milling tool path (step " + step.label() + ")");
}

}  // namespace taiwa
