// Generated contour jobs judged (contour_generator.h: runContourCase) and
// counted (ContourTally): the plan or its refusal, the verification, the
// linuxcnc tape through rs274 and the tool centre against the walls.
#include "support/contour_generator.h"
#include "support/rs274.h"

#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"
#include "verify/verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace taiwa::test {

namespace {

constexpr double kResolution = 0.15;  // mm: the verification's cells
constexpr double kSpacing = 0.05;    // mm between the tape's points measured against the walls
constexpr double kWallTolerance = 1e-3;

double since(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
// The linuxcnc tape writes mm to 3 decimals: an end point may move 0.5 µm
// in x and y, an arc's centre (start + I, J) 1 µm: on the tape the centre
// is allowed that much more.
constexpr double kTapeRounding = 1.5e-3;

// The points of a CL path's cutting moves below the top, every kSpacing,
// with the step's tool radius.
template <typename Visit>
void clPoints(const Plan& plan, Visit visit)
{
    for (const Step& s : plan.steps) {
        if (!s.path || !s.tool) continue;
        const Tool* tool = plan.tool(s.tool->toolId);
        if (!tool) continue;
        Point3 at = s.path->start;
        for (const Move& m : s.path->moves) {
            const Point3 from = at;
            at = m.end;
            if (m.kind == MoveKind::Rapid || m.kind == MoveKind::DrillCycle) continue;
            if (from.z >= -1e-6 && m.end.z >= -1e-6) continue;
            const bool arc = m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW;
            const double sweep = arc ? arcSweep(from, m) : 0.0;
            const double r = std::hypot(from.x - m.centre.x, from.y - m.centre.y);
            const double l = arc ? std::abs(sweep) * r : std::hypot(m.end.x - from.x, m.end.y - from.y);
            const int n = std::max(1, static_cast<int>(std::ceil(l / kSpacing)));
            const double a0 = std::atan2(from.y - m.centre.y, from.x - m.centre.x);
            for (int i = 0; i <= n; ++i) {
                const double t = static_cast<double>(i) / n;
                const double z = from.z + t * (m.end.z - from.z);
                if (z >= -1e-6) continue;
                const Point2 p = arc ? Point2{m.centre.x + r * std::cos(a0 + t * sweep), m.centre.y + r * std::sin(a0 + t * sweep)}
                                     : Point2{from.x + t * (m.end.x - from.x), from.y + t * (m.end.y - from.y)};
                visit(p, z, *tool, s);
            }
        }
    }
}

// The fields each module has (a refusal elsewhere names what the operator cannot change).
bool moduleField(const std::string& module, const std::string& field)
{
    static const std::set<std::string> cp{"outline", "islands", "depth", "U", "F", "stepOver", "tools",
                                          "tools.roughing", "tools.floor", "tools.wall"};
    static const std::set<std::string> side{"contour", "side", "direction", "depth", "width", "U", "F", "stepOver", "tools.side"};
    return module == "CP" ? cp.count(field) > 0 : side.count(field) > 0;
}

std::vector<Point3> pointsOf(const CanonMove& m)
{
    if (m.kind == CanonMove::Arc) {
        std::vector<Point3> pts{m.start};
        const auto s = sampleArc(m, kSpacing);
        pts.insert(pts.end(), s.begin(), s.end());
        return pts;
    }
    const double l = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y, m.end.z - m.start.z);
    const int n = std::max(1, static_cast<int>(std::ceil(l / kSpacing)));
    std::vector<Point3> pts;
    for (int i = 0; i <= n; ++i) {
        const double t = static_cast<double>(i) / n;
        pts.push_back({m.start.x + t * (m.end.x - m.start.x), m.start.y + t * (m.end.y - m.start.y),
                       m.start.z + t * (m.end.z - m.start.z)});
    }
    return pts;
}

}  // namespace

ContourOutcome runContourCase(const ContourCase& c, bool withTape)
{
    ContourOutcome o;
    const std::vector<Tool>& library = defaultToolLibrary();
    Plan plan;
    auto clock = std::chrono::steady_clock::now();
    try {
        plan = planJob(c.job, TechnologyTable::builtIn(), library);
        o.planSeconds = since(clock);
    } catch (const std::exception& e) {
        o.failure = fmt::format("planning threw: {}", e.what());
        return o;
    }
    if (!plan.ok()) {
        for (const Diagnostic& d : plan.diagnostics)
            if (d.severity == Severity::Error) {
                o.refusedOn = d.field;
                o.refusal = d.message;
                break;
            }
        if (o.refusal.empty()) o.failure = fmt::format("refused on {} saying nothing", o.refusedOn);
        else if (o.refusal.find("  ") != std::string::npos || o.refusal.ends_with(" ") || o.refusal.find(" ,") != std::string::npos)
            o.failure = fmt::format("a refusal with a word missing: {}", o.refusal);
        else if (!moduleField(c.module, o.refusedOn))
            o.failure = fmt::format("refused on {}, a field {} does not have: {}", o.refusedOn, c.module, o.refusal);
        return o;
    }
    o.planned = true;
    verify::Options vo;
    vo.resolution = kResolution;
    clock = std::chrono::steady_clock::now();
    const verify::Report report = verify::verifyPlan(plan, vo);
    o.verifySeconds = since(clock);
    std::string fatal;
    for (const verify::Finding& f : report.findings) {
        if (!f.fatal()) ++o.restMaterial;
        else if (fatal.empty()) fatal = verify::describe(f, plan);
    }
    o.clean = fatal.empty();
    if (!o.clean) o.failure = "the verification refuses the plan: " + fatal;
    // The plan's own tool centre (before the tape's rounding) against the walls.
    std::string clWhere;
    clPoints(plan, [&](Point2 p, double z, const Tool& tool, const Step& s) {
        double d = 1e300;
        for (const Contour& w : c.walls) d = std::min(d, wallDistance(w, p));
        if (d - tool.radius() < o.clMargin) {
            o.clMargin = d - tool.radius();
            clWhere = fmt::format("T{} (R {:g}) at X{:.4f} Y{:.4f} Z{:.4f} in {}", tool.id, tool.radius(), p.x, p.y, z, s.label());
        }
    });
    if (o.clMargin < -kWallTolerance && o.failure.empty())
        o.failure = fmt::format("the plan's tool centre comes {:.4f} mm inside R of a wall: {}", -o.clMargin, clWhere);

    clock = std::chrono::steady_clock::now();
    o.tape = postProcess(plan.steps, plan.tools, postOptions(plan, "linuxcnc")).nc;
    o.tapeSeconds = since(clock);
    if (withTape) runTapes({{&c, &o}});
    return o;
}

void runTapes(const std::vector<std::pair<const ContourCase*, ContourOutcome*>>& batch)
{
    const auto clock = std::chrono::steady_clock::now();
    // One program of them all: each tape's M30 left out but the last's, its
    // steps renumbered on (the step of a move names its case).
    std::string nc;
    std::vector<std::size_t> caseOfStep{0};
    for (std::size_t k = 0; k < batch.size(); ++k) {
        const std::size_t first = caseOfStep.size() - 1;
        std::size_t last = first;
        std::size_t at = 0;
        const std::string& tape = batch[k].second->tape;
        while (at < tape.size()) {
            const std::size_t eol = std::min(tape.find('\n', at), tape.size());
            std::string line = tape.substr(at, eol - at);
            at = eol + 1;
            if (line == "M30") continue;
            if (line.starts_with("(STEP ")) {
                const std::size_t colon = line.find(':');
                const std::size_t n = first + std::stoul(line.substr(6, colon - 6));
                line = fmt::format("(STEP {}{}", n, line.substr(colon));
                last = std::max(last, n);
            }
            nc += line + "\n";
        }
        caseOfStep.resize(last + 1, k);
    }
    nc += "M30\n";
    const Rs274Result run = runRs274(nc);
    if (const char* debug = std::getenv("TAIWA_CONTOUR_NC")) {
        FILE* f = std::fopen(debug, "w");
        if (f) {
            std::fprintf(f, "%s\n(moves %zu ok %d)\n", nc.c_str(), run.moves.size(), run.ok ? 1 : 0);
            std::fclose(f);
        }
    }
    if (!run.ok && batch.size() > 1) {  // which one: each on its own
        for (const auto& one : batch) runTapes({one});
        return;
    }
    const double seconds = since(clock) / static_cast<double>(batch.size());
    std::vector<std::string> where(batch.size());
    for (const auto& [c, o] : batch) {
        o->tapeRun = true;
        o->tapeAccepted = run.ok;
        o->tapeSeconds += seconds;
        if (!run.ok && o->failure.empty()) o->failure = "rs274 refuses the tape: " + run.errors.toStdString();
    }
    const std::vector<Tool>& library = defaultToolLibrary();
    for (const CanonMove& m : run.moves) {
        if (m.kind == CanonMove::Traverse || (m.start.z >= -1e-6 && m.end.z >= -1e-6)) continue;
        if (m.step <= 0 || static_cast<std::size_t>(m.step) >= caseOfStep.size()) continue;
        const std::size_t k = caseOfStep[static_cast<std::size_t>(m.step)];
        const ContourCase& c = *batch[k].first;
        ContourOutcome& o = *batch[k].second;
        const Tool* tool = findTool(library, m.tool);
        if (!tool) continue;
        for (const Point3& p : pointsOf(m)) {
            if (p.z >= -1e-6) continue;
            double d = 1e300;
            for (const Contour& w : c.walls) d = std::min(d, wallDistance(w, {p.x, p.y}));
            if (d - tool->radius() < o.wallMargin) {
                o.wallMargin = d - tool->radius();
                where[k] = fmt::format("T{} (R {:g}) at X{:.4f} Y{:.4f} Z{:.4f}", tool->id, tool->radius(), p.x, p.y, p.z);
            }
        }
    }
    for (std::size_t k = 0; k < batch.size(); ++k) {
        ContourOutcome& o = *batch[k].second;
        if (o.wallMargin < -(kWallTolerance + kTapeRounding) && o.failure.empty())
            o.failure = fmt::format("the tape's tool centre comes {:.4f} mm inside R of a wall: {}", -o.wallMargin, where[k]);
        o.tape.clear();
    }
}

void ContourTally::add(const ContourCase& c, const ContourOutcome& o)
{
    ++cases;
    ++byModule[c.module];
    planSeconds += o.planSeconds;
    verifySeconds += o.verifySeconds;
    tapeSeconds += o.tapeSeconds;
    necks += c.neck;
    touching += c.touching;
    notches += c.notch;
    if (o.planned) ++planned;
    else if (!o.refusal.empty()) {
        ++refused;
        const std::string key = c.module + " " + o.refusedOn;
        if (++refusedOn[key] == 1) refusalExample[key] = fmt::format("seed {}: {}", c.seed, o.refusal);
    }
    if (o.clean) ++clean;
    if (o.restMaterial > 0) ++withRest;
    if (o.tapeRun) ++tapes;
    if (o.tapeAccepted) ++tapesAccepted;
    if (o.tapeRun) smallestMargin = std::min(smallestMargin, o.wallMargin);
    if (o.planned) smallestClMargin = std::min(smallestClMargin, o.clMargin);
    if (!o.failure.empty()) failing.push_back(fmt::format("seed {} ({}): {}", c.seed, c.what, o.failure));
}

std::string ContourTally::summary() const
{
    std::string refusals, fails;
    for (const auto& [k, n] : refusedOn) refusals += fmt::format("\n  {} refused on {} (e.g. {})", n, k, refusalExample.at(k));
    for (std::size_t i = 0; i < failing.size() && i < 20; ++i) fails += "\n  FAILING " + failing[i];
    return fmt::format("{} cases ({} CP, {} SIDE; {} with a neck, {} with an island touching, {} with a notch): "
                       "{} planned, {} verified clean ({} with material left reported), {} refused with a reason; "
                       "{} tapes, {} accepted by rs274; the tool centre's least margin to R {:.6f} mm on the plan, {:.6f} mm on "
                       "the tapes; {} failing; time in planning {:.1f} s, verifying {:.1f} s, posting and rs274 {:.1f} s{}{}",
                       cases, byModule.count("CP") ? byModule.at("CP") : 0, byModule.count("SIDE") ? byModule.at("SIDE") : 0,
                       necks, touching, notches, planned, clean, withRest, refused, tapes, tapesAccepted,
                       smallestClMargin > 1e299 ? 0.0 : smallestClMargin, smallestMargin > 1e299 ? 0.0 : smallestMargin, failing.size(), planSeconds, verifySeconds, tapeSeconds,
                       refusals, fails);
}

}  // namespace taiwa::test
