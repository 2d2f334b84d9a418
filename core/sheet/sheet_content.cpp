// What the instruction sheet says, from a plan: formatted in the sheet's
// length unit, one row per step in machining order and one per tool.
#include "sheet/sheet_content.h"

#include "machine/machine.h"
#include "model/technology.h"
#include "model/turn_path.h"
#include "post/dialect.h"
#include "post/lathe_post.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <functional>

namespace taiwa::sheet {

namespace {

std::string attributesText(const turning::EdgeAttributes& a)
{
    std::string t = a.roughness ? fmt::format("Ra {:g}", *a.roughness) : std::string();
    if (!a.tolerance.empty()) t += (t.empty() ? "" : ", ") + a.tolerance;
    return t.empty() ? "-" : t;
}

std::string endText(const turning::EndOutcome& e, const std::function<std::string(double)>& len)
{
    using turning::Joint;
    std::string t = toKey(e.joint);
    if (e.joint != Joint::FreeEnd) t = fmt::format("{} {} ({:g}°)", e.neighbour, t, std::round(e.angle * 1000) / 1000);
    if (e.joint == Joint::Tangent && e.adjustment > 0) t += ", shortened " + len(e.adjustment) + " (" + e.adjustmentFrom + ")";
    return t;
}

std::string grooveText(const turning::EndOutcome& e, const std::function<std::string(double)>& len)
{
    if (!e.groove) return e.grooveNote;
    const auto& g = *e.groove;
    return fmt::format("{} {} x {} in {}{}", turning::toKey(g.kind), len(g.width), len(g.depth), g.inEdge,
                       g.identified ? " (identified: " + g.rule + ")" : std::string(" (typed)"));
}

// The grinding-allowance table and the profile as cut, of every turning unit.
void turnedTables(const Plan& plan, const std::function<std::string(double)>& len, const std::string& us, Content& c)
{
    c.allowances.headers = {"Unit", "Edge", "Allowance " + us, "Ra, tolerance", "At its start", "At its end", "Relief groove"};
    c.allowances.numeric = {true, false, true, false, false, false, false};
    c.allowances.widths = {5, 4, 5, 7, 16, 16, 37};
    c.turned.headers = {"Unit", "Edge", "From", "Element", "X start", "Z start", "X end", "Z end", "R", "Ra, tolerance"};
    c.turned.numeric = {true, false, false, false, true, true, true, true, true, false};
    c.turned.widths = {6, 9, 9, 6, 6, 6, 6, 6, 5, 9};
    for (const TurnedPart& part : plan.turned) {
        const std::string unit = std::to_string(part.unit + 1) + (part.name.empty() ? "" : " " + part.name);
        for (const auto& r : part.deformed.rows) {
            const turning::Edge* e = part.profile.find(r.edge);
            std::string groove = grooveText(r.start, len);
            const std::string atEnd = grooveText(r.end, len);
            if (!atEnd.empty()) groove += (groove.empty() ? "" : "; ") + atEnd;
            c.allowances.rows.push_back({unit, r.edge, len(r.allowance), e ? attributesText(e->attributes) : "-",
                                         endText(r.start, len), endText(r.end, len), groove.empty() ? "-" : groove});
        }
        if (part.deformed.rows.empty()) continue;
        for (const auto& e : part.deformed.edges) {
            const auto& g = e.geometry;
            c.turned.rows.push_back({unit, e.id, e.origin == turning::Origin::Original ? "as drawn" : std::string(toKey(e.origin)) + " " + e.from,
                                     g.arc ? (g.ccw ? "arc CCW" : "arc CW") : "line", len(2 * g.a.r), len(g.a.z),
                                     len(2 * g.b.r), len(g.b.z), g.arc ? len(g.radius) : "-", attributesText(e.attributes)});
        }
    }
}

}  // namespace

namespace {

// The lathe's setup: where the work offset is, the chuck, and how far the
// bar must stand out of the jaws (the part, the parting blade and 2 mm).
std::string latheSetup(const Plan& plan, const std::function<std::string(double)>& len)
{
    const Job& job = plan.mmJob;
    std::string chuck;
    if (const Machine* m = findMachine(job.machine); m && m->chuckDiameter > 0)
        chuck = fmt::format(" in chuck Ø{}", len(m->chuckDiameter));
    double limit = 0.0;
    for (const auto& s : plan.steps)
        if (turnOf(s) && turnOf(s)->cutting.constantSurfaceSpeed) limit = turnOf(s)->cutting.maxRpm;
    return fmt::format("Setup: bar Ø{}{}, out of the jaws ≥ {}; {}: X0 spindle axis (X as Ø), Z0 finished face{}.",
                       len(job.bar->diameter), chuck, len(barStickOut(plan)), plan.job.workOffset,
                       limit > 0 ? fmt::format("; vc in m/min up to {:.0f} rpm", limit) : "");
}

// The material by its name in the sheet's language (the shipped table's
// description), not its id; a material the table lacks by its id.
std::string materialWords(const std::string& id)
{
    const MaterialTechnology* m = TechnologyTable::builtIn().find(id);
    return m && !m->description.empty() ? m->description : id;
}

// The dialect by name and by the control it speaks.
std::string dialectWords(const std::string& name)
{
    const post::Dialect* d = post::findDialect(name);
    return d && !d->description.empty() ? name + " (" + d->description + ")" : name;
}

// The program as the control knows it: its O-number where the dialect has
// one, else the tape's file name (Siemens, HEIDENHAIN, LinuxCNC).
std::string programWords(const SheetOptions& o)
{
    const post::Dialect* d = post::findDialect(o.dialect);
    if (d && !d->programNumberLine.empty()) {
        if (o.programNumber <= 0) return {};
        // The number as the tape writes it: "O{number:04d}" of "O{number:04d} ({name})".
        const std::string number = d->programNumberLine.substr(0, d->programNumberLine.find(' '));
        return fmt::format(fmt::runtime(number), fmt::arg("number", o.programNumber), fmt::arg("name", ""));
    }
    if (!d || o.jobFile.empty()) return {};
    return std::filesystem::path(o.jobFile).stem().string() + "." + d->fileExtension;
}

}  // namespace

namespace {

using Len = std::function<std::string(double)>;

// The header's fields: the job, its file, dialect, material, machine, date,
// program, stock and the plan's counts; a field with nothing to say left out.
std::vector<std::pair<std::string, std::string>> headerFields(const Plan& plan, const SheetOptions& o, const Len& len,
                                                              const std::string& us)
{
    const Job& job = plan.mmJob;
    std::vector<std::pair<std::string, std::string>> fields = {
        {"Job", plan.job.name},
        {"File", o.jobFile},
        {"Dialect", dialectWords(o.dialect)},
        {"Material", materialWords(job.material)},
        {"Machine", job.machine},
        {"Date", o.date},
        {"Program", programWords(o)},
        {"Stock", job.bar ? fmt::format("bar D{} x {} {}, face stock {}{}", len(job.bar->diameter), len(job.bar->length), us,
                                        len(job.bar->face), job.bar->bore > 0 ? ", bore D" + len(job.bar->bore) : std::string())
                          : fmt::format("{} x {} x {} {}", len(job.stock.width), len(job.stock.length), len(job.stock.height), us)},
        {"Steps", std::to_string(plan.steps.size())},
        {"Tool changes", std::to_string(plan.toolChanges)},
        {"Total time", fmt::format("{:.1f} min", plan.totalMinutes)},
    };
    if (job.bar && plan.steps.empty())  // nothing to cut: no tape, no dialect, no program number
        std::erase_if(fields, [](const auto& f) { return f.first == "Dialect" || f.first == "Program"; });
    std::erase_if(fields, [](const auto& f) { return f.second.empty(); });
    return fields;
}

// The setup: the work offset and origin, how the stock is held, the setup picture.
void setupLines(const Plan& plan, const SheetOptions& o, const Len& len, const std::string& us, Content& c)
{
    const Job& job = plan.mmJob;
    c.setup = "Setup: work offset " + job.workOffset + ", origin X0 Y0 at the stock's front-left corner" +
              (job.stock.x == 0 && job.stock.y == 0
                   ? std::string()
                   : fmt::format(" (stock corner at X{} Y{})", len(job.stock.x), len(job.stock.y))) +
              ", Z0 on the top face.";
    if (!plan.setups.empty())
        c.setup = fmt::format("Setup: work offset {} at the centre of the workpiece, found by probing (unit {}); Z0 on "
                              "its top face.",
                              job.workOffset, plan.setups.front().unit + 1);
    if (!job.bar)
        c.clamping = !job.clamping ? "Clamping not given."
                                   : fmt::format("Clamping: vice, the jaws on the stock's {} faces ({}), gripping {} {} up "
                                                 "from its bottom.",
                                                 job.clamping->grip == Clamping::Grip::X ? "X" : "Y",
                                                 job.clamping->grip == Clamping::Grip::X ? "left and right" : "front and back",
                                                 len(job.clamping->height), us);
    if (!o.setupPicture.empty()) {
        const std::string caption =
            job.bar ? fmt::format("The bar in the chuck; {} on the finished face", job.workOffset)
                    : fmt::format("The stock{}; {} at the origin", job.clamping ? " in the vice" : "", job.workOffset);
        c.setupPicture = Content::Picture{caption, o.setupPicture};
    }
    if (job.bar) c.setup = latheSetup(plan, len);
}

// Probing units: what the touches entered measured (the probing cycle
// measures again on the machine and prints it there).
Table workCentreTable(const Plan& plan, LengthUnit u, const Len& len, const std::string& us)
{
    Table t;
    t.headers = {"Unit", "Workpiece", "Probe", "Centre X " + us, "Centre Y " + us, "Top Z " + us, "Size " + us,
                 "Turned deg", "Residuals " + us};
    t.numeric = {true, false, false, true, true, true, false, true, false};
    t.widths = {3, 10, 9, 7, 7, 6, 10, 5, 23};
    for (const WorkSetup& w : plan.setups) {
        const std::string shape = w.round ? (w.inside ? "round bore" : "round boss") : (w.inside ? "rectangular pocket" : "rectangular block");
        const std::string probe = fmt::format("T{} ball {}", w.tool, len(2 * w.ballRadius));
        if (!w.measured) {
            t.rows.push_back({std::to_string(w.unit + 1), shape, probe, "-", "-", "-", "-", "-",
                              "no touches entered: run the probing cycle"});
            continue;
        }
        const auto& m = *w.measured;
        std::string residuals;
        for (std::size_t i = 0; i < m.residuals.size(); ++i)
        {
            const int decimals = u == LengthUnit::Inch ? 5 : 4;
            const double r = fromMm(m.residuals[i], u);  // below the last digit: +0, never -0
            residuals += fmt::format("{}P{} {:+.{}f}", i ? " " : "", i + 1, std::abs(r) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : r, decimals);
        }
        t.rows.push_back(
            {std::to_string(w.unit + 1), shape, probe, len(m.centre.x), len(m.centre.y), m.top ? len(*m.top) : "-",
             w.round ? "D " + len(2 * m.radius) : len(m.width) + " x " + len(m.length),
             !w.round && m.rotationMeasured ? fmt::format("{:.4f}", m.rotation) : "-", residuals});
    }
    return t;
}

// One row per step in machining order, and the steps' pictures.
void stepRows(const Plan& plan, const SheetOptions& o, const Len& len, const Len& feed, const std::string& us, Content& c)
{
    const Job& job = plan.mmJob;
    c.steps.headers = {"No.", "Unit", "Module", "Step", "T", "H", "Tool", "S rpm", "F " + us + "/min", "Start " + us,
                       "Depth " + us, job.bar ? "X left" : "Wall left", job.bar ? "Z left" : "Floor left", "Cut " + us, "Min",
                       "Machine min"};
    // The unit column wide enough for its number and the start of its name
    // (read left to right); the tool's name is the T column's gloss.
    c.steps.numeric = {true, false, false, false, true, true, false, true, true, true, true, true, true, true, true, true};
    c.steps.widths = {3, 9, 5.3, 12, 2.6, 2.6, 11.5, 5, 6, 5.5, 5.5, 5, 5, 7, 4, 6.5};
    // A turning step's speed: constant surface speed with its spindle
    // limit, or the drill's rpm; its feed per revolution.
    const auto speedText = [](const Step& s, const std::optional<SpeedsFeeds>& sf) -> std::string {
        if (turnOf(s)) {
            const TurnCutting& tc = turnOf(s)->cutting;
            return (tc.constantSurfaceSpeed ? fmt::format("vc {:.0f}", tc.surfaceSpeed) : fmt::format("{:.0f}", tc.rpm)) +
                   (s.cutting.speed ? "*" : "");
        }
        return sf ? fmt::format("{:.0f}", sf->rpm) + (s.cutting.speed ? "*" : "") : "-";
    };
    const auto feedText = [&](const Step& s, const std::optional<SpeedsFeeds>& sf) -> std::string {
        if (turnOf(s)) return fmt::format("{}/rev", len(turnOf(s)->cutting.feedPerRev)) + (s.cutting.feed ? "*" : "");
        return sf ? feed(sf->feed) + (s.cutting.feed ? "*" : "") : "-";
    };

    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& s = plan.steps[i];
        const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        const std::optional<SpeedsFeeds>& sf = s.speeds;
        const PathLength pl = s.path ? pathLength(*s.path) : turnOf(s) ? turnPathLength(turnOf(s)->path) : PathLength{};
        // The unit by its number and the name the operator gave it.
        std::string unit = std::to_string(s.unit + 1);
        if (s.unit >= 0 && static_cast<std::size_t>(s.unit) < job.units.size() && !job.units[s.unit].name.empty())
            unit += " " + job.units[static_cast<std::size_t>(s.unit)].name;
        if (i < o.stepPictures.size() && !o.stepPictures[i].empty())
            c.pictures.push_back({fmt::format("{}. {}, unit {}", i + 1, s.label(), unit), o.stepPictures[i]});
        const MillingGeometry& g = millingOf(s);  // none on a lathe: its allowances are the turning step's
        c.steps.rows.push_back({std::to_string(i + 1), unit, s.module, s.label(),
                                t ? std::to_string(t->id) : "-", t ? std::to_string(t->id) : "-", t ? t->name : "-",
                                speedText(s, sf), feedText(s, sf), turnOf(s) ? "-" : len(g.startDepth),
                                turnOf(s) ? "-" : len(g.cutDepth), turnOf(s) ? len(turnOf(s)->allowanceX) : len(g.wallAllowance),
                                turnOf(s) ? len(turnOf(s)->allowanceZ) : len(g.floorAllowance),
                                s.path || turnOf(s) ? len(pl.feed) : "-", s.minutes ? fmt::format("{:.2f}", *s.minutes) : "-",
                                s.machineMinutes ? fmt::format("{:.2f}", *s.machineMinutes) : "-"});
    }
}

// One row per tool, their drawings, and a lathe's tools by turret station.
void toolRows(const Plan& plan, const Len& len, const std::string& us, Content& c)
{
    c.tools.headers = {"T", "Tool", "Type", "Diameter " + us, "Stick-out " + us, "Holder", "Life min", "Used min", "Left min"};
    c.tools.numeric = {true, false, false, true, true, false, true, true, true};
    c.tools.widths = {3, 22, 9, 7, 7, 14, 5, 5, 5};
    for (const auto& t : plan.tools)
        c.tools.rows.push_back({std::to_string(t.id), t.name, toString(t.type), len(t.diameter), len(t.stickout), t.holder,
                                fmt::format("{:.0f}", t.lifeMinutes), fmt::format("{:.1f}", t.usedMinutes),
                                fmt::format("{:.1f}", t.remainingLife())});
    for (const auto& t : plan.tools)
        if (auto d = toolDrawing(t, [&](double mm) { return len(mm) + " " + us; }))
            c.toolDrawings.push_back({fmt::format("T{} {}", t.id, t.name), std::move(*d)});
    // Lathe tools by turret station: what the control's tool table needs.
    c.latheTools.headers = {"Station", "T", "Tool", "Insert / blade", "Nose R " + us, "Tip orientation", "Holder"};
    c.latheTools.numeric = {true, true, false, false, true, true, false};
    c.latheTools.widths = {4, 3, 22, 12, 6, 6, 12};
    for (const auto& [station, id] : plan.mmJob.bar ? latheStations(plan.steps) : std::vector<std::pair<int, int>>{}) {
        const Tool* t = plan.tool(id);
        if (!t) continue;
        int orientation = 0;
        for (const auto& s : plan.steps)
            if (s.tool && s.tool->toolId == id && turnOf(s)) orientation = turnOf(s)->orientation;
        const std::string insert = !t->turning.insertCode.empty() ? t->turning.insertCode
                                   : t->turning.width > 0        ? "blade " + len(t->turning.width)
                                                                 : toString(t->type);
        c.latheTools.rows.push_back({fmt::format("{:02d}", station), std::to_string(id), t->name, insert, len(t->cornerRadius),
                                     std::to_string(orientation), t->holder});
    }
}

}  // namespace

Content content(const Plan& plan, const SheetOptions& o)
{
    const LengthUnit u = o.units;
    const std::string us = unitSymbol(u);
    const Len len = [&](double mm) { return fmt::format("{:.{}f}", fromMm(mm, u), u == LengthUnit::Inch ? 4 : 3); };
    const Len feed = [&](double mmPerMin) { return fmt::format("{:.{}f}", fromMm(mmPerMin, u), u == LengthUnit::Inch ? 1 : 0); };
    const Job& job = plan.mmJob;
    Content c;
    c.title = "Machining instruction sheet";
    c.fields = headerFields(plan, o, len, us);
    setupLines(plan, o, len, us, c);
    c.toolsOrigin = o.toolsOrigin;
    turnedTables(plan, len, us, c);
    c.workCentre = workCentreTable(plan, u, len, us);
    stepRows(plan, o, len, feed, us, c);
    toolRows(plan, len, us, c);
    c.notes = plan.notes();
    c.faults = o.faults;
    c.paths = o.paths;
    c.picturesNote = o.picturesNote;
    if (std::any_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return !s.cutting.empty(); }))
        c.notes.push_back("* S or F set by the operator for the step, in place of the tool's cutting data.");
    double cutting = 0.0;
    for (const auto& s : plan.steps) cutting += s.minutes.value_or(0.0);
    c.total = fmt::format("{:.1f} min of machining, {} tool changes, {:.1f} min in all", cutting, plan.toolChanges,
                          plan.totalMinutes);
    if (plan.totalMachineMinutes)
        c.total += fmt::format(" ({:.1f} min as the machine '{}' moves: acceleration, corners, look-ahead)",
                               *plan.totalMachineMinutes, job.machine);
    return c;
}

}  // namespace taiwa::sheet

namespace taiwa {

double barStickOut(const Plan& plan)
{
    double zMin = 0.0;
    for (const TurnedPart& part : plan.turned)
        for (const auto& e : part.deformed.edges) zMin = std::min({zMin, e.geometry.a.z, e.geometry.b.z});
    double blade = 0.0;
    for (const auto& s : plan.steps)
        if (s.machiningType == MachiningType::Parting && s.tool)
            if (const Tool* t = plan.tool(s.tool->toolId)) blade = t->turning.width;
    return (plan.mmJob.bar ? plan.mmJob.bar->face : 0.0) - zMin + blade + 2.0;
}

}  // namespace taiwa
