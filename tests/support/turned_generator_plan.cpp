// Generated turned profiles as lathe jobs, planned and verified, and the
// counts of a run (turned_generator.h: PlanCheck, PlanTally). The bar is
// kept within the lathe's spindle bore (Ø65) where the part allows.
#include "support/turned_generator.h"

#include "support/rs274.h"
#include "support/turning_oracle.h"

#include "model/turned_geometry.h"
#include "modules/turn/turn.h"
#include "pipeline/pipeline.h"
#include "post/lathe_post.h"
#include "tools/tool_library.h"
#include "turning/profile_resolve.h"
#include "verify/verify.h"

#include <QFile>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace taiwa::test {

using namespace turning;

PlanCheck planAndVerify(const GeneratedProfile& g, bool rs274)
{
    PlanCheck out;
    const Resolution r = resolveProfile(g.profile);
    double rMax = 0.0, zMin = 0.0;
    for (const Edge& e : r.profile.edges)
        for (int k = 0; k <= 32; ++k) {
            const ZR q = pointAt(e.geometry, length(e.geometry) * k / 32.0);
            rMax = std::max(rMax, q.r);
            zMin = std::min(zMin, q.z);
        }
    Job job;
    job.name = fmt::format("generated {}", g.seed);
    job.machine = "lathe";
    job.material = "steel-s45c";
    const double over = g.profile.side == ProfileSide::Outer ? 3.0 : 12.0;
    job.bar = BarStock{std::ceil(std::min(2.0 * rMax + over, std::max(65.0, 2.0 * rMax + 1.0))), std::ceil(-zMin) + 30.0,
                       1.0, 0.0};
    TurnUnit unit;
    unit.profile = g.profile;
    job.units.push_back({"generated", unit, {}});
    const Plan plan = planJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
    if (!plan.ok()) {
        for (const Diagnostic& d : plan.diagnostics)
            if (d.severity == Severity::Error) {
                const auto dot = d.field.rfind('.');
                out.refusedOn = dot == std::string::npos ? d.field : d.field.substr(dot + 1);
                out.refusal = d.message;
                break;
            }
        return out;
    }
    out.planned = true;
    for (const Diagnostic& d : plan.diagnostics)
        if (d.severity == Severity::Warning) out.warnings.push_back(d.message);
    const verify::Report report = verify::verifyPlan(plan);
    for (const verify::Finding& f : report.findings) {
        const std::string kind = verify::toKey(f.kind);
        if (++out.findings[kind] == 1) out.first[kind] = verify::describe(f, plan);
        out.fatal = out.fatal || f.fatal();
    }
    if (rs274) {
        const std::string nc = postProcess(plan.steps, plan.tools, postOptions(plan, "linuxcnc", LengthUnit::Millimetre, 1000, job.name)).nc;
        // TAIWA_RS274_LOCK=<file>: each run holds that lock (flock) only
        // while rs274 runs, as a long bench should, not the whole run.
        int lock = -1;
        if (const QByteArray file = qgetenv("TAIWA_RS274_LOCK"); !file.isEmpty()) {
            lock = ::open(file.constData(), O_RDWR | O_CREAT, 0666);
            if (lock >= 0) ::flock(lock, LOCK_EX);
        }
        const Rs274Result run = runRs274(nc, latheToolTable(plan));
        if (lock >= 0) ::close(lock);
        out.rs274Run = true;
        // TAIWA_GENERATED_DUMP=<folder>: each tape, its tool table and rs274's verdict there.
        if (const QString dump = qEnvironmentVariable("TAIWA_GENERATED_DUMP"); !dump.isEmpty()) {
            QFile f(dump + "/" + QString::number(g.seed) + ".ngc");
            std::string edges;
            for (const TurnedPart& t : plan.turned)
                for (const turning::DeformedEdge& e : t.deformed.edges)
                    edges += fmt::format("({} {}: Z{:.4f} X{:.4f} to Z{:.4f} X{:.4f}{})\n", e.id, toKey(e.origin), e.geometry.a.z,
                                         2 * e.geometry.a.r, e.geometry.b.z, 2 * e.geometry.b.r,
                                         e.geometry.arc ? fmt::format(" R{:.4f} {}", e.geometry.radius, e.geometry.ccw ? "ccw" : "cw") : "");
            if (f.open(QIODevice::WriteOnly))
                f.write((nc + "\n(" + latheToolTable(plan) + ")\n(" + run.errors.toStdString() + ")\n" + edges).c_str());
        }
        if (!run.ok) out.rs274Refusal = run.errors.isEmpty() ? "exit code " + std::to_string(run.exitCode) : run.errors.toStdString();
    }
    return out;
}

PlanCheck planAndVerify(const TurnedProfile& profile, bool rs274)
{
    GeneratedProfile g;
    g.profile = profile;
    return planAndVerify(g, rs274);
}

void PlanTally::add(std::uint64_t seed, const PlanCheck& c, const std::vector<std::string>& drawn)
{
    ++profiles;
    for (const std::string& s : drawn) ++shapes[s];
    if (!c.planned) {
        if (++refusedOn[c.refusedOn] == 1) refusal[c.refusedOn] = fmt::format("seed {}: {}", seed, c.refusal);
        return;
    }
    ++planned;
    if (!c.fatal) ++clean;
    else if (fatalSeeds.size() < 5) fatalSeeds.push_back(seed);
    if (c.rs274Run) ++rs274Run;
    if (!c.rs274Refusal.empty()) {
        if (++rs274Refused == 1) rs274Example = fmt::format("seed {}: {}", seed, c.rs274Refusal);
        if (rs274Seeds.size() < 5) rs274Seeds.push_back(seed);
    }
    for (const auto& [kind, n] : c.findings) {
        ++withFinding[kind];
        auto& s = seeds[kind];
        if (s.size() < 5) s.push_back(seed);
        if (!example.count(kind)) example[kind] = c.first.at(kind);
    }
}

std::string PlanTally::summary() const
{
    std::string refused, found, drawn;
    for (const auto& [k, n] : shapes) drawn += fmt::format("{}{} {}", drawn.empty() ? "" : ", ", n, k);
    for (const auto& [k, n] : refusedOn) refused += fmt::format("\n  {} refused on {} (e.g. {})", n, k, refusal.at(k));
    for (const auto& [k, n] : withFinding) {
        std::string list;
        for (std::uint64_t s : seeds.at(k)) list += fmt::format("{}{}", list.empty() ? "" : " ", s);
        found += fmt::format("\n  {} profiles with {} (seeds {}; e.g. {})", n, k, list, example.at(k));
    }
    std::string rs;
    if (rs274Run > 0) {
        std::string list;
        for (std::uint64_t s : rs274Seeds) list += fmt::format("{}{}", list.empty() ? "" : " ", s);
        rs = fmt::format("; rs274 ran {} tapes, refused {}{}", rs274Run, rs274Refused,
                         rs274Refused ? fmt::format(" (seeds {}; e.g. {})", list, rs274Example) : "");
    }
    return fmt::format("{} profiles{}: {} planned ({} verified clean: no gouge, collision, rapid into stock or travel "
                       "limit), {} refused by the planner{}{}{}",
                       profiles, drawn.empty() ? "" : " (" + drawn + ")", planned, clean, profiles - planned, rs, refused, found);
}

}  // namespace taiwa::test
