// The shared input checks of pocket_checks.h.
#include "modules/pocket_checks.h"

#include "model/translate_noop.h"
#include "modules/pocket_messages.h"

namespace taiwa {

std::optional<ToolUse> checkToolUseCode(int code, check::Reporter& r)
{
    const auto use = toolUseFromCode(code);
    if (!use) r.unit("U", msg::toolUseUnknown(code));
    return use;
}

bool checkWallFinishCode(int code, check::Reporter& r)
{
    if (wallFinishFromCode(code)) return true;
    r.unit("F", msg::wallFinishUnknown(code));
    return false;
}

bool checkPilotHoleCode(int code, check::Reporter& r)
{
    if (pilotHoleFromCode(code)) return true;
    r.unit("H", msg::pilotHoleUnknown(code));
    return false;
}

bool checkDepthField(double depth, check::Reporter& r)
{
    return check::checkLength(depth, "depth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"), r) &&
           check::checkDepth(depth, r);
}

}  // namespace taiwa
