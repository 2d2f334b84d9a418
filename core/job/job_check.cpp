// Input processing of a whole job: the job-level checks (material, stock,
// technology overrides), every unit's checks through its module's door and
// the interference check, collecting all diagnostics (capped);
// jobTechnology gives the technology data in force.
#include "job/job_check.h"
#include "model/technology_ranges.h"
#include "job/figure_contours.h"
#include "model/translate_noop.h"

#include "check/messages.h"
#include "check/unit_checks.h"
#include "io/job_messages.h"
#include "machine/machine.h"
#include "modules/registry.h"
#include "post/dialect.h"
#include "post/post.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {


Diagnostic jobError(std::string field, std::string message)
{
    return {Severity::Error, std::nullopt, "", std::move(field), std::move(message)};
}

// The largest stock side: a part for this station, and every cell, layer and
// pass count bounded.
constexpr double kMaxStockSide = 10'000.0;  // mm

// Stock origin within reach, dimensions positive and at most kMaxStockSide;
// returns whether the stock is usable.
bool checkStock(const Stock& mm, LengthUnit shown, Diagnostics& out)
{
    bool ok = true;
    const std::pair<const char*, double> origin[] = {{"x", mm.x}, {"y", mm.y}};
    for (const auto& [key, v] : origin) {
        if (std::isfinite(v) && std::abs(v) <= check::kMaxLength) continue;
        out.push_back(jobError(std::string("stock.") + key,
                               std::isfinite(v) ? msg::beyondReach(std::string("the stock ") + key, {v, shown}, {check::kMaxLength, shown})
                                                : msg::notFinite(std::string("the stock ") + key)));
        ok = false;
    }
    const std::pair<const char*, double> sizes[] = {{"width", mm.width}, {"length", mm.length}, {"height", mm.height}};
    for (const auto& [key, v] : sizes) {
        const std::string field = std::string("stock.") + key;
        if (!std::isfinite(v)) out.push_back(jobError(field, msg::notFinite("the stock " + std::string(key)))), ok = false;
        else if (v <= 0.0) out.push_back(jobError(field, msg::stockNotPositive(key, {v, shown}))), ok = false;
        else if (v > kMaxStockSide) out.push_back(jobError(field, msg::stockTooLarge(key, {v, shown}, {kMaxStockSide, shown}))), ok = false;
    }
    return ok;
}

// A bar: diameter and length positive and within kMaxStockSide, the face
// stock not negative and shorter than the bar, a bore narrower than the bar,
// and a bar the lathe's spindle takes.
bool checkBar(const BarStock& mm, const Machine* machine, LengthUnit shown, Diagnostics& out)
{
    bool ok = true;
    const std::pair<const char*, double> sizes[] = {{"diameter", mm.diameter}, {"length", mm.length}};
    for (const auto& [key, v] : sizes) {
        const std::string field = std::string("stock.") + key;
        if (!std::isfinite(v)) out.push_back(jobError(field, msg::notFinite("the bar " + std::string(key)))), ok = false;
        else if (v <= 0.0) out.push_back(jobError(field, msg::stockNotPositive(key, {v, shown}))), ok = false;
        else if (v > kMaxStockSide) out.push_back(jobError(field, msg::stockTooLarge(key, {v, shown}, {kMaxStockSide, shown}))), ok = false;
    }
    if (!ok) return false;
    if (!std::isfinite(mm.face) || mm.face < 0.0 || mm.face >= mm.length)
        out.push_back(jobError("stock.face", "the face stock is " + msg::quote({mm.face, shown}) +
                                                 "; it must be at least 0 and shorter than the bar")),
            ok = false;
    if (!std::isfinite(mm.bore) || mm.bore < 0.0 || mm.bore >= mm.diameter)
        out.push_back(jobError("stock.bore", "the bar's bore is Ø" + msg::quote({mm.bore, shown}) +
                                                 "; it must be 0 (a solid bar) or narrower than the bar (Ø" +
                                                 msg::quote({mm.diameter, shown}) + ")")),
            ok = false;
    if (machine && machine->maxBarDiameter > 0.0 && mm.diameter > machine->maxBarDiameter)
        out.push_back(jobError("stock.diameter", "a bar of Ø" + msg::quote({mm.diameter, shown}) +
                                                     " does not pass the spindle of machine " + machine->id + " (Ø" +
                                                     msg::quote({machine->maxBarDiameter, shown}) + " at most)")),
            ok = false;
    return ok;
}

// The vice's jaws: a height above 0 and, on a usable block, below its top,
// so that the top face and what is cut from it stand clear of the jaws.
void checkClamping(const Clamping& mm, const Stock* stock, LengthUnit shown, Diagnostics& out)
{
    if (!std::isfinite(mm.height))
        out.push_back(
            jobError("clamping.height", msg::notFinite(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the jaws' height"))));
    else if (mm.height <= 0.0)
        out.push_back(jobError("clamping.height", "the jaws' height is " + msg::quote({mm.height, shown}) +
                                                      "; the vice must grip the block: give a height above 0"));
    else if (stock && mm.height >= stock->height)
        out.push_back(jobError("clamping.height", "the jaws reach " + msg::quote({mm.height, shown}) +
                                                      " up the block, its top or beyond (the stock is " +
                                                      msg::quote({stock->height, shown}) +
                                                      " high): the top must stand out of the vice"));
}

// The technology values in force, each within a range that keeps the work
// bounded (γ sets the layer count, the allowances the passes):
// docs/input-checks.md. α1 to γ as the shipped table's reader reads them
// (model/technology_ranges.h), then the step-over.
constexpr TechnologyRange kStepOverRange{"stepOver", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the step-over"),
                                         check::kStepOverLow, check::kStepOverHigh, check::kStepOverWhy};

// Overrides finite and within their ranges (lengths quoted in the job's unit, gamma as is).
bool checkOverrides(const TechnologyOverrides& mm, LengthUnit shown, Diagnostics& out)
{
    bool ok = true;
    const std::optional<double> values[] = {mm.alpha1, mm.alpha2, mm.alpha3, mm.beta2, mm.gamma, mm.stepOver};
    for (std::size_t i = 0; i < std::size(values); ++i) {
        const auto& v = values[i];
        const TechnologyRange& range = i < std::size(kTechnologyRanges) ? kTechnologyRanges[i] : kStepOverRange;
        if (!v) continue;
        const std::string field = std::string("technology.") + range.key;
        const bool isGamma = std::string(range.key) == "gamma" || std::string(range.key) == "stepOver";  // factors
        const auto shownOf = [&](double x) { return isGamma ? x : fromMm(x, shown); };
        const std::string unitText = isGamma ? "" : std::string(" ") + unitSymbol(shown);
        if (!std::isfinite(*v)) out.push_back(jobError(field, msg::notFinite(range.name))), ok = false;
        else if (*v <= 0.0)
            out.push_back(jobError(field, msg::technologyNotPositive(range.name, shownOf(*v), unitText))), ok = false;
        else if (*v < range.low || *v > range.high)
            out.push_back(jobError(field, msg::technologyOutOfRange(range.name, shownOf(*v), shownOf(range.low),
                                                                     shownOf(range.high), unitText, range.why))),
                ok = false;
    }
    return ok;
}

// The operator's speeds and feeds: keys of the module's steps, S and F
// positive and within the machine (S as rpm up to its spindle limit, or a
// surface speed; F per minute up to its feed limit, or per revolution).
void checkCutting(const std::map<std::string, CuttingOverride>& cutting, const ModuleKind& kind, int unitNo,
                  const Machine* machine, LengthUnit shown, Diagnostics& out)
{
    if (cutting.empty()) return;
    const std::vector<std::string> keys = kind.stepKeys();
    const auto error = [&](const std::string& field, const std::string& message) {
        out.push_back({Severity::Error, unitNo, kind.name(), field, message});
    };
    if (keys.empty()) {
        error("cutting", msg::noCuttingSteps(kind.name()));
        return;
    }
    const bool lathe = kind.machineKind() == MachineKind::Lathe;
    const double maxRpm = machine && machine->maxSpindleSpeed > 0 ? machine->maxSpindleSpeed : 100000.0;
    const double maxFeed = machine && machine->maxFeed > 0 ? machine->maxFeed : 100000.0;
    const std::string length = unitSymbol(shown);
    for (const auto& [key, c] : cutting) {
        const std::string field = "cutting." + key;
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
            error(field, msg::unknownStepKey(key, kind.name(), keys));
            continue;
        }
        if (c.speed) {
            const bool vc = kind.surfaceSpeedStep(key);
            const double high = vc ? 2000.0 : maxRpm;
            if (!std::isfinite(*c.speed) || *c.speed < 1.0 || *c.speed > high)
                error(field + ".S",
                      msg::cuttingValueOutOfRange(vc ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface speed S")
                                                     : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the spindle speed S"),
                                                  *c.speed, vc ? "m/min" : "rpm", 1.0, high,
                                                  vc        ? ""
                                                  : machine ? " (the spindle limit of " + machine->id + ")"
                                                            : ""));
        }
        if (c.feed) {
            // Per revolution on a lathe (at most 5 mm), per minute on a mill up to the machine's feed.
            const double low = lathe ? 0.001 : 1.0, high = lathe ? 5.0 : maxFeed;
            if (!std::isfinite(*c.feed) || *c.feed < low || *c.feed > high)
                error(field + ".F", msg::cuttingValueOutOfRange(
                                        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the feed F"), fromMm(*c.feed, shown),
                                        length + (lathe ? "/rev" : "/min"), fromMm(low, shown), fromMm(high, shown),
                                        lathe || !machine ? "" : " (the feed limit of " + machine->id + ")"));
        }
    }
}

// The two-path settings (docs/two-path-lathe.md): a dwell of at least half
// a revolution whatever the machine; settings other than the defaults only
// on a two-path lathe, with a first wait code the machine offers.
void checkTwoPath(const TwoPathSettings& t, const Machine* machine, Diagnostics& out)
{
    if (!(t.dwellRevolutions >= 0.5) || !std::isfinite(t.dwellRevolutions))
        out.push_back(jobError("twoPath.dwellRevolutions",
                               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                "the follower's dwell is {:g} spindle revolutions; it must be "
                                                                "at least 0.5, or the follower cuts where the leader has not"),
                                           t.dwellRevolutions)));
    if (!machine || t == TwoPathSettings{}) return;
    if (!machine->layout.multiPath) {
        std::string twoPath;
        for (const auto& id : machineIds())
            if (const Machine* m = findMachine(id); m && m->layout.multiPath) twoPath += (twoPath.empty() ? "" : ", ") + id;
        out.push_back(jobError("twoPath", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                           "machine {} has one path; the two-path settings are "
                                                                           "for a two-path lathe ({})"),
                                                      machine->id, twoPath)));
        return;
    }
    const WaitCodeRange& codes = machine->layout.multiPath->waitCodes;
    if (t.firstWait && !codes.contains(*t.firstWait))
        out.push_back(jobError("twoPath.firstWait",
                               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                "M{} is not a wait code of machine {}: it waits with M{} to M{}"),
                                           *t.firstWait, machine->id, codes.first, codes.last)));
}

// The job's work offset (one some controller has: whether the chosen one has
// it, G54.1 P on FANUC or G59.1-G59.3 on LinuxCNC, is known only at export)
// and its own dialect, if it names one: one this program posts, whose
// controller has the work offset and writes the tape the job needs.
void checkOffsetAndDialect(const Job& job, const Job& mm, const Machine* machine, Diagnostics& out)
{
    const bool lathe = machine && machine->kind == MachineKind::Lathe;
    const auto names = dialectNames();
    if (std::all_of(names.begin(), names.end(), [&](const std::string& d) { return workOffsetProblem(d, job.workOffset); }))
        out.push_back(jobError("workOffset",
                               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                "'{}' is not a work offset: give G54 to G59, G59.1 to G59.3, "
                                                                "G54.1 P1 to P48 (G154 P on Haas) or G505 to G599 (SINUMERIK)"),
                                           job.workOffset)));
    // The job's own dialect: one this program posts, whose controller has the
    // job's work offset.
    else if (!job.dialect.empty()) {
        if (!isDialect(job.dialect)) {
            std::string known;
            for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
            out.push_back(jobError(
                "dialect", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "unknown dialect '{}'; this program posts {}"),
                                       job.dialect, known)));
        } else if (auto why = workOffsetProblem(job.dialect, job.workOffset)) {
            out.push_back(*why);
        } else if (const post::Dialect* d = post::findDialect(job.dialect)) {
            // Lathe tapes and probing cycles are written in the G-code dialects.
            const bool probing = std::any_of(mm.units.begin(), mm.units.end(), [](const auto& u) {
                const ModuleKind* k = findModuleKind(u.module.name());
                return k && k->setsWorkOffset();
            });
            if (auto can = post::canPost(*d, post::taskOf(lathe, probing)); !can)
                out.push_back(jobError("dialect", can.error()));
            // A two-path lathe's programs: the ISO dialects' waits (docs/two-path-lathe.md).
            else if (lathe && machine->layout.multiPath && d->syntax != post::Syntax::Iso)
                out.push_back(jobError(
                    "dialect", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the {} dialect writes no two-path programs; "
                                                                              "machine {} needs one of the ISO dialects"),
                                           d->name, machine->id)));
        }
    }
}

}  // namespace

std::optional<TechnologyData> jobTechnology(const Job& mmJob, const TechnologyTable& table)
{
    const MaterialTechnology* m = table.find(mmJob.material);
    if (!m) return std::nullopt;
    return effective(m->data, mmJob.technology);
}

CheckedJob checkedJob(Job typed, const TechnologyTable& table, const std::vector<Tool>& library)
{
    CheckedJob c;
    c.mmJob = toMillimetres(typed);
    c.job = std::move(typed);
    const Job& job = c.job;
    const Job& mm = c.mmJob;
    const LengthUnit shown = job.lengthUnit;
    Diagnostics& out = c.diagnostics;
    resolveContours(c.mmJob, figureContours(job, out));

    std::optional<TechnologyData> tech = jobTechnology(mm, table);
    if (!tech) {
        std::vector<std::string> known;
        for (const auto& m : table.materials()) known.push_back(m.id);
        out.push_back(jobError("material", msg::unknownMaterial(job.material, known)));
    }
    if (!checkOverrides(mm.technology, shown, out)) tech.reset();
    // The machine: one of the library's, with the stock its kind takes.
    const Machine* machine = findMachine(job.machine);
    if (!machine) {
        std::string known;
        for (const auto& id : machineIds()) known += (known.empty() ? "" : ", ") + id;
        out.push_back(jobError("machine", "unknown machine '" + job.machine + "'; the machine library has " + known));
    }
    const bool lathe = machine && machine->kind == MachineKind::Lathe;
    bool stockOk = false, barOk = false;
    if (mm.bar) {
        barOk = checkBar(*mm.bar, machine, shown, out);
        if (machine && !lathe)
            out.push_back(jobError("stock.shape", "a bar is stock for a lathe; machine " + machine->id +
                                                      " mills a block: give \"shape\": \"block\" or a lathe")),
                barOk = false;
    } else {
        stockOk = checkStock(mm.stock, shown, out);
        if (lathe)
            out.push_back(jobError("stock.shape", "machine " + machine->id + " is a lathe: its stock is a bar "
                                                  "(\"shape\": \"bar\" with its diameter and length)"));
    }
    checkTwoPath(mm.twoPath, machine, out);
    if (mm.clamping) {
        if (mm.bar || lathe)
            out.push_back(jobError("clamping", "a lathe holds its bar in the chuck; the clamping is for a block in a vice"));
        else
            checkClamping(*mm.clamping, stockOk ? &mm.stock : nullptr, shown, out);
    }
    checkOffsetAndDialect(job, mm, machine, out);

    const check::Context ctx{shown, tech, stockOk ? &mm.stock : nullptr, &library, barOk ? &*mm.bar : nullptr};
    std::vector<check::UnitFigure> figures;
    for (std::size_t u = 0; u < mm.units.size(); ++u) {
        const int unitNo = static_cast<int>(u) + 1;
        const ModuleInput& module = mm.units[u].module;
        const ModuleKind* kind = findModuleKind(module.name());
        if (!kind) {  // a unit being built in the station: no module yet
            out.push_back({Severity::Error, unitNo, module.name(), "module", msg::io::unknownModule(module.name(), moduleNames())});
            continue;
        }
        if (machine && kind->machineKind() != machine->kind) {
            out.push_back({Severity::Error, unitNo, module.name(), "module",
                           std::string("module ") + module.name() + " runs on a " + toKey(kind->machineKind()) +
                               "; this job's machine " + machine->id + " is a " + toKey(machine->kind)});
            continue;
        }
        checkCutting(mm.units[u].cutting, *kind, unitNo, machine, shown, out);
        auto report = kind->check(module, unitNo, ctx);
        out.insert(out.end(), report.diagnostics.begin(), report.diagnostics.end());
        if (report.turned) {
            // Sized at the first turning unit: a milling job of 100,000
            // units kept 17.6 MB of empty entries through its planning.
            if (c.turned.empty()) c.turned.resize(mm.units.size());
            c.turned[u] = std::move(report.turned);
        }
        if (!report.figureValid) continue;
        if (const auto outline = kind->topOutline(module))
            figures.push_back({static_cast<int>(u), kind->name(), kind->outlineField(), *outline, kind->topPolygon(module)});
    }
    const Diagnostics overlaps = check::interferences(std::move(figures), shown);
    out.insert(out.end(), overlaps.begin(), overlaps.end());

    // A job-level finding several units make (α3 against α2) is said once.
    std::vector<std::pair<std::string, std::string>> seen;
    std::erase_if(out, [&](const Diagnostic& d) {
        if (d.unit) return false;
        const std::pair<std::string, std::string> key{d.field, d.message};
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) return true;
        seen.push_back(key);
        return false;
    });
    out = capped(std::move(out));
    if (!hasErrors(out)) c.technology = tech;
    return c;
}

Diagnostics checkJob(const Job& job, const TechnologyTable& table, const std::vector<Tool>& library)
{
    return checkedJob(job, table, library).diagnostics;
}

std::vector<int> machiningOrder(const Job& mmJob)
{
    std::vector<Point2> centres;
    std::vector<int> units;
    for (std::size_t u = 0; u < mmJob.units.size(); ++u) {
        const auto& module = mmJob.units[u].module;
        if (const auto outline = moduleKind(module).topOutline(module)) {
            centres.push_back(centroid(outline->corners));
            units.push_back(static_cast<int>(u));
        }
    }
    std::vector<int> order;
    for (const int k : check::machiningOrder(centres)) order.push_back(units[static_cast<std::size_t>(k)]);
    // Units without a figure in the XY plane keep their place after those with one.
    std::vector<bool> placed(mmJob.units.size(), false);
    for (const int u : units) placed[static_cast<std::size_t>(u)] = true;
    for (std::size_t u = 0; u < mmJob.units.size(); ++u)
        if (!placed[u]) order.push_back(static_cast<int>(u));
    return order;
}

}  // namespace taiwa
