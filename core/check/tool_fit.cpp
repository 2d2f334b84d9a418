// Tool checks of input processing: pinned tools must exist, and every corner
// radius a step must cut needs a library tool that fits into it.
#include "check/messages.h"
#include "check/unit_checks.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace taiwa::check {

namespace {

bool suits(const Tool& t, const RoomQuery& q)
{
    return t.type == q.type && (q.type != ToolType::TaperEndMill || sameAngle(t.taperAngle, q.taper));
}

bool fits(const Tool& t, const RoomQuery& q) { return fitsInto(t.radius(), q.available); }

// The largest suitable tool that fits: the one a machinist would take instead.
const Tool* largestFitting(const std::vector<Tool>& library, const RoomQuery& q)
{
    const Tool* best = nullptr;
    for (const auto& t : library)
        if (suits(t, q) && fits(t, q) && (!best || t.diameter > best->diameter)) best = &t;
    return best;
}

Diagnostic error(int unitNo, const std::string& module, std::string field, std::string message)
{
    return {Severity::Error, unitNo, module, std::move(field), std::move(message)};
}

}  // namespace

const Tool* smallestSuitable(const std::vector<Tool>& library, const RoomQuery& q)
{
    const Tool* best = nullptr;
    for (const auto& t : library)
        if (suits(t, q) && (!best || t.diameter < best->diameter)) best = &t;
    return best;
}

void checkRoom(const RoomQuery& q, const ToolPins& pins, int unitNo, const std::string& module, const Context& ctx,
               Diagnostics& out)
{
    const auto& library = *ctx.library;
    const msg::Len available{q.available, ctx.shownUnit};
    bool needsLibraryTool = false;
    for (const auto& key : q.stepKeys) {
        const auto pin = pins.find(key);
        if (pin == pins.end()) {
            needsLibraryTool = true;
            continue;
        }
        const Tool* pinned = findTool(library, pin->second);
        if (pinned && !fits(*pinned, q))
            out.push_back(error(unitNo, module, "tools." + key,
                                msg::pinnedToolTooBig(key, *pinned, q.label, available, largestFitting(library, q))));
    }
    if (!needsLibraryTool) return;

    const Tool* smallest = smallestSuitable(library, q);
    if (!smallest) {
        if (q.type == ToolType::TaperEndMill) {
            std::set<double> angles;
            for (const auto& t : library)
                if (t.type == ToolType::TaperEndMill) angles.insert(t.taperAngle);
            out.push_back(error(unitNo, module, "taper", msg::noTaperTool(q.taper, {angles.begin(), angles.end()})));
        } else {
            out.push_back(error(unitNo, module, "tools." + q.stepKeys.front(), msg::noToolOfType(toString(q.type))));
        }
        return;
    }
    if (!fits(*smallest, q)) {
        const double neededR1 = q.cornerRadius + (smallest->radius() - q.available);
        out.push_back(error(unitNo, module, "cornerRadius",
                            msg::noRoomForTool(q.label, available, *smallest, {neededR1, ctx.shownUnit})));
    }
}

const std::vector<std::string>& millingStepKeys()
{
    static const std::vector<std::string> keys{"pilot", "roughing", "floor", "wall", "inclined"};
    return keys;
}

void checkPins(const ToolPins& pins, const std::vector<std::string>& keys, int unitNo, const std::string& module,
               const Context& ctx, Diagnostics& out)
{
    for (const auto& [key, id] : pins) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            out.push_back(error(unitNo, module, "tools." + key, msg::unknownStepKey(key, module, keys)));
        else if (ctx.library && !findTool(*ctx.library, id))
            out.push_back(error(unitNo, module, "tools." + key, msg::toolNotInLibrary(id)));
    }
}

}  // namespace taiwa::check
