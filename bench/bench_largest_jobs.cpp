// For every module, the largest job it accepts and what that job costs
// (issue 39: "the largest job each module accepts finishes within 60 s and
// 2 GB"), with a ladder of sizes below it: the job's move estimate (the
// budget of pipeline.h, 10⁷ moves, counts them weighed by each module's
// workPerMove: SURFACE's 6, the others' 1) beside the time `taiwa check`
// and `taiwa export` take, so that time growing faster than the estimate
// shows.
//
// Each module's job grows from its sample (resources/samples):
//  - milling units: the sample job copied n times side by side across a
//    stock n sample stocks large, each copy moved through its module's door
//    (moveBy), or, for units that name contours of the figure (CP, AREA,
//    SIDE) and the probing unit, its figure statements renamed and its
//    points, origin and drawn passes moved; n doubles until `taiwa check`
//    refuses the job (the move budget, or the stock's 10 m), then the
//    largest n it accepts is looked for between;
//  - FACE: one unit at step-over 0.01 on a square stock whose side doubles;
//  - TURN: a staircase profile of n rows up to the 1,000 a profile may have,
//    on the one-turret lathe and on the two-path lathe.
// The jobs run on a copy of the sample's milling machine with 10 m of travel
// (a shop machine file in a temporary ~/.config), so that the machine's
// travel is not what refuses them. Every check and export is the `taiwa`
// command itself (build/app/taiwa, next to this program's folder), spawned:
// wall time and peak memory (ru_maxrss) are its alone. The export
// is the operator's: verification, tape, sheet with pictures, steps.
//
// It runs for several minutes. `bench_largest_jobs MODULE...` runs those
// rows only (M4, M2D, CP, AREA, SIDE, HOLES, PROBE, SURFACE, FACE, TURN,
// TURN2).
#include "bench_anchor.h"
#include "bench_child.h"
#include "bench_paths.h"

#include "job/job_file.h"
#include "modules/registry.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace taiwa;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kMaxSide = 10000.0;  // mm: the largest stock side the job checks accept

fs::path g_home;        // the temporary home of the run
std::string g_taiwa;    // the command

json readJson(const fs::path& p)
{
    std::ifstream in(p);
    return json::parse(in);
}

void writeText(const fs::path& p, const std::string& text)
{
    std::ofstream out(p, std::ios::binary);
    out << text;
}

// `taiwa ARGS...` in a child, its output into `log`: spawned, not forked,
// so that its peak memory is its own and not this process's pages.
bench::Measured runTaiwa(const std::vector<std::string>& args, const fs::path& log)
{
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    std::vector<char*> argv{const_cast<char*>(g_taiwa.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    bench::Measured m;
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, g_taiwa.c_str(), &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    if (spawned != 0) return m;
    int status = 0;
    rusage usage{};
    ::wait4(pid, &status, 0, &usage);
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.peakKb = usage.ru_maxrss;
    if (WIFEXITED(status)) m.exitCode = WEXITSTATUS(status);
    m.ok = m.exitCode == 0;
    return m;
}

// The moves the job's paths would hold, as the budget estimates them; -1
// when the job is refused.
double estimatedMoves(const std::string& jobText)
{
    const auto read = readJob(jobText);
    if (!read.job) return -1;
    PlanOptions stepsOnly;
    stepsOnly.withToolPaths = false;
    const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary(), stepsOnly);
    if (!plan.ok()) return -1;
    double moves = 0;
    for (const Step& s : plan.steps)
        if (s.tool)
            if (const Tool* t = plan.tool(s.tool->toolId)) moves += estimateMoves(s, *t, plan.technology, stepsOnly.path);
    return moves;
}

// ---- the jobs -------------------------------------------------------------

// Renames the figure's names of copy k (P1 -> P1C7) and moves its points.
std::vector<std::string> movedFigure(const std::vector<std::string>& figure, int k, double dx, double dy, std::map<std::string, std::string>& names)
{
    static const std::regex statement(R"(^\s*([A-Za-z][A-Za-z0-9]*)\s*=)");
    static const std::regex point(R"(POINT/\s*(-?[0-9.]+)\s*,\s*(-?[0-9.]+)\s*$)", std::regex::icase);
    static const std::regex word(R"([A-Za-z][A-Za-z0-9]*)");
    names.clear();
    for (const auto& line : figure) {
        std::smatch m;
        if (std::regex_search(line, m, statement)) names[m[1]] = m[1].str() + "C" + std::to_string(k);
    }
    std::vector<std::string> out;
    for (std::string line : figure) {
        if (line.rfind("$$", 0) == 0) continue;
        std::string renamed;
        auto last = line.cbegin();
        for (std::sregex_iterator it(line.begin(), line.end(), word), end; it != end; ++it) {
            renamed.append(last, line.cbegin() + it->position());
            const auto n = names.find(it->str());
            renamed += n != names.end() ? n->second : it->str();
            last = line.cbegin() + it->position() + it->length();
        }
        renamed.append(last, line.cend());
        std::smatch m;
        if (std::regex_search(renamed, m, point)) {
            std::ostringstream p;
            p.precision(12);
            p << "POINT/" << std::stod(m[1]) + dx << ", " << std::stod(m[2]) + dy;
            renamed = m.prefix().str() + p.str();
        }
        out.push_back(renamed);
    }
    return out;
}

// The sample job copied n times across a stock of copies, as `cols` columns.
std::string tiled(const json& sample, int n)
{
    const json& stock = sample["stock"];
    const double w = stock["width"], l = stock["length"];
    int cols = 1;
    while (cols * cols < n) ++cols;
    const int rows = (n + cols - 1) / cols;
    json job = sample;
    job["machine"] = std::string(sample.value("machine", "vmc")) + "-10m";
    job["stock"]["width"] = cols * w;
    job["stock"]["length"] = rows * l;
    job["units"] = json::array();
    job["figure"] = json::array();
    std::vector<json> units;
    std::map<std::string, std::string> names;
    for (int k = 0; k < n; ++k) {
        const double dx = (k % cols) * w, dy = (k / cols) * l;
        if (sample.contains("figure"))
            for (auto& s : movedFigure(sample["figure"].get<std::vector<std::string>>(), k, dx, dy, names)) job["figure"].push_back(s);
        for (json u : sample["units"]) {
            u["name"] = u.value("name", std::string("unit")) + " " + std::to_string(k + 1);
            for (const char* key : {"outline", "contour"})
                if (u.contains(key)) u[key] = names.at(u[key]);
            if (u.contains("islands"))
                for (auto& i : u["islands"]) i = names.at(i);
            if (u.contains("points"))
                for (auto& p : u["points"]) p = json::array({p[0].get<double>() + dx, p[1].get<double>() + dy});
            if (u.contains("origin")) u["origin"] = json::array({u["origin"][0].get<double>() + dx, u["origin"][1].get<double>() + dy});
            units.push_back(u);
        }
    }
    if (job["figure"].empty()) job.erase("figure");
    // Read once to move the units whose door moves them (the pockets, holes,
    // surfaces): the job's own writer then gives the file.
    job["units"] = units;
    auto read = readJob(job.dump());
    if (!read.job) return job.dump();
    Job typed = *read.job;
    std::size_t i = 0;
    for (int k = 0; k < n; ++k)
        for (std::size_t s = 0; s < sample["units"].size(); ++s, ++i) {
            auto& m = typed.units[i].module;
            if (const ModuleKind* kind = findModuleKind(m.name())) kind->moveBy(m, {(k % cols) * w, (k / cols) * l});
        }
    return writeJob(typed);
}

// One FACE unit at the finest step-over it accepts (1 % of the face mill)
// on a square stock of `side` mm.
std::string faced(const json& sample, int side)
{
    json job = sample;
    job["units"][0]["stepOver"] = 0.01;
    job["machine"] = std::string(sample.value("machine", "vmc")) + "-10m";
    job["stock"]["width"] = side;
    job["stock"]["length"] = side;
    return job.dump();
}

// A staircase of n rows (n/2 steps) from Ø20 to Ø54 along 300 mm of a 60 mm
// bar (the shipped lathes' spindles pass 65 mm), on `machine`.
std::string staircase(int n, const std::string& machine)
{
    json rows = json::array();
    const int steps = std::max(1, n / 2);
    const double dx = 34.0 / steps, dz = 300.0 / steps;
    double x = 20.0, z = 0.0;
    for (int i = 0; i < steps; ++i) {
        rows.push_back({{"id", 2 * i + 1}, {"kind", "line"}, {"x", x}, {"z", z}});
        z -= dz;
        rows.push_back({{"id", 2 * i + 2}, {"kind", "line"}, {"x", x}, {"z", z}});
        x += dx;
    }
    json job{{"format", "taiwa-job"}, {"version", 5}, {"name", "staircase"}, {"lengthUnit", "mm"}, {"material", "steel-s45c"},
             {"machine", machine}, {"workOffset", "G54"},
             {"stock", {{"shape", "bar"}, {"diameter", 60}, {"length", 320}, {"face", 1}, {"bore", 0}}},
             {"units", json::array({{{"module", "TURN"}, {"name", "Outside"}, {"side", "outer"}, {"start", {{"x", 0}, {"z", 0}}}, {"rows", rows}}})}};
    return job.dump();
}

// ---- the rows -------------------------------------------------------------

struct Row {
    std::string name;
    std::string knob;                        // what n counts
    int first, most;                         // the ladder starts at `first`, doubling, at most `most`
    std::function<std::string(int)> job;     // the job of size n
};

struct Rung {
    int n = 0;
    double moves = -1;
    bench::Measured check, exported;
    bool accepted() const { return check.ok; }
};

Rung measure(const Row& row, int n, bool exportToo)
{
    Rung r;
    r.n = n;
    const std::string text = row.job(n);
    const fs::path file = g_home / (row.name + "-" + std::to_string(n) + ".taiwa");
    writeText(file, text);
    r.check = runTaiwa({"check", file.string()}, g_home / "check.log");
    if (!r.accepted()) return r;
    r.moves = estimatedMoves(text);
    if (exportToo) {
        const fs::path out = g_home / ("out-" + row.name + "-" + std::to_string(n));
        // --no-cache: each export verifies (the largest job may be a rung already exported).
        r.exported = runTaiwa({"export", file.string(), "--out", out.string(), "--no-cache"}, g_home / "export.log");
        fs::remove_all(out);
    }
    fs::remove(file);
    return r;
}

// The first refusal `taiwa check` gave, without the file's name.
std::string whyRefused()
{
    std::ifstream in(g_home / "check.log");
    std::string line;
    while (std::getline(in, line))
        if (const auto at = line.find(".taiwa: "); at != std::string::npos && line.find("warning") == std::string::npos)
            return line.substr(at + 8, 160);
    return "no reason printed";
}

void print(const Row& row, const Rung& r, const char* note)
{
    if (!r.accepted()) {
        std::printf("%-8s %-6s %7d  refused by check in %6.2f s: %s\n", row.name.c_str(), row.knob.c_str(), r.n, r.check.seconds,
                    whyRefused().c_str());
    } else {
        std::printf("%-8s %-6s %7d  %11.0f moves  check %6.2f s %6.0f MB  export %6.2f s %6.0f MB %s  %s\n", row.name.c_str(),
                    row.knob.c_str(), r.n, r.moves, r.check.seconds, r.check.peakKb / 1024.0, r.exported.seconds,
                    r.exported.peakKb / 1024.0, r.exported.ok ? "ok" : r.exported.exitCode == 3 ? "faults" : "FAILED", note);
    }
    std::fflush(stdout);
}

void runRow(const Row& row)
{
    // The ladder: doubling while check accepts.
    Rung lastIn;
    int firstOut = 0;
    for (int n = row.first;; n = std::min(2 * n, row.most)) {
        Rung r = measure(row, n, true);
        print(row, r, "");
        if (!r.accepted()) {
            firstOut = n;
            break;
        }
        lastIn = std::move(r);
        if (n == row.most) break;
    }
    if (lastIn.n == 0) return;
    // The largest it accepts, between the last rung in and the first out
    // (the last rung itself when the ladder reached its top).
    int largest = lastIn.n;
    if (firstOut > 0) {
        int lo = lastIn.n, hi = firstOut;
        while (hi - lo > std::max(1, lo / 16)) {
            const int mid = lo + (hi - lo) / 2;
            const Rung r = measure(row, mid, false);
            (r.accepted() ? lo : hi) = mid;
        }
        largest = lo;
    }
    const Rung r = largest == lastIn.n ? lastIn : measure(row, largest, true);
    const bool within = r.exported.ok && r.exported.seconds < 60 && r.check.seconds < 60 && r.exported.peakKb < 2 * 1024 * 1024;
    print(row, r, within ? "<- largest accepted: within 60 s and 2 GB" : "<- largest accepted: OVER 60 s or 2 GB");
}

void writeMachines()
{
    const fs::path dir = g_home / ".config/taiwa/machines";
    fs::create_directories(dir);
    json vmc = readJson(fs::path(bench::sample("m4-standard")).parent_path() / "../machines/vmc.json");
    vmc["id"] = "vmc-10m";
    vmc["name"] = "Bench: the vertical machining centre with 10 m of travel";
    vmc.erase("names");
    vmc["travel"]["x"] = {-200, kMaxSide + 200};
    vmc["travel"]["y"] = {-200, kMaxSide + 200};
    writeText(dir / "vmc-10m.json", vmc.dump(1));
}

}  // namespace

int main(int argc, char** argv)
{
    char exe[4096] = {};
    const ssize_t len = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0) return 1;
    g_taiwa = (fs::path(exe).parent_path().parent_path() / "app/taiwa").string();
    if (!fs::exists(g_taiwa)) {
        std::fprintf(stderr, "bench_largest_jobs: %s not built (ninja -C build taiwa)\n", g_taiwa.c_str());
        return 1;
    }
    char tmpl[] = "/tmp/taiwa-largest-XXXXXX";
    if (!::mkdtemp(tmpl)) return 1;
    g_home = tmpl;
    // A home of its own: the shop machine, an empty tool library of the
    // shipped tools, no verification cache of earlier runs.
    ::setenv("HOME", g_home.c_str(), 1);
    ::setenv("XDG_CONFIG_HOME", (g_home / ".config").c_str(), 1);
    ::setenv("XDG_DATA_HOME", (g_home / ".local/share").c_str(), 1);
    ::setenv("XDG_CACHE_HOME", (g_home / ".cache").c_str(), 1);
    ::setenv("QT_QPA_PLATFORM", "offscreen", 1);
    writeMachines();

    const auto sample = [](const char* stem) { return readJson(bench::sample(stem)); };
    std::vector<Row> rows;
    for (const auto& [module, file] : std::vector<std::pair<std::string, std::string>>{
             {"M4", "m4-standard"}, {"M2D", "m2d-standard"}, {"CP", "cp-islands"},
             {"AREA", "area-drawn-passes"}, {"SIDE", "side-boss"}, {"HOLES", "holes-grid"},
             {"PROBE", "probe-bore"}, {"SURFACE", "surface-cover"}}) {
        const json s = sample(file.c_str());
        rows.push_back({module, "copies", 1, 1 << 20, [s](int n) { return tiled(s, n); }});
    }
    const json face = sample("face-top");
    rows.push_back({"FACE", "side", 125, static_cast<int>(kMaxSide), [face](int n) { return faced(face, n); }});
    rows.push_back({"TURN", "rows", 8, 1000, [](int n) { return staircase(n, "lathe"); }});
    rows.push_back({"TURN2", "rows", 8, 1000, [](int n) { return staircase(n, "lathe-two-path"); }});

    const std::set<std::string> only(argv + 1, argv + argc);
    std::printf("anchor: a plain to_chars loop writes %.1f M tape-like lines/s\n", bench::toCharsLinesPerSecond() / 1e6);
    std::printf("module   knob         n  estimate           taiwa check             taiwa export\n");
    for (const Row& row : rows)
        if (only.empty() || only.count(row.name)) runRow(row);
    fs::remove_all(g_home);
    return 0;
}
