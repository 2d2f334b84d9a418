// The command line of docs/command-line.md: `taiwa [JOB]`, `taiwa check JOB`,
// `taiwa export JOB --out DIR ...`, `taiwa verify JOB ...` (its report in
// app/verify_command.cpp), `taiwa render JOB --out PNG ...`, `taiwa import
// STEP` and `taiwa figure-from-dxf FILE.dxf ...` (app/import_commands.cpp),
// `taiwa store list|history|locks|unlock` and `taiwa import-tools`
// (app/store_command.cpp), `--version`, `--help`, `--list-machines` and
// `--list-dialects` (app/about_commands.cpp). Exit codes (app/exit_codes.h):
// 0 ok, 2 input errors, 3 verification faults, 1 internal failure.
#include "app/cli.h"

#include "app/about_commands.h"
#include "app/exit_codes.h"
#include "app/import_commands.h"
#include "app/options.h"
#include "app/store_command.h"
#include "app/verify_command.h"
#include "job/job_check.h"
#include "job/job_file.h"
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
    JobReadResult read = readJobFile(o.job);
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
    l.plan = planJob(std::move(*read.job), TechnologyTable::builtIn(), *tools, options);
    l.exit = printDiagnostics(name, l.plan.diagnostics);
    return l;
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
    std::optional<PostedJob> posted;
    verify::Report checked;
    bool reused = false;
    try {
        checked = verified(l.plan, o, postOptions(l.plan, dialect, o.units, programNumber, stem), posted, &reused);
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
    e.posted = posted ? &*posted : nullptr;
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
        case Command::Help: std::cout << helpText(); return kOk;
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
        case Command::Store: return storeCommand(o.storeAction, o.job, o.force, o.tools);
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
