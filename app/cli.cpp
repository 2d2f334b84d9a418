// The command line of docs/command-line.md: `taiwa [JOB]`, `taiwa check JOB`,
// `taiwa export JOB --out DIR ...`, `taiwa verify JOB ...` (its report in
// app/verify_command.cpp), `taiwa render JOB --out PNG ...`, `taiwa
// figure-from-dxf FILE.dxf ...`, `taiwa store list|history` and `taiwa
// import-tools` (app/store_command.cpp), `--version`, `--help`. Exit codes: 0 ok, 2 input errors, 3 verification faults, 1
// internal failure.
#include "app/cli.h"

#include "app/options.h"
#include "app/store_command.h"
#include "app/verify_command.h"
#include "dxf/dxf_import.h"
#include "job/dxf_figure.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "job/step_job.h"
#include "machine/machine.h"
#include "post/dialect.h"
#include "post/post.h"
#include "io/job_io.h"
#include "model/technology.h"
#include "export/export.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "tools/tool_store.h"

#if defined(TAIWA_WITH_UI) && __has_include("viz/render.h")
#define TAIWA_WITH_RENDER 1
#include "viz/render.h"
#endif
#ifdef TAIWA_WITH_UI
#include "ui/profile_view.h"
#include "ui/ui.h"

#include <QApplication>
#endif

#include <QGuiApplication>

#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace taiwa::app {

namespace {

constexpr int kOk = 0, kInternal = 1, kInputErrors = 2, kFindings = 3;

const char* const kHelp = R"(taiwa - conversational NC programming station

Usage:
  taiwa [JOB]                      open the station window (with JOB loaded)
  taiwa check JOB                  input processing only; one line per error:
                                   JOB: unit N (MODULE) field: message
  taiwa export JOB --out DIR [--dialect NAME] [--units mm|inch] [--no-pictures]
                                   the whole pipeline; writes STEM.nc (.mpf for
                                   sinumerik, .h for heidenhain), STEM.tape.txt,
                                   STEM.sheet.html, STEM.sheet.pdf and
                                   STEM.steps.json into DIR (and each probing
                                   unit's programs, and a linuxcnc lathe tape's
                                   tool table STEM.tbl); the dialect (--list-dialects):
                                   --dialect, else the job's, else linuxcnc;
                                   verifies first (--resolution) and writes
                                   nothing when a gouge, collision or travel
                                   limit is found (exit 3), unless --force,
                                   which writes them into the sheet in red;
                                   the sheet shows each step's stock in a
                                   picture (drawn on the processor: no display)
  taiwa export --from-store NAME --out DIR [...]
                                   the same for the newest version of job NAME
                                   of the shop server's store (TAIWA_TOOL_DB)
  taiwa verify JOB [--resolution MM] [--json]
                                   cuts every step into the stock on a grid of
                                   MM (default 0.05) and prints each gouge,
                                   collision, rapid into stock, travel limit
                                   and material left, with its step, move and
                                   tape line; exit 3 when a gouge, collision
                                   or travel limit is found
  taiwa render JOB --out PNG [--step K|all] [--stock] [--size WxH]
               [--view iso|top|front|profile]
                                   the 3-D preview of step K (1-based, in
                                   machining order) or all steps, to a PNG; a
                                   lathe job: the part revolved, or with
                                   --view profile its profile views
  taiwa import STEP --out JOB [--material ID]
                                   a lathe job from a STEP solid of revolution:
                                   its outer profile (and bore) as turned-profile
                                   units, a bar that holds it; JOB must not exist
  taiwa figure-from-dxf FILE.dxf [--layers A,B] [--gap MM] [--units mm|inch]
                                   the contours of a DXF drawing (on the
                                   layers given; ends within MM, default 0.01,
                                   joined; lengths in the unit given, else the
                                   file's) as figure elements on stdout; what
                                   was read, gaps, branches and contours left
                                   out on stderr; exit 2 when the file is
                                   refused, has gaps or a contour is left out
  taiwa import-tools FILE.sqlite
                                   the shop server's tool library (TAIWA_TOOL_DB
                                   or --tools, a postgresql:// setting) replaced
                                   by that of an SQLite library of any version;
                                   the file is left as it was
  taiwa store list | taiwa store history NAME
                                   the shop server's job store (TAIWA_TOOL_DB
                                   or --tools): each job with its newest
                                   version, who saved it from which station
                                   and when, and who has it open; or every
                                   version of job NAME; tab-separated lines
  taiwa --list-machines | --list-dialects
                                   the machines and dialects this program knows
                                   (shipped, and the shop's own in
                                   ~/.config/taiwa/machines|dialects/*.json),
                                   with where each comes from
  taiwa --version | --help

Common options:
  --tools DB    the tool library (SQLite); default $TAIWA_TOOL_DB or
                ~/.local/share/taiwa/tools.sqlite, created on first use
  --no-cache    verify, export: verify afresh; otherwise a report stored by
                an earlier verify or export of the same job, plan, library
                tools, machine and resolution is reused
                ($XDG_CACHE_HOME/taiwa/verification, or $TAIWA_CACHE_DIR)

Exit status: 0 ok, 2 input errors (the job's, the options' or the tool
library's; nothing written), 3 the verification found
a gouge, a collision or a travel limit, 1 internal failure.
)";

int printDiagnostics(const std::string& jobName, const Diagnostics& ds)
{
    for (const auto& d : ds) std::cerr << format(jobName, d) << '\n';
    return hasErrors(ds) ? kInputErrors : kOk;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Reads the job and the tool library and plans it. Returns an exit code when
// the pipeline cannot go on (errors already printed), or nothing.
struct Loaded {
    Plan plan;
    int exit = kOk;
    std::string toolsOrigin;  // ToolStore::origin, for the sheet
};

Loaded load(const Options& o, bool withToolPaths)
{
    Loaded l;
    const std::string name = fileName(o.job);
    const JobReadResult read = readJobFile(o.job);
    if (!read.job) {
        l.exit = printDiagnostics(name, read.diagnostics) == kOk ? kInternal : kInputErrors;
        return l;
    }
    // The shop server's tools (or its copy's): the sheet says which.
    auto store = openToolStore(o.tools);
    const auto tools = store ? (*store)->tools() : Result<std::vector<Tool>>(Failure{store.error()});
    if (store) l.toolsOrigin = (*store)->origin();
    if (!tools) {
        // The shop's library is input like the job: refused with its reason, exit 2.
        std::cerr << "taiwa: tool library: " << tools.error() << "; nothing was written\n";
        l.exit = kInputErrors;
        return l;
    }
    PlanOptions options;
    options.withToolPaths = withToolPaths;
    l.plan = planJob(*read.job, TechnologyTable::builtIn(), *tools, options);
    l.exit = printDiagnostics(name, l.plan.diagnostics);
    return l;
}

int importStep(const Options& o)
{
    std::error_code ec;
    if (std::filesystem::exists(o.out, ec)) {
        std::cerr << "taiwa: import: " << o.out << " exists; give a new file name (nothing was written)\n";
        return kInputErrors;
    }
    const auto job = latheJobFromStep(o.job, o.material);
    if (!job) {
        std::cerr << "taiwa: import: " << job.error() << '\n';
        return kInputErrors;
    }
    if (!TechnologyTable::builtIn().find(o.material)) {
        std::cerr << "taiwa: import: material '" << o.material << "' is not in the technology table\n";
        return kInputErrors;
    }
    if (auto saved = writeFileAtomically(o.out, writeJob(*job)); !saved) {
        std::cerr << "taiwa: import: " << saved.error() << '\n';
        return kInternal;
    }
    std::cout << "taiwa: wrote " << o.out << ": " << job->units.size() << " turned profile"
              << (job->units.size() == 1 ? "" : "s") << " on a bar D" << job->bar->diameter << " x " << job->bar->length
              << " mm\n";
    return kOk;
}

// A DXF drawing's contours as figure text on stdout (job/dxf_figure.h), and
// on stderr what was read and what is wrong with it.
int figureFromDxf(const Options& o)
{
    const std::string name = fileName(o.job);
    dxf::DxfOptions d;
    d.layers = o.layers;
    if (o.gap) d.gapTolerance = *o.gap;
    if (o.units) d.units = *o.units == LengthUnit::Inch ? dxf::Units::Inches : dxf::Units::Millimetres;
    const dxf::DxfReadResult r = dxf::readDxf(o.job, d);
    for (const auto& w : r.warnings) std::cerr << name << ": " << w << '\n';
    if (!r.ok()) {
        std::cerr << name << ": " << *r.error << '\n';
        return kInputErrors;
    }
    std::vector<Contour> contours;
    for (const auto& c : r.contours) contours.push_back(c.contour);
    const FigureFromContours f = figureFromContours(contours);
    std::cout << f.text;
    std::string layers;
    for (const auto& l : r.layers)
        if (l.selected) layers += (layers.empty() ? "" : ", ") + l.name;
    std::cerr << name << ": " << r.contours.size() << " contours (" << r.closedCount() << " closed, " << r.openCount()
              << " open) on " << (layers.empty() ? "no layer" : "layers " + layers) << ", drawn in " << r.units
              << ", written in mm; " << r.gaps.size() << " gaps, " << r.branches.size() << " branches\n";
    for (const auto& g : r.gaps) std::cerr << name << ": " << g.message << '\n';
    for (const auto& b : r.branches) std::cerr << name << ": " << b.message << '\n';
    for (const auto& n : f.notes) std::cerr << name << ": " << n << '\n';
    for (const auto& x : f.refusals) std::cerr << name << ": " << x << '\n';
    return r.gaps.empty() && f.refusals.empty() ? kOk : kInputErrors;
}

// One line per machine: id, kind, name and where it was read from; the
// user's files left out on standard error.
int listMachines()
{
    for (const Machine& m : machineLibrary())
        std::cout << m.id << '\t' << toKey(m.kind) << '\t' << m.name << '\t' << m.source << '\n';
    for (const std::string& p : machineLibraryProblems()) std::cerr << "taiwa: " << p << '\n';
    return kOk;
}

int listDialects()
{
    for (const post::Dialect& d : post::dialectLibrary())
        std::cout << d.name << '\t' << d.description << '\t' << d.source << '\n';
    for (const std::string& p : post::dialectLibraryProblems()) std::cerr << "taiwa: " << p << '\n';
    return kOk;
}

int check(const Options& o)
{
    // Input processing only: no tool paths.
    return load(o, false).exit;
}

// The dialect asked for, else the job's own, else LinuxCNC's.
std::string dialectFor(const Options& o, const Plan& plan)
{
    return !o.dialect.empty() ? o.dialect : !plan.job.dialect.empty() ? plan.job.dialect : "linuxcnc";
}

int verifyJob(const Options& o)
{
    const Loaded l = load(o, true);
    if (l.exit != kOk) return l.exit;
    try {
        return printVerification(l.plan, o, fileName(o.job), dialectFor(o, l.plan)) ? kFindings : kOk;
    } catch (const Refusal& e) {  // --resolution too fine for this stock
        std::cerr << "taiwa: verify: " << e.what() << '\n';
        return kInputErrors;
    }
}

int exportJob(const Options& o, int& argc, char** argv)
{
    // A file size limit (ulimit -f) makes a write fail with EFBIG, which the
    // export reports naming the file, instead of killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
    const Loaded l = load(o, true);
    if (l.exit != kOk) return l.exit;
    // The dialect asked for, else the job's own, else LinuxCNC's. Whether its
    // controller has the job's work offset is an input error of the job,
    // known only now that the dialect is.
    const std::string dialect = dialectFor(o, l.plan);
    if (auto why = workOffsetProblem(dialect, l.plan.job.workOffset)) return printDiagnostics(fileName(o.job), {*why});
    // A dialect that writes no lathe tape or no probing programs is refused
    // here, as an input error, whether --dialect or the job named it.
    if (const post::Dialect* d = post::findDialect(dialect)) {
        if (auto can = post::canPost(*d, post::taskOf(l.plan.mmJob.bar.has_value(), !l.plan.setups.empty())); !can) {
            std::cerr << fileName(o.job) << ": dialect: " << can.error() << "; nothing was written\n";
            return kInputErrors;
        }
    }
    // A tape with a gouge, a collision or beyond the travel is not written
    // unless the operator forces it; then its sheet says why in red.
    // The tape is posted once: for the findings' places on it, when there
    // are any, and then written as it is.
    const std::string stem = std::filesystem::path(o.job).stem().string();
    const int programNumber = ExportOptions{}.programNumber;
    std::optional<PostedProgram> tape;
    verify::Report checked;
    bool reused = false;
    try {
        checked = verified(l.plan, o, postOptions(l.plan, dialect, o.units, programNumber, stem), tape, &reused);
    } catch (const Refusal& e) {  // --resolution too fine for this stock
        std::cerr << "taiwa: export: " << e.what() << '\n';
        return kInputErrors;
    }
    if (reused)  // `taiwa verify` (or an export) of this very job and plan ran before: its report, not a second run
        std::cout << "taiwa: the verification at " << checked.resolution
                  << " mm of this job and plan was reused (--no-cache verifies again)\n";
    std::vector<std::string> faults;
    for (const auto& f : checked.findings)
        if (f.fatal()) faults.push_back(verify::describe(f, l.plan));
    if (!faults.empty() && !o.force) {
        for (const auto& f : faults) std::cerr << fileName(o.job) << ": " << f << '\n';
        std::cerr << "taiwa: export: the verification found " << faults.size()
                  << " faults; nothing was written (--force writes them into the sheet)\n";
        return kFindings;
    }
    // The PDF writer needs a QGuiApplication; no window is ever shown.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication qapp(argc, argv);
    ExportOptions e;
    e.dialect = dialect;
    e.units = o.units;
    e.jobFile = fileName(o.job);
    e.programNumber = programNumber;
    e.verificationFaults = faults;
    e.posted = tape ? &*tape : nullptr;
    e.toolsOrigin = l.toolsOrigin;
    if (o.pictures) picturesFor(l.plan, e);
    const auto written = exportPlan(l.plan, o.out, stem, e);
    if (!written) {
        std::cerr << "taiwa: export: " << written.error() << '\n';
        return kInternal;
    }
    std::cout << "taiwa: wrote " << written->size() << " files to " << o.out << '\n';
    for (const auto& f : *written) std::cout << "  " << f << '\n';
    return kOk;
}

int render(const Options& o, [[maybe_unused]] int& argc, [[maybe_unused]] char** argv)
{
#ifdef TAIWA_WITH_RENDER
    // 4096 x 4096 takes seconds and ~1 GB with software rendering (8192 took 17 s and 5.8 GB).
    if (o.width > viz::kMaxRenderSide || o.height > viz::kMaxRenderSide) {
        std::cerr << "taiwa: --size " << o.width << "x" << o.height << " is larger than " << viz::kMaxRenderSide << "x"
                  << viz::kMaxRenderSide << " pixels\nTry 'taiwa --help'.\n";
        return kInputErrors;
    }
    const Loaded l = load(o, true);
    if (l.exit != kOk) return l.exit;
    if (o.view == "profile") {  // a lathe job's profile views, painted by the station's widget offscreen
        if (l.plan.turned.empty()) {
            std::cerr << "taiwa: render: --view profile draws turned profiles; this job has none\n";
            return kInputErrors;
        }
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
        QApplication qapp(argc, argv);
        if (!ui::profileImage(l.plan, o.width, o.height).save(QString::fromStdString(o.out), "PNG")) {
            std::cerr << "taiwa: render: cannot write " << o.out << '\n';
            return kInternal;
        }
        std::cout << "taiwa: wrote " << o.out << '\n';
        return kOk;
    }
    viz::RenderOptions r;
    r.step = o.step ? *o.step - 1 : -1;
    if (o.step && (*o.step < 1 || *o.step > static_cast<int>(l.plan.steps.size()))) {
        std::cerr << "taiwa: render: --step " << *o.step << " is out of range: the job has "
                  << l.plan.steps.size() << " steps\n";
        return kInputErrors;
    }
    r.showStock = o.stock;
    r.width = o.width;
    r.height = o.height;
    r.view = o.view == "top" ? viz::ViewPreset::Top : o.view == "front" ? viz::ViewPreset::Front : viz::ViewPreset::Iso;
    if (const auto drawn = viz::renderToPng(l.plan, r, o.out); !drawn) {
        std::cerr << "taiwa: render: " << drawn.error() << '\n';
        return kInternal;
    }
    std::cout << "taiwa: wrote " << o.out << '\n';
    return kOk;
#else
    (void)o;
    std::cerr << "taiwa: render: this build has no 3-D view (built without TAIWA_BUILD_UI)\n";
    return kInternal;
#endif
}

}  // namespace

int run(int argc, char** argv)
{
    try {
        Options o;
        if (auto parsed = parseOptions(argc, argv, o); !parsed) {
            std::cerr << "taiwa: " << parsed.error() << "\nTry 'taiwa --help'.\n";
            return kInputErrors;
        }
        switch (o.command) {
        case Command::Help: std::cout << kHelp; return kOk;
        case Command::Version: std::cout << "taiwa " << TAIWA_VERSION << '\n'; return kOk;
        case Command::Check: return check(o);
        case Command::Export:
            if (!o.fromStore.empty()) {  // the job from the shop server's store (app/store_command.h)
                auto stored = fetchStoredJob(o.fromStore, o.tools);
                if (!stored) {
                    std::cerr << "taiwa: export: " << stored.error() << '\n';
                    return kInternal;
                }
                o.job = *stored;
                const int exit = exportJob(o, argc, argv);
                std::error_code ec;
                std::filesystem::remove_all(std::filesystem::path(o.job).parent_path(), ec);
                return exit;
            }
            return exportJob(o, argc, argv);
        case Command::Verify: return verifyJob(o);
        case Command::Render: return render(o, argc, argv);
        case Command::Import: return importStep(o);
        case Command::FigureFromDxf: return figureFromDxf(o);
        case Command::ImportTools: return importTools(o.job, o.tools);
        case Command::Store: return storeCommand(o.storeAction, o.job, o.tools);
        case Command::ListMachines: return listMachines();
        case Command::ListDialects: return listDialects();
        case Command::Station:
#ifdef TAIWA_WITH_UI
            return ui::runStation(argc, argv, QString::fromStdString(o.job));
#else
            std::cerr << "taiwa: this build has no station window (built without TAIWA_BUILD_UI)\n";
            return kInternal;
#endif
        }
    } catch (const std::exception& e) {
        std::cerr << "taiwa: internal failure: " << e.what() << '\n';
    }
    return kInternal;
}

}  // namespace taiwa::app
