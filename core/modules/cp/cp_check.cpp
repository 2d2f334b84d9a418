// Input checks of one CP unit (contour pocket): the named contours (known,
// closed, not crossing themselves, islands inside the outline and apart, no
// sharp inside corner), the codes, the depth, and the room for the tools in
// the contour's narrowest place: a refusal for want of room names that
// place (an island touching the outline or another island, the gap between
// them, a neck of one contour, an inside arc: paths/narrowest.h) on the
// field of the contour concerned, "outline" or "islands".
#include "model/translate_noop.h"
#include "modules/cp/cp.h"

#include "check/check_unit.h"
#include "check/messages.h"
#include "modules/named_region.h"
#include "modules/pocket_checks.h"
#include "modules/pocket_tools.h"
#include "model/codes.h"
#include "paths/narrowest.h"
#include "modules/pocket_messages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

using check::Reporter;

bool checkContours(const ContourPocket& p, Reporter& r)
{
    return checkNamedRegion(p.contours, r, TAIWA_TRANSLATE_NOOP("taiwa::msg", "pocket"), true);
}

bool checkCodes(const ContourPocket& p, Reporter& r)
{
    const auto use = checkToolUseCode(p.toolUse, r);
    bool ok = use.has_value();
    if (use == ToolUse::Cored) {
        r.unit("U", msg::toolUseNotForContours(p.toolUse));
        ok = false;
    }
    return checkWallFinishCode(p.wallFinish, r) && ok;
}

// The words the messages about a narrow place quote, each written once:
// its contours' names, its width and its two points, lengths in the job's
// unit; and the field of the contour concerned.
struct PlaceWords {
    std::string first, second;   // the contours' names (the same one for a neck or an arc)
    std::string width;
    std::string ax, ay, bx, by;  // the points a and b
    std::string field;           // "outline" or "islands"
};

PlaceWords placeWords(const ContourPocket& p, const paths::NarrowestPlace& n, LengthUnit shown)
{
    const auto name = [&](int k) { return k == 0 ? p.contours.outline : p.contours.islands.at(static_cast<std::size_t>(k - 1)); };
    const auto q = [&](double mm) { return msg::quote({mm, shown}); };
    return {name(n.first), name(n.second), q(n.width), q(n.a.x), q(n.a.y), q(n.b.x), q(n.b.y),
            n.first == 0 && n.second == 0 ? "outline" : "islands"};
}

// The refusal of a room too small for the smallest end mill, at the place
// that makes it so, on the field of its contour. `allowance`: what the
// step leaves on the walls (α2, α3 or 0), the tool's radius plus it must
// fit the place's reach.
Diagnostic narrowPlace(const ContourPocket& p, const paths::NarrowestPlace& n, const Tool& tool, double allowance,
                       Reporter& r)
{
    using Kind = paths::NarrowestPlace::Kind;
    const PlaceWords w = placeWords(p, n, r.ctx.shownUnit);
    const std::string needed = msg::quote(r.len(2.0 * (tool.radius() + allowance))), mill = msg::toolName(tool);
    std::string text;
    switch (n.kind) {
    case Kind::Touch:
        text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "the island {} touches {} at ({}, {}): no end mill passes between them; "
                                                "keep it {} off (the smallest end mill, {}, with what the step leaves "
                                                "on the walls) or make the two one contour"),
                           w.first, w.second, w.ax, w.ay, needed, mill);
        break;
    case Kind::Gap:
        text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "the gap between the island {} and {} is {} wide at ({}, {}); the "
                                                "smallest end mill, {}, needs {} there"),
                           w.first, w.second, w.width, w.ax, w.ay, mill, needed);
        break;
    case Kind::Neck:
        text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} narrows to {} between ({}, {}) and ({}, {}); the smallest end "
                                                "mill, {}, needs {} there"),
                           w.first, w.width, w.ax, w.ay, w.bx, w.by, mill, needed);
        break;
    case Kind::InsideArc:
        text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} has an inside arc of radius {} at ({}, {}); the smallest end mill, "
                                                "{}, needs a radius of at least {} there"),
                           w.first, w.width, w.ax, w.ay, mill, msg::quote(r.len(tool.radius() + allowance)));
        break;
    }
    return {Severity::Error, r.unitNo, ContourPocket::kName, w.field, text};
}

// check::checkRoom, its refusal for want of room (on a field CP does not
// have) replaced by the place that limits the tool.
void checkRoomAt(const check::RoomQuery& q, const ContourPocket& p, Reporter& r)
{
    Diagnostics found;
    check::checkRoom(q, p.tools, r.unitNo, ContourPocket::kName, r.ctx, found);
    for (Diagnostic& d : found) {
        if (d.field == "cornerRadius") {
            // One refusal per place: roughing's (the larger need) says it.
            if (std::any_of(r.out.begin(), r.out.end(), [&](const Diagnostic& e) {
                    return e.unit == r.unitNo && (e.field == "outline" || e.field == "islands");
                }))
                continue;
            const Tool* tool = check::smallestSuitable(*r.ctx.library, q);
            const auto place = p.contours.region ? paths::narrowestPlace(*p.contours.region) : std::nullopt;
            if (tool && place) d = narrowPlace(p, *place, *tool, q.cornerRadius - q.available, r);
            else d.field = "outline";
        }
        r.out.push_back(std::move(d));
    }
}

void checkRooms(const ContourPocket& p, double reach, Reporter& r)
{
    const TechnologyData& tech = *r.ctx.tech;
    const ToolUse use = *toolUseFromCode(p.toolUse);
    if (hasRoughing(use) || hasFloorFinishing(use)) {
        check::RoomQuery q;
        if (hasRoughing(use)) q.stepKeys.push_back("roughing");
        if (hasFloorFinishing(use)) q.stepKeys.push_back("floor");
        q.label = "the contour's narrowest reach (half its narrowest channel or its smallest inside radius) − α2";
        q.available = reach - tech.alpha2;
        q.cornerRadius = reach;
        checkRoomAt(q, p, r);
    }
    if (!hasWallFinishing(use)) return;
    const bool twoStage = *wallFinishFromCode(p.wallFinish) == WallFinish::TwoStage;
    check::RoomQuery q;
    q.stepKeys = {"wall"};
    q.label = twoStage ? "the contour's narrowest reach − α3"
                       : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the contour's narrowest reach");
    q.available = reach - (twoStage ? tech.alpha3 : 0.0);
    q.cornerRadius = reach;
    checkRoomAt(q, p, r);
}

}  // namespace

void nameNarrowPlaceOfShortFlutes(const ContourPocket& p, const std::vector<Step>& steps, const std::vector<Tool>& library,
                                  const std::string& material, LengthUnit shown, int unitNo, Diagnostics& out)
{
    if (!p.contours.region) return;
    std::optional<paths::NarrowestPlace> place;
    for (const Step& s : steps) {
        if (s.tool) continue;
        const auto why = narrowForcesShortFlutes(s, library, material);
        if (!why) continue;
        if (!place) place = paths::narrowestPlace(*p.contours.region);
        if (!place) return;
        const auto it = std::find_if(out.begin(), out.end(), [&](const Diagnostic& d) {
            return d.unit == unitNo && d.field == "tools" && d.message.starts_with(s.label() + ": ");
        });
        if (it == out.end()) continue;
        using Kind = paths::NarrowestPlace::Kind;
        const paths::NarrowestPlace& n = *place;
        const PlaceWords w = placeWords(p, n, shown);
        const auto q = [&](double mm) { return msg::quote({mm, shown}); };
        // What the step leaves on the walls: the place's reach less the corner the tool must fit.
        const double allowance = std::max(0.0, p.reach - why->cornerRadius);
        const double neededRadius = why->reaching->radius() + allowance;
        const std::string passing = msg::toolName(*why->passing), reaching = msg::toolName(*why->reaching);
        std::string text;
        if (n.kind == Kind::InsideArc) {
            text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "{} has an inside arc of radius {} at ({}, {}): the end mills that fit it have flutes "
                                                    "shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but "
                                                    "needs a radius of {} there, {} more (make the arc larger, or the pocket shallower)"),
                               w.first, w.width, w.ax, w.ay, q(why->depth), passing, reaching, q(neededRadius),
                               q(neededRadius - n.width));
        } else if (n.kind == Kind::Neck) {
            text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "{} narrows to {} between ({}, {}) and ({}, {}): the end mills that pass there "
                                                    "have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that "
                                                    "depth but needs it {} wider there (widen it, or make the pocket shallower)"),
                               w.first, w.width, w.ax, w.ay, w.bx, w.by, q(why->depth), passing, reaching,
                               q(2.0 * neededRadius - n.width));
        } else {
            text = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "the gap between the island {} and {} is {} wide at ({}, {}): the end mills that "
                                                    "pass there have flutes shorter than the depth {} (the longest-fluted, {}); {} "
                                                    "reaches that depth but needs {} there, {} more (widen the gap, or make the "
                                                    "pocket shallower)"),
                               w.first, w.second, w.width, w.ax, w.ay, q(why->depth), passing, reaching,
                               q(2.0 * neededRadius), q(2.0 * neededRadius - n.width));
        }
        it->field = w.field;
        it->message = std::move(text);
    }
}

check::UnitReport checkContourPocket(const ContourPocket& p, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, ContourPocket::kName, ctx, [&](Reporter& r, check::UnitReport& report) {
        const bool codes = checkCodes(p, r);
        const bool depth = checkDepthField(p.depth, r);
        check::checkStepOver(p.stepOver, r);
        const bool contours = checkContours(p, r);
        report.figureValid = contours;
        if (!codes || !depth || !contours || !ctx.tech) return;
        const ToolUse use = *toolUseFromCode(p.toolUse);
        if (!check::checkDepthAllowances(p.depth, *ctx.tech, false, hasRoughing(use) || hasFloorFinishing(use), r))
            return;
        checkRooms(p, p.reach, r);
    });
}

}  // namespace taiwa
