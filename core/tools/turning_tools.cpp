// Choosing among the library's lathe tools (turning_tools.h).
#include "tools/turning_tools.h"

namespace taiwa {

const Tool* finishingTurningTool(const std::vector<Tool>& library, bool inside)
{
    const Tool* best = nullptr;
    for (const Tool& t : library) {
        if (t.type != ToolType::TurningInsert || t.turning.inside != inside || !(t.cornerRadius > 0.0)) continue;
        if (!best || t.cornerRadius < best->cornerRadius || (t.cornerRadius == best->cornerRadius && t.id < best->id))
            best = &t;
    }
    return best;
}

}  // namespace taiwa
