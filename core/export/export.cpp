// Export of a planned job into its files (docs/command-line.md), and the
// machine-readable step list STEM.steps.json.
#include "export/export.h"

#include "export/sheet_pdf.h"
#include "export/two_path_export.h"
#include "export/two_path_sheet.h"
#include "io/job_io.h"
#include "io/json_write.h"
#include "modules/module_kind.h"
#include "modules/registry.h"
#include "occt/surface_step.h"
#include "model/translate_noop.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/post.h"
#include "post/tool_table.h"
#include "sheet/sheet.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <future>
#include <regex>
#include <set>
#include <system_error>

namespace taiwa {

namespace {

// Lengths in the file's unit, rounded to 1 nm (io/json_write.h).
double out(double mm, LengthUnit u) { return io::stepLength(mm, u); }
nlohmann::ordered_json point(Point2 p, LengthUnit u) { return io::stepPoint(p, u); }

nlohmann::ordered_json stepJson(const Plan& plan, const Step& s, LengthUnit u)
{
    const MillingGeometry& g = millingOf(s);
    nlohmann::ordered_json j;
    j["unit"] = s.unit + 1;
    j["module"] = s.module;
    j["kind"] = toKey(s.kind);
    j["number"] = s.number;
    j["label"] = s.label();
    j["machiningType"] = static_cast<int>(s.machiningType);
    if (s.tool) {
        nlohmann::ordered_json t;
        t["id"] = s.tool->toolId;
        if (const Tool* tool = plan.tool(s.tool->toolId)) {
            t["name"] = tool->name;
            t["type"] = toKey(tool->type);
            t["diameter"] = out(tool->diameter, u);
        }
        t["reason"] = s.tool->reason;
        j["tool"] = t;
    }
    j["startDepth"] = out(g.startDepth, u);
    j["cutDepth"] = out(g.cutDepth, u);
    if (s.machiningType == MachiningType::PilotHole) {
        j["position"] = point(g.position, u);
    }
    if (g.outline) {
        nlohmann::ordered_json o;
        o["corners"] = nlohmann::ordered_json::array();
        for (const auto& c : g.outline->corners) o["corners"].push_back(point(c, u));
        o["cornerRadius"] = out(g.outline->cornerRadius, u);
        j["outline"] = o;
    }
    moduleKind(s).describeStep(s, u, j);  // the module's own data of the step
    j["wallTaper"] = g.wallTaper;
    j["wallAllowance"] = out(g.wallAllowance, u);
    j["floorAllowance"] = out(g.floorAllowance, u);
    if (g.multiIncision) j["multiIncision"] = true;
    if (s.path) {
        const PathLength len = pathLength(*s.path);
        j["pathLength"] = {{"feed", out(len.feed, u)}, {"rapid", out(len.rapid, u)}};
        j["moves"] = s.path->moves.size();
    }
    if (const TurnStep* turned = turnOf(s)) {
        const TurnStep& t = *turned;
        const PathLength len = turnPathLength(t.path);
        j["pathLength"] = {{"feed", out(len.feed, u)}, {"rapid", out(len.rapid, u)}};
        j["moves"] = t.path.moves.size();
        nlohmann::ordered_json tj;
        tj["side"] = turning::toKey(t.side);
        tj["region"] = t.region;
        tj["orientation"] = t.orientation;
        if (t.cutting.constantSurfaceSpeed) {
            tj["surfaceSpeed"] = t.cutting.surfaceSpeed;
            tj["maxRpm"] = t.cutting.maxRpm;
        } else {
            tj["rpm"] = t.cutting.rpm;
        }
        tj["feedPerRev"] = out(t.cutting.feedPerRev, u);
        if (t.depthOfCut > 0) tj["depthOfCut"] = out(t.depthOfCut, u);
        if (t.allowanceX > 0 || t.allowanceZ > 0) tj["allowance"] = {{"x", out(t.allowanceX, u)}, {"z", out(t.allowanceZ, u)}};
        if (t.withdrawal > 0) tj["withdrawal"] = out(t.withdrawal, u);
        if (t.path.cycle) tj["cycle"] = "G71";
        if (t.path.comp != NoseCompensation::Off) tj["noseCompensation"] = t.path.comp == NoseCompensation::Left ? "G41" : "G42";
        j["turning"] = tj;
    }
    if (s.minutes) j["minutes"] = *s.minutes;
    if (s.machineMinutes) j["machineMinutes"] = *s.machineMinutes;
    return j;
}

// A point of a turned profile: [X as a diameter, Z].
nlohmann::ordered_json xz(turning::ZR p, LengthUnit u) { return nlohmann::ordered_json::array({out(2.0 * p.r, u), out(p.z, u)}); }

nlohmann::ordered_json segmentJson(const turning::Segment& g, const turning::EdgeAttributes& a, LengthUnit u)
{
    nlohmann::ordered_json j;
    j["element"] = g.arc ? (g.ccw ? "ccw" : "cw") : "line";
    j["start"] = xz(g.a, u);
    j["end"] = xz(g.b, u);
    if (g.arc) {
        j["centre"] = xz(g.centre, u);
        j["radius"] = out(g.radius, u);
    }
    if (a.roughness) j["roughness"] = *a.roughness;
    if (!a.tolerance.empty()) j["tolerance"] = a.tolerance;
    return j;
}

nlohmann::ordered_json endJson(const turning::EndOutcome& e, LengthUnit u)
{
    nlohmann::ordered_json j;
    j["joint"] = turning::toKey(e.joint);
    if (!e.neighbour.empty()) {
        j["neighbour"] = e.neighbour;
        j["angle"] = std::round(e.angle * 1e6) / 1e6;
    }
    if (e.joint == turning::Joint::Tangent) {
        j["adjustment"] = out(e.adjustment, u);
        j["adjustmentFrom"] = e.adjustmentFrom;
    }
    if (e.groove) {
        const auto& g = *e.groove;
        j["groove"] = {{"kind", turning::toKey(g.kind)}, {"identified", g.identified}, {"rule", g.rule},
                       {"in", g.inEdge}, {"width", out(g.width, u)}, {"depth", out(g.depth, u)}, {"corner", xz(g.corner, u)}};
    } else if (!e.grooveNote.empty()) {
        j["groove"] = e.grooveNote;
    }
    return j;
}

// A turning unit: its profile as drawn, the allowance rows as applied and
// the deformed profile, each edge saying where it came from.
nlohmann::ordered_json turnedJson(const TurnedPart& part, LengthUnit u)
{
    nlohmann::ordered_json j;
    j["unit"] = part.unit + 1;
    j["name"] = part.name;
    j["side"] = turning::toKey(part.profile.side);
    j["profile"] = nlohmann::ordered_json::array();
    for (const auto& e : part.profile.edges) {
        nlohmann::ordered_json s;
        s["id"] = e.id;
        s.update(segmentJson(e.geometry, e.attributes, u));
        j["profile"].push_back(s);
    }
    j["allowances"] = nlohmann::ordered_json::array();
    for (const auto& r : part.deformed.rows)
        j["allowances"].push_back({{"edge", r.edge}, {"allowance", out(r.allowance, u)}, {"start", endJson(r.start, u)},
                                   {"end", endJson(r.end, u)}});
    if (!part.noseRadiusTool.empty()) j["noseRadiusFrom"] = part.noseRadiusTool;
    j["deformed"] = nlohmann::ordered_json::array();
    for (const auto& e : part.deformed.edges) {
        nlohmann::ordered_json d;
        d["id"] = e.id;
        d["origin"] = turning::toKey(e.origin);
        d["from"] = e.from;
        if (e.allowanceRow >= 0) d["allowanceRow"] = e.allowanceRow + 1;
        d.update(segmentJson(e.geometry, e.attributes, u));
        j["deformed"].push_back(d);
    }
    return j;
}

// An export that failed after writing began: why, and that the folder is as it was.
std::string nothingChanged(const std::string& why, const std::string& outDir)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}; nothing was changed in {}"), why, outDir);
}

}  // namespace

std::string stepsJson(const Plan& plan)
{
    const LengthUnit u = plan.job.lengthUnit;
    nlohmann::ordered_json doc;
    doc["format"] = "taiwa-steps";
    doc["version"] = 1;
    doc["job"] = plan.job.name;
    doc["lengthUnit"] = u == LengthUnit::Inch ? "inch" : "mm";
    doc["material"] = plan.job.material;
    doc["totalMinutes"] = plan.totalMinutes;
    doc["toolChanges"] = plan.toolChanges;
    doc["steps"] = nlohmann::ordered_json::array();
    for (const auto& s : plan.steps) doc["steps"].push_back(stepJson(plan, s, u));
    if (!plan.turned.empty()) {
        doc["turnedProfiles"] = nlohmann::ordered_json::array();
        for (const TurnedPart& part : plan.turned) doc["turnedProfiles"].push_back(turnedJson(part, u));
    }
    return doc.dump(2) + "\n";
}

Result<std::vector<std::string>> exportPlan(const Plan& plan, const std::string& outDir, const std::string& stem,
                                            const ExportOptions& options)
{
    if (!plan.ok()) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "the job did not pass input processing; nothing was written")};
    if (auto why = workOffsetProblem(options.dialect, plan.job.workOffset))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}; nothing was written"), why->message)};
    const post::Dialect* dialect = post::findDialect(options.dialect);
    if (!dialect) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "unknown dialect '{}'; nothing was written"), options.dialect)};
    if (auto can = post::canPost(*dialect, post::taskOf(plan.mmJob.bar.has_value(), !plan.setups.empty())); !can)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}; nothing was written"), can.error()), can.place()};
    // The tape's file: STEM.nc, or the control's own kind (STEM.h for HEIDENHAIN).
    const std::string tape = "." + dialect->fileExtension;
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (ec) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot create folder {}: {}"), outDir, ec.message())};
    const LengthUnit units = options.units.value_or(plan.job.lengthUnit);

    SheetOptions sheet;
    sheet.units = units;
    sheet.dialect = options.dialect;
    sheet.jobFile = options.jobFile;
    sheet.programNumber = options.programNumber;
    sheet.faults = options.verificationFaults;
    sheet.stepPictures = options.stepPictures;
    sheet.picturesNote = options.picturesNote;
    sheet.setupPicture = options.setupPicture;
    sheet.paths = twoPathSheet(plan);  // a two-path lathe's: each step's path, the roughing's timeline
    sheet.toolsOrigin = options.toolsOrigin;
    // The PDF (most of an export's time after planning: shaping and
    // compressing every page's text) is drawn on a thread of its own while
    // this one posts the tape and writes the HTML sheet and steps.json.
    auto drawing = std::async(std::launch::async, [&plan, &sheet] { return sheetPdf(plan, sheet); });
    std::optional<PostedJob> own;
    const PostedJob& posted =
        options.posted ? *options.posted : own.emplace(postJob(plan, postOptions(plan, options.dialect, units, options.programNumber, stem)));
    const PostedProgram& program = posted.tape;
    const std::string html = sheetHtml(plan, sheet), steps = stepsJson(plan);
    auto pdf = drawing.get();
    if (!pdf) return Failure{nothingChanged(pdf.error(), outDir), pdf.place()};

    auto set = FileSet::open(outDir, stem);
    if (!set) return Failure{nothingChanged(set.error(), outDir), set.place()};
    std::vector<std::pair<std::string, std::string>> files = {
        {tape, program.nc}, {".tape.txt", program.tapeImage}, {".sheet.html", html},
        {".steps.json", steps}, {".sheet.pdf", *pdf},
    };
    // A lathe job whose steps are all turned off has no tape: its sheet and
    // steps.json hold the profile to cut.
    if (plan.mmJob.bar && plan.steps.empty()) std::erase_if(files, [&](const auto& f) { return f.first == tape || f.first == ".tape.txt"; });
    // A LinuxCNC lathe tape runs with its tool table (nose radii, orientations): STEM.tbl.
    else if (plan.mmJob.bar && dialect->syntax == post::Syntax::Iso && dialect->macroSyntax != "fanuc")
        files.emplace_back(".tbl", linuxcncLatheToolTable(plan.steps, plan.tools, stem));
    // A two-path lathe: STEM.p1.nc, STEM.p2.nc (and their tables) in place of the tape (two_path_export.h).
    if (auto two = twoPathTapes(plan, posted.twoPath, options.dialect, stem)) {
        if (!*two) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}; nothing was written"), two->error())};
        std::erase_if(files, [&](const auto& f) { return f.first == tape || f.first == ".tape.txt" || f.first == ".tbl"; });
        files.insert(files.end(), (*two)->begin(), (*two)->end());
    }
    // Probing units: the setting program from the touches entered (when
    // there are) and the probing cycle, STEM.u<unit>.setting.nc and
    // STEM.u<unit>.probe.nc, with O-numbers after the tape's (postProbing).
    for (const PostedProbing& p : posted.probing) {
        const std::string unit = ".u" + std::to_string(p.unit + 1);
        if (!p.setting.empty()) files.emplace_back(unit + ".setting.nc", p.setting);
        files.emplace_back(unit + ".probe.nc", p.probe);
    }
    // A unit's finished 3-D surface (the module's machinedSurface, SURFACE's
    // finishing surface): STEM.u<unit>.surface.step, one face, flat
    // between its paths' points as the unit's bilinear patches are, in mm.
    for (const Step& s : plan.steps) {
        const ModuleKind* kind = findModuleKind(s.module);
        const auto paths = kind ? kind->machinedSurface(s) : std::vector<std::vector<Point3>>{};
        if (paths.empty()) continue;
        auto step = surface::surfaceStepText(paths, surface::SurfaceFit::Bilinear);
        if (!step)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}; nothing was written"),
                                       fmt::format("unit {}'s surface: {}", s.unit + 1, step.error()))};
        files.emplace_back(".u" + std::to_string(s.unit + 1) + ".surface.step", std::move(*step));
    }
    for (const auto& [suffix, bytes] : files)
        if (auto written = set->add(stem + suffix, bytes); !written)
            return Failure{nothingChanged(written.error(), outDir), written.place()};
    // The files of an older set of this stem the new one does not have
    // (another dialect's tape, a lathe tape's tool table, probing programs
    // and surfaces of units no longer there) go in the same switch: a folder never holds
    // part.nc beside part.mpf.
    std::set<std::string> names;
    for (const auto& f : files) names.insert(stem + f.first);
    std::set<std::string> older{stem + ".nc", stem + ".tape.txt", stem + ".tbl"};
    for (const post::Dialect& d : post::dialectLibrary()) older.insert(stem + "." + d.fileExtension);
    static const std::regex probing(R"(\.u[0-9]+\.((setting|probe)\.nc|surface\.step))");
    for (const auto& entry : std::filesystem::directory_iterator(outDir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with(stem) && std::regex_match(name.substr(stem.size()), probing)) older.insert(name);
    }
    for (const auto& name : older)
        if (!names.contains(name)) set->remove(name);
    auto written = set->commit();
    if (!written) return Failure{nothingChanged(written.error(), outDir), written.place()};
    return written;
}

}  // namespace taiwa
