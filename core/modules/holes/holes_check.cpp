// Input checks of one HOLES unit: the pattern and hole kind known, every
// value finite and in range, the count bounded, the holes apart (more than
// a diameter between centres), inside the stock and, with their drill
// points, above its bottom (no through holes: no breakthrough is made),
// threads from the table only, the tool pins of the unit's steps.
#include "model/translate_noop.h"
#include "modules/holes/holes.h"

#include "check/check_unit.h"
#include "check/messages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

using check::Reporter;

constexpr double kMinDiameter = 1.0, kMaxDiameter = 100.0;  // mm
constexpr double kEps = 1e-9;

const std::vector<std::string> kPatterns{"single", "line", "grid", "bolt circle", "arc"};
const std::vector<std::string> kHoles{"drilled", "tapped", "reamed", "bored"};

std::string listed(const std::vector<std::string>& names)
{
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
    return s;
}

bool known(const std::string& v, const std::vector<std::string>& names)
{
    return std::find(names.begin(), names.end(), v) != names.end();
}

bool uses(const std::string& pattern, std::initializer_list<const char*> patterns)
{
    return std::any_of(patterns.begin(), patterns.end(), [&](const char* p) { return pattern == p; });
}

bool checkCount(const HolePattern& h, Reporter& r)
{
    bool ok = true;
    const auto bounded = [&](int n, const char* field, const char* what) {
        if (n < 1 || n > holes::kMaxHoles) {
            r.unit(field,
                   fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {} must be 1 to {}"), what, n, holes::kMaxHoles));
            ok = false;
        }
    };
    if (uses(h.pattern, {"line", "grid", "bolt circle", "arc"}))
        bounded(h.count, "count",
                h.pattern == "grid" ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the columns")
                                    : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the number of holes"));
    if (h.pattern == "grid")
        bounded(h.rows, "rows", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the rows"));
    if (ok && h.pattern == "grid" && static_cast<long>(h.count) * h.rows > holes::kMaxHoles) {
        r.unit("rows",
               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} columns by {} rows are {} holes, more than the {} a unit may have"),
                           h.count, h.rows, static_cast<long>(h.count) * h.rows, holes::kMaxHoles));
        ok = false;
    }
    return ok;
}

bool checkValues(const HolePattern& h, Reporter& r)
{
    bool ok = check::checkLength(h.x, "x", "x", r) && check::checkLength(h.y, "y", "y", r);
    if (!std::isfinite(h.angle) || std::abs(h.angle) > 360.0) {
        r.unit("angle",
               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the angle {} must be from -360° to 360°"), msg::quoteDeg(h.angle)));
        ok = false;
    }
    const auto positive = [&](double v, const char* field, const char* what) {
        if (!check::checkLength(v, field, what, r)) return ok = false;
        if (!(v > 0.0)) {
            r.unit(field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} {} must be greater than zero"), what,
                                      msg::quote(r.len(v))));
            return ok = false;
        }
        return true;
    };
    if (uses(h.pattern, {"line", "grid"}) && (h.count > 1 || h.pattern == "line"))
        positive(h.pitch, "pitch", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the pitch"));
    if (h.pattern == "grid" && h.rows > 1)
        positive(h.pitchY, "pitchY", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the pitch between rows"));
    if (uses(h.pattern, {"bolt circle", "arc"}))
        positive(h.radius, "radius", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the radius"));
    if (h.pattern == "arc" && (!std::isfinite(h.angularPitch) || h.angularPitch == 0.0 || std::abs(h.angularPitch) >= 360.0)) {
        r.unit("angularPitch",
               fmt::format(
                   TAIWA_TRANSLATE_NOOP("taiwa::msg", "the angular pitch {:g}° must not be 0 and lie within ±360°"),
                   h.angularPitch));
        ok = false;
    }
    if (h.hole == "tapped") {
        if (!holes::findThread(h.thread)) {
            std::string sizes;
            for (const auto& t : holes::threadTable()) sizes += (sizes.empty() ? "" : ", ") + std::string(t.name);
            r.unit("thread",
                   fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "thread \"{}\" is not one this program taps: ISO metric coarse {}"),
                               h.thread, sizes));
            ok = false;
        }
        if (h.diameter != 0.0) {
            r.unit("diameter", TAIWA_TRANSLATE_NOOP(
                                   "taiwa::msg", "a tapped hole's diameter is its thread's: leave out \"diameter\""));
            ok = false;
        }
    } else {
        if (!h.thread.empty()) {
            r.unit("thread", "only a tapped hole has a thread; the hole is " + h.hole);
            ok = false;
        }
        if (positive(h.diameter, "diameter", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the diameter")) &&
            (h.diameter < kMinDiameter || h.diameter > kMaxDiameter)) {
            r.unit("diameter", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the diameter {} must be {} to {}"),
                                           msg::quote(r.len(h.diameter)), msg::quote(r.len(kMinDiameter)),
                                           msg::quote(r.len(kMaxDiameter))));
            ok = false;
        }
    }
    if (check::checkLength(h.depth, "depth", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth"), r) && !(h.depth > 0.0)) {
        r.unit("depth", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the depth {} must be greater than zero"),
                                    msg::quote(r.len(h.depth))));
        ok = false;
    }
    return ok;
}

// Holes closer than a diameter cut into each other: the pattern's own
// spacing first (on its field), then any pair (an arc closing on itself).
bool checkApart(const HolePattern& h, const std::vector<Point2>& at, double diameter, Reporter& r)
{
    const auto tooClose = [&](double spacing, const char* field, const char* what) {
        if (spacing > diameter + kEps) return false;
        r.unit(field,
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "{} {} is not more than the hole's diameter {}: the holes would cut into each other"),
                           what, msg::quote(r.len(spacing)), msg::quote(r.len(diameter))));
        return true;
    };
    if (uses(h.pattern, {"line", "grid"}) && h.count > 1 &&
        tooClose(h.pitch, "pitch", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the pitch")))
        return false;
    if (h.pattern == "grid" && h.rows > 1 &&
        tooClose(h.pitchY, "pitchY", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the pitch between rows")))
        return false;
    if (h.pattern == "bolt circle" && h.count > 1 &&
        tooClose(2 * h.radius * std::sin(std::numbers::pi / h.count), "count",
                 TAIWA_TRANSLATE_NOOP("taiwa::msg", "the distance between neighbouring holes")))
        return false;
    if (h.pattern == "arc" && h.count > 1 &&
        tooClose(2 * h.radius * std::sin(std::abs(h.angularPitch) * std::numbers::pi / 360.0), "angularPitch",
                 TAIWA_TRANSLATE_NOOP("taiwa::msg", "the distance between neighbouring holes")))
        return false;
    if (!uses(h.pattern, {"arc"})) return true;
    for (std::size_t i = 0; i < at.size(); ++i)
        for (std::size_t j = i + 1; j < at.size(); ++j)
            if (distance(at[i], at[j]) <= diameter + kEps) {
                r.unit("count",
                       fmt::format(TAIWA_TRANSLATE_NOOP(
                                       "taiwa::msg",
                                       "holes {} and {} lie {} apart, not more than the diameter {}: the arc closes on "
                                       "itself; fewer holes or a smaller angular pitch"),
                                   i + 1, j + 1, msg::quote(r.len(distance(at[i], at[j]))),
                                   msg::quote(r.len(diameter))));
                return false;
            }
    return true;
}

bool checkStock(const HolePattern& h, const std::vector<Point2>& at, double diameter, Reporter& r)
{
    const Stock* st = r.ctx.stock;
    if (!st) return true;
    const double rad = diameter / 2.0;
    for (std::size_t i = 0; i < at.size(); ++i) {
        const Point2 p = at[i];
        if (p.x - rad < st->x - kEps || p.y - rad < st->y - kEps || p.x + rad > st->x + st->width + kEps ||
            p.y + rad > st->y + st->length + kEps) {
            r.unit(h.pattern == "single" ? "x" : "pattern",
                   fmt::format(
                       TAIWA_TRANSLATE_NOOP(
                           "taiwa::msg",
                           "hole {} (X {}, Y {}) reaches outside the stock; move the pattern or enlarge the stock"),
                       i + 1, msg::quote(r.len(p.x)), msg::quote(r.len(p.y))));
            return false;
        }
    }
    const double lowest = holes::lowestPoint(h);
    if (lowest > st->height + kEps) {
        r.unit("depth",
               fmt::format(TAIWA_TRANSLATE_NOOP(
                               "taiwa::msg",
                               "the hole goes down to {} with its drill point (its tools go deeper than the depth {}; "
                               "docs/holes.md), below the stock's height {}: through holes are not made; make it "
                               "shallower"),
                           msg::quote(r.len(lowest)), msg::quote(r.len(h.depth)), msg::quote(r.len(st->height))));
        return false;
    }
    return true;
}

// Pins of a step this kind of hole does not have. A key no hole has, or a
// tool not in the library, is check::checkPins's (the door runs it).
void checkPins(const HolePattern& h, int unitNo, Diagnostics& out)
{
    const auto keys = holes::stepKeys(h.hole);
    const auto all = holes::allStepKeys();
    for (const auto& [key, id] : h.tools)
        if (std::find(keys.begin(), keys.end(), key) == keys.end() && std::find(all.begin(), all.end(), key) != all.end())
            out.push_back({Severity::Error, unitNo, HolePattern::kName, "tools." + key,
                           fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a {} hole has no step \"{}\"; its steps are {}"),
                                       h.hole, key, listed(keys))});
}

}  // namespace

check::UnitReport checkHolePattern(const HolePattern& h, int unitNo, const check::Context& ctx)
{
    return check::checkUnit(unitNo, HolePattern::kName, ctx, [&](Reporter& r, check::UnitReport& report) {
        bool ok = true;
        if (!known(h.pattern, kPatterns)) {
            r.unit("pattern", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "pattern \"{}\" is not one of {}"), h.pattern,
                                          listed(kPatterns)));
            ok = false;
        }
        if (!known(h.hole, kHoles)) {
            r.unit("hole",
                   fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "hole \"{}\" is not one of {}"), h.hole, listed(kHoles)));
            ok = false;
        }
        if (!ok) return;
        checkPins(h, unitNo, report.diagnostics);
        ok = checkCount(h, r);
        ok = checkValues(h, r) && ok;
        if (!ok) return;
        const std::vector<Point2> at = holes::positions(h);
        const double diameter = holes::depths(h).finishDiameter;
        if (!checkApart(h, at, diameter, r)) return;
        report.figureValid = true;
        checkStock(h, at, diameter, r);
    });
}

}  // namespace taiwa
