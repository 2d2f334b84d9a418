// The wording of every input-processing message (see messages.h).
#include "check/messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace taiwa::msg {

namespace {
// Fixed decimals with trailing zeros trimmed and no "-0".
std::string trimmed(double v, int decimals)
{
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}
}  // namespace

std::string quote(Len v)
{
    const double shown = fromMm(v.mm, v.unit);
    std::string text = trimmed(shown, v.unit == LengthUnit::Inch ? 4 : 3);
    // A value too small for the usual decimals is not "0": its significant digits.
    if (shown != 0.0 && (text == "0" || text == "-0")) text = fmt::format("{:g}", shown);
    return text + " " + unitSymbol(v.unit);
}

std::string quoteDeg(double deg) { return trimmed(deg, 3) + "°"; }

std::string toolName(const Tool& t)
{
    if (t.type == ToolType::TurningInsert && !t.turning.insertCode.empty())  // inserts by their code and nose
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} {}, nose R{} mm)"), t.id, toString(t.type),
                           t.turning.insertCode, trimmed(t.cornerRadius, 3));
    if (t.type == ToolType::TaperEndMill)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} Ø{} mm, {} per side)"), t.id, toString(t.type),
                           trimmed(t.diameter, 3), quoteDeg(t.taperAngle));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "T{} ({} Ø{} mm)"), t.id, toString(t.type),
                       trimmed(t.diameter, 3));
}

std::string notFinite(const std::string& what)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a finite number; type a number"), what);
}

std::string unknownMaterial(const std::string& id, const std::vector<std::string>& known)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "material \"{}\" is not in the technology table; known materials: {}"), id,
        fmt::join(known, ", "));
}

std::string stockNotPositive(const std::string& what, Len v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the stock {} is {}; it must be greater than zero"), what,
                       quote(v));
}

std::string technologyNotPositive(const std::string& name, double shownValue, const std::string& unitText)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} = {}{} must be greater than zero"), name,
                       trimmed(shownValue, 4), unitText);
}

std::string alpha3NotBelowAlpha2(Len a3, Len a2)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the final wall allowance α3 = {} must be smaller than the roughing wall allowance α2 = {}"),
        quote(a3), quote(a2));
}

std::string alpha1NotBelowDepth(int unitNo, Len a1, Len depth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the pilot-hole remainder α1 = {} is not smaller than the depth {} of unit {}: "
                             "the pilot hole would have no depth; use H = 9 or a smaller α1"),
        quote(a1), quote(depth), unitNo);
}

std::string beta2NotBelowDepth(int unitNo, Len b2, Len depth)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "the floor allowance β2 = {} is not smaller than the depth {} of unit {}: "
                                            "roughing would not cut at all"),
                       quote(b2), quote(depth), unitNo);
}

std::string beyondReach(const std::string& what, Len value, Len limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} is {}; every length and coordinate must lie within ±{} of the origin (beyond it a "
                             "micrometre is no longer exact on the tape)"),
        what, quote(value), quote(limit));
}

std::string technologyOutOfRange(const std::string& name, double shownValue, double low, double high,
                                 const std::string& unitText, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is {:g}{}; it must lie between {:g} and {:g}{} ({})"),
                       name, shownValue, unitText, low, high, unitText, why);
}

std::string scallopTooSmall(Len scallop, Len smallest)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "the scallop height is {}; it must be at least {} (a smaller one multiplies the passes of the "
            "inclined faces without a finer surface any machine holds)"),
        quote(scallop), quote(smallest));
}

std::string stockTooLarge(const std::string& key, Len value, Len limit)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the stock {} is {}; a stock of more than {} a side is not a part for this station"),
        key, quote(value), quote(limit));
}

std::string depthNotPositive(Len depth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the depth is {}; it must be greater than zero (measured down from the top face)"),
        quote(depth));
}

std::string deeperThanStock(Len depth, Len stockHeight)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth {} is deeper than the stock, which is {} high"),
                       quote(depth), quote(stockHeight));
}

std::string lengthNotPositive(const std::string& name, Len v)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is {}; it must be greater than zero"), name, quote(v));
}

std::string radiusNegative(Len r1)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius is {}; it cannot be negative"), quote(r1));
}

std::string outsideStock(const std::string& figure)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} reaches outside the stock; move it or enlarge the stock"), figure);
}

std::string duplicateCorner(int first, int second, Len x, Len y)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "P{} and P{} are the same point ({}, {}); the outline needs four distinct corners"),
        first, second, quote(x), quote(y));
}

std::string pointsUnreadable(const std::string& typed)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "'{}' is not a list of points; type each point as X, Y and separate the points with ';' "
                             "(10, 20; 60, 20), or draw the passes in the Figure tab"),
        typed);
}

std::string tooFewPoints(std::size_t count)
{
    if (count == 0)
        return TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "no point is drawn; a pass runs from a start point to an end point: draw at least two points");
    return TAIWA_TRANSLATE_NOOP(
        "taiwa::msg",
        "only one point is drawn; a pass runs from a start point to an end point: draw at least two points");
}

std::string pointOutsideStock(std::size_t index, Len x, Len y)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {} ({}, {}) lies outside the stock"), index, quote(x),
                       quote(y));
}

std::string passSamePoint(int pass)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pass {} ends where it starts; remove the repeated point"),
                       pass);
}

std::string passLeavesArea(int pass, Len x, Len y, Len by, const std::string& outline)
{
    if (pass == 0)
        return fmt::format(
            TAIWA_TRANSLATE_NOOP(
                "taiwa::msg", "the start point ({}, {}) puts the tool's edge {} outside the area {} or into an island; "
                              "start at least a tool radius inside"),
            quote(x), quote(y), quote(by), outline);
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "pass {} takes the tool's edge {} outside the area {} (or into an island) with the tool's centre "
            "at ({}, {}); keep each pass a tool radius from the walls"),
        pass, quote(by), outline, quote(x), quote(y));
}

std::string diameterNotPositive(Len d)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the tool diameter is {}; it must be positive: the passes are strips one tool wide"),
        quote(d));
}

std::string noToolOfDiameter(Len d, const std::vector<double>& diametersMm, LengthUnit unit)
{
    std::vector<std::string> shown;
    for (const double v : diametersMm) shown.push_back(quote({v, unit}));
    if (shown.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP(
                "taiwa::msg",
                "the library has no centre-cutting flat end mill of {} (nor of any diameter) for the drawn "
                "passes"),
            quote(d));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "the library has no centre-cutting flat end mill of {}, the width the passes were drawn for; "
                          "its flat end mills: {}"),
        quote(d), fmt::join(shown, ", "));
}

std::string pinnedDiameterDiffers(const Tool& pinned, Len d)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} is pinned, but the passes were drawn for a tool of {}; pin a tool of that diameter or "
                             "change the diameter and redraw"),
        toolName(pinned), quote(d));
}

std::string unswept(double areaMm2, int pieces, double largestMm2, Len x, Len y, LengthUnit unit)
{
    const double f = unit == LengthUnit::Inch ? 1.0 / (25.4 * 25.4) : 1.0;
    const char* u = unit == LengthUnit::Inch ? "in²" : "mm²";
    const int decimals = unit == LengthUnit::Inch ? 4 : 1;
    const std::string area = fmt::format("{:.{}f} {}", areaMm2 * f, decimals, u);
    const std::string largest = fmt::format("{:.{}f} {}", largestMm2 * f, decimals, u);
    if (pieces == 1)
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                 "the passes leave {} of the area unswept in {} place; the largest, {}, near ({}, {})"),
            area, pieces, largest, quote(x), quote(y));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the passes leave {} of the area unswept in {} places; the largest, {}, near ({}, {})"),
        area, pieces, largest, quote(x), quote(y));
}

std::string contourNotNamed(const std::string& role)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "name the contour of the pocket's {} (a CONTOUR of the job's figure elements)"),
        role);
}

std::string contourUnknown(const std::string& name, const std::vector<std::string>& known)
{
    if (known.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                 "{} is not a contour of the job's figure elements, which define no contour"),
            name);
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a contour of the job's figure elements (its contours: {})"), name,
        fmt::join(known, ", "));
}

std::string contourOpen(const std::string& name, const std::string& what, const std::string& role)
{
    if (what.starts_with("a"))
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} is an open contour; an {}'s {} must be closed (a contour "
                                                "without a start and end point)"),
                           name, what, role);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is an open contour; a {}'s {} must be closed (a contour "
                                                          "without a start and end point)"),
                       name, what, role);
}

std::string contourCrossesItself(const std::string& name)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} crosses itself; check the order of its elements and the side chosen at each junction"),
        name);
}

std::string islandOutside(const std::string& island, const std::string& what, const std::string& outline)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the island {} reaches outside the {}'s outline {}"), island,
                       what, outline);
}

std::string islandsOverlap(const std::string& a, const std::string& b)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the islands {} and {} overlap; make them one contour"), a,
                       b);
}

std::string sharpInsideCorner(const std::string& name, Len x, Len y)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "{} has a sharp inside corner at ({}, {}): an end mill cannot cut it and leaves its own radius "
            "there; round the corner (ROUND) in the contour"),
        name, quote(x), quote(y));
}

std::string toolUseNotForContours(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "U {} is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 (walls "
                          "only) or 9 (roughing only)"),
        code);
}

std::string selfIntersecting()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "the outline crosses itself; enter the corners P1..P4 in order around the pocket");
}

std::string notConvex()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "the outline is not convex (a corner points inward or three corners are in line)");
}

std::string radiusOverHalfSide(Len r1, Len shortestSide)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius {} is larger than half the shortest side ({} long)"),
        quote(r1), quote(shortestSide));
}

std::string radiusOverInscribed(Len r1, Len inscribed)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the corner radius {} does not fit: the largest circle inside the outline has radius {}"),
        quote(r1), quote(inscribed));
}

std::string radiusOverHalfL2(Len r1, Len l2)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the corner radius {} is larger than half of L2 = {}"),
                       quote(r1), quote(l2));
}

std::string taperOutOfRange(double taper)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the taper {} per side is outside 0° to 30°"),
                       quoteDeg(taper));
}

std::string taperClosesPocket(double taper, Len meetDepth)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "with a taper of {} per side the walls meet at depth {}, above the floor"),
        quoteDeg(taper), quote(meetDepth));
}

std::string thetaOutOfRange(const std::string& name, double theta)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} = {} is outside 0° to under 60° (measured from the vertical)"), name,
        quoteDeg(theta));
}

std::string floorVanishes(Len floorWidth, Len needed, Len shortBy)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the inclined walls leave a floor {} wide along L1; it must be wider than 2 × r1 = {} "
                             "(short by {}): reduce the angles or the depth, or lengthen L1"),
        quote(floorWidth), quote(needed), quote(shortBy));
}

std::string scallopNotPositive(Len scallop)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the scallop height is {}; it must be greater than zero (usual 0.01 mm)"),
        quote(scallop));
}

std::string toolUseUndefined(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "tool-use code U = {} is not defined (codes 2 to 5 are reserved); use 1, 6, 7, 8 or 9"),
        code);
}

std::string toolUseUnknown(int code)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool-use code U = {} does not exist; use 1, 6, 7, 8 or 9"),
                       code);
}

std::string toolUseNotForM2D(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "tool-use code U = {} is not allowed for M2D; use 1 (rough and finish) or 9 (rough only)"),
        code);
}

std::string wallFinishUnknown(int code)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "finishing code F = {} does not exist; use 1, 2 or 3"), code);
}

std::string pilotHoleUnknown(int code)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "pilot-hole code H = {} does not exist; use 0 (drill a pilot hole) or 9 (none)"),
        code);
}

std::string unknownPinKey(const std::string& key)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg", "\"{}\" is not a step kind; tools can be pinned for pilot, roughing, floor, wall, inclined"),
        key);
}

std::string unknownCuttingKey(const std::string& key, const std::string& module, const std::vector<std::string>& keys)
{
    std::string list;
    for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "\"{}\" is not a step of module {}; its steps are {}"), key,
                       module, list);
}

std::string noCuttingSteps(const std::string& module)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "module {} has no cutting steps to set a speed or feed for"),
                       module);
}

std::string cuttingValueOutOfRange(const std::string& what, double value, const std::string& unit, double low,
                                   double high, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {:g} {} is out of range: give {:g} to {:g} {}{}"), what,
                       value, unit, low, high, unit, why);
}

std::string toolNotInLibrary(int id)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "tool T{} is not in the tool library"), id);
}

std::string noToolOfType(const std::string& typeName)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no {}; add one to machine this pocket"),
                       typeName);
}

std::string noTaperTool(double taper, const std::vector<double>& anglesInLibrary)
{
    std::vector<std::string> shown;
    for (const double a : anglesInLibrary) shown.push_back(quoteDeg(a));
    if (shown.empty())
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "no taper end mill of {} per side in the tool library (it has none)"),
            quoteDeg(taper));
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "no taper end mill of {} per side in the tool library (it has {})"),
        quoteDeg(taper), fmt::join(shown, ", "));
}

std::string noRoomForTool(const std::string& label, Len available, const Tool& smallest, Len neededR1)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "{} = {} is smaller than the radius of the smallest suitable tool, {}; "
                             "no tool of the library fits: a corner radius of at least {} would let it fit"),
        label, quote(available), toolName(smallest), quote(neededR1));
}

std::string pinnedToolTooBig(const std::string& step, const Tool& pinned, const std::string& label, Len available,
                             const Tool* fitting)
{
    const std::string hint =
        fitting ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} would fit"), toolName(*fitting))
                : std::string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no tool of that kind in the library fits"));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} tool {} is too big for {} = {}; {}"), step,
                       toolName(pinned), label, quote(available), hint);
}

std::string overlap(int unitNo, int otherUnitNo, double areaMm2, LengthUnit unit)
{
    const double shown = unit == LengthUnit::Inch ? areaMm2 / (kMillimetresPerInch * kMillimetresPerInch) : areaMm2;
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the figure of unit {} overlaps the figure of unit {} by {} {}²; figures of one job may "
                             "touch but not overlap"),
        unitNo, otherUnitNo, trimmed(shown, unit == LengthUnit::Inch ? 6 : 4), unitSymbol(unit));
}

std::string sideContourNotNamed()
{
    return TAIWA_TRANSLATE_NOOP(
        "taiwa::msg",
        "name the contour the side milling follows (a CONTOUR of the job's figure elements, open or closed)");
}

std::string sideCodeUnknown(const std::string& code, int value, const std::string& allowed)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {} is not a code of side milling; use {}"), code, value,
                       allowed);
}

std::string sideWidthNotAboveAllowance(Len width, Len alpha2)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg",
                             "the width W is {}; roughing leaves α2 = {} on the wall, so W must be larger than that"),
        quote(width), quote(alpha2));
}

std::string sidePinKeyUnknown(const std::string& key)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP(
            "taiwa::msg",
            "\"{}\" is not a step of side milling; pin its end mill under \"side\" (roughing and finishing)"),
        key);
}

std::string sideNoTool(const std::string& step, const std::string& why)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), step, why);
}

std::string sideChannelTooNarrow(const std::string& name, const std::string& tool, Len x, Len y)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP(
                           "taiwa::msg",
                           "{} does not fit where {} narrows near ({}, {}): the tool would cut into the contour there; "
                           "pin a smaller end mill or widen the channel"),
                       tool, name, quote(x), quote(y));
}

}  // namespace taiwa::msg
