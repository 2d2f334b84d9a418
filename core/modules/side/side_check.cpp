// Input checks of one SIDE unit (side milling along a contour): the
// contour named and known, not crossing itself, no sharp corner turning
// towards the tool's side; the side, direction, U and F codes; depth, width
// and step-over; the pins; the room for the end mill (the smallest concave
// radius on the tool's side, and with the tool inside a closed contour its
// reach), refused naming the arc or neck that limits it and by how much.
#include "model/translate_noop.h"
#include "modules/side/side.h"

#include "check/check_unit.h"
#include "check/messages.h"
#include "modules/pocket_checks.h"
#include "modules/region_messages.h"
#include "modules/self_crossing.h"
#include "modules/side/side_messages.h"

#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;

bool checkCodes(const SideMill& m, Reporter& r)
{
    bool ok = true;
    const auto code = [&](const char* field, int v, bool allowed, const char* list) {
        if (allowed) return;
        r.unit(field, msg::sideCodeUnknown(field, v, list));
        ok = false;
    };
    code("side", m.side, m.side == 1 || m.side == 2, "1 (the tool on the left of the contour) or 2 (on its right)");
    code("direction", m.direction, m.direction == 1 || m.direction == 2, "1 (climb) or 2 (conventional)");
    code("U", m.toolUse, m.toolUse == 1 || m.toolUse == 8 || m.toolUse == 9,
         "1 (roughing and finishing), 8 (finishing only) or 9 (roughing only)");
    code("F", m.wallFinish, m.wallFinish == 1 || m.wallFinish == 2,
         "1 (finishing at full depth at once) or 2 (in several incisions)");
    return ok;
}

bool checkContour(const SideMill& m, Reporter& r)
{
    if (m.contour.empty()) {
        r.unit("contour", msg::sideContourNotNamed());
        return false;
    }
    if (!m.resolved) return false;  // no figure evaluated (a unit checked on its own)
    if (!m.path) {
        r.unit("contour", msg::contourUnknown(m.contour, m.figureContours));
        return false;
    }
    if (m.path->segments.empty() || crossesItself(*m.path)) {
        r.unit("contour", msg::contourCrossesItself(m.contour));
        return false;
    }
    return true;
}

}  // namespace

check::UnitReport checkSideMill(const SideMill& m, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, SideMill::kName, ctx, [&](Reporter& r, check::UnitReport& report) {
        const bool codes = checkCodes(m, r);
        const bool depth = checkDepthField(m.depth, r);
        bool width = check::checkLength(m.width, "width", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the width"), r);
        if (width && !(m.width > 0.0)) {
            r.unit("width", msg::lengthNotPositive(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the width W"), r.len(m.width)));
            width = false;
        }
        const bool roughs = m.toolUse != 8;
        if (width && codes && roughs && ctx.tech && m.width <= ctx.tech->alpha2 + 1e-9) {
            r.unit("width", msg::sideWidthNotAboveAllowance(r.len(m.width), r.len(ctx.tech->alpha2)));
            width = false;
        }
        check::checkStepOver(m.stepOver, r);
        const bool contour = checkContour(m, r);
        // A side milling unit works along another shape's wall: its band may
        // touch and surround other units' figures (a pocket in the boss it
        // mills round), so it takes no part in the interference check.
        report.figureValid = false;
        if (!codes || !contour) return;
        const side::Travel t = side::travel(m);
        if (const auto corner = side::sharpConcaveCorner(t.contour, t.toolOnLeft)) {
            r.unit("contour", msg::sharpInsideCorner(m.contour, r.len(corner->x), r.len(corner->y)));
            return;
        }
        if (!depth || !width || !ctx.tech || !ctx.library) return;
        const double room = side::toolRoom(m);
        if (room >= 1e299) return;  // nothing on the tool's side limits the end mill
        check::RoomQuery q;
        q.stepKeys = {"side"};
        const bool finishes = m.toolUse != 9;
        q.label = finishes ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the contour's smallest inside radius on the tool's side")
                           : "the contour's smallest inside radius on the tool's side + α2";
        q.available = finishes ? room : room + ctx.tech->alpha2;
        q.cornerRadius = room;
        Diagnostics found;
        check::checkRoom(q, m.tools, unitNo, SideMill::kName, ctx, found);
        for (Diagnostic& d : found) {
            // No end mill fits: said of the arc (or neck) that limits it, on the
            // contour, SIDE having no corner radius of its own.
            if (d.field == "cornerRadius") {
                const Tool* smallest = check::smallestSuitable(*ctx.library, q);
                d.field = "contour";
                if (smallest)
                    if (std::string at = side::noRoomAt(m, *smallest, q.cornerRadius - q.available, ctx.shownUnit); !at.empty())
                        d.message = std::move(at);
            }
            report.diagnostics.push_back(std::move(d));
        }
    });
}

}  // namespace taiwa
