// Module TURN behind its door (modules/module_kind.h): the job file's keys,
// the input checks (the profile table, the allowance table, the bar, the
// pinned tools and the steps turned off), the deformed profile handed to the
// plan, and the turning steps (core/modules/turn/turn_plan.h).
#include "model/translate_noop.h"
#include "modules/module_kind.h"
#include "modules/turn/turn.h"
#include "modules/turn/turn_file.h"

#include "check/messages.h"
#include "io/job_messages.h"
#include "io/json_write.h"
#include "tools/turning_tools.h"
#include "turning/allowance.h"
#include "modules/turn/turn_deform.h"
#include "modules/turn/turn_plan.h"
#include "turning/profile_resolve.h"
#include "model/turned_geometry.h"

#include <fmt/format.h>

#include <algorithm>

namespace taiwa {

namespace {

using namespace turning;
using ordered = nlohmann::ordered_json;

constexpr std::size_t kMaxRows = kMaxProfileRows, kMaxAllowances = kMaxAllowanceRows;

// The unit's turned part from its resolved profile and its deformation
// (deformTurned, the one computation of the check, turned() and, through
// turned(), the profile editor).
TurnedPart partOf(int unit, const Resolution& resolved, TurnDeformation d)
{
    TurnedPart part;
    part.unit = unit;
    part.profile = resolved.profile;
    part.complete = resolved.ok() && d.deformation.ok();
    part.deformed = std::move(d.deformation.profile);
    part.noseRadiusTool = std::move(d.noseRadiusTool);
    return part;
}

class TurnKind final : public ModuleKindOf<TurnUnit> {
public:
    MachineKind machineKind() const override { return MachineKind::Lathe; }
    std::vector<std::string> stepKeys() const override { return turning::turnStepKeys(); }
    // Turning steps come with their paths (their TurnStep, turnOf).
    double estimateMoves(const Step& step, const Tool&, const TechnologyData&, const PathParameters&) const override
    {
        return turnOf(step) ? static_cast<double>(turnOf(step)->path.moves.size()) : 10;
    }
    // Drilling runs at a fixed rpm (G97); every other turning step at a surface speed.
    bool surfaceSpeedStep(const std::string& key) const override { return key != "drill" && key != "centre-drill"; }

    ModuleInput makeDefault(const Stock& /*stock*/) const override
    {
        // A stepped shaft: front face, Ø30 with a chamfer, shoulder, Ø40.
        TurnUnit t;
        auto row = [](int id, double x, double z) {
            ProfileRow r;
            r.id = id;
            r.x = x;
            r.z = z;
            return r;
        };
        t.profile.rows = {row(1, 30, 0), row(2, 30, -30), row(3, 40, -30), row(4, 40, -60)};
        t.profile.rows[0].corner = CornerKind::Chamfer;
        t.profile.rows[0].cornerSize = 1.0;
        return t;
    }

    const TurnedProfile* turnedProfile(const ModuleInput& m) const override
    {
        const TurnUnit* t = m.getIf<TurnUnit>();
        return t ? &t->profile : nullptr;
    }
    bool setTurnedProfile(ModuleInput& m, const TurnedProfile& p) const override
    {
        TurnUnit* t = m.getIf<TurnUnit>();
        if (!t) return false;
        t->profile = p;
        return true;
    }

    // The check makes it for the plan (check::UnitReport::turned); the
    // profile editor and a plan of an unchecked unit call this.
    std::optional<TurnedPart> turned(const ModuleInput& mm, const UnitPlanContext& ctx) const override
    {
        const TurnUnit& t = mm.as<TurnUnit>();
        const Resolution r = resolveProfile(t.profile);
        const BarStock* bar = ctx.job && ctx.job->bar ? &*ctx.job->bar : nullptr;
        TurnDeformation d = deformTurned(t.profile, r.profile, t.tools, t.skip, ctx.library, bar, LengthUnit::Millimetre);
        return partOf(ctx.unit, r, std::move(d));
    }

protected:
    TurnUnit readInput(const io::ObjectFields& f) const override { return readTurnUnit(f); }
    void writeInput(const TurnUnit& t, ordered& u) const override { writeTurnUnit(t, u); }

    check::UnitReport checkInput(const TurnUnit& t, int unitNo, const check::Context& ctx) const override
    {
        check::UnitReport report;
        auto add = [&](const FieldProblem& p) {
            report.diagnostics.push_back({Severity::Error, unitNo, TurnUnit::kName, p.field, p.message});
        };
        // Bounded work: the chain check is quadratic in the rows, the union
        // grows with the allowance rows.
        if (t.profile.rows.size() > kMaxRows || t.profile.allowances.size() > kMaxAllowances) {
            const bool rows = t.profile.rows.size() > kMaxRows;
            add({rows ? "rows" : "allowances",
                 fmt::format(
                     TAIWA_TRANSLATE_NOOP(
                         "taiwa::msg",
                         "the {} has {} rows; a turned profile has at most {} (split the part into several units)"),
                     rows ? "profile table" : "grinding-allowance table",
                     rows ? t.profile.rows.size() : t.profile.allowances.size(), rows ? kMaxRows : kMaxAllowances)});
            return report;
        }
        const auto& keys = turnStepKeys();
        const std::string known = fmt::format("{}", fmt::join(keys, ", "));
        for (std::size_t i = 0; i < t.skip.size(); ++i)
            if (std::find(keys.begin(), keys.end(), t.skip[i]) == keys.end())
                add({fmt::format("skip[{}]", i + 1),
                     fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "\"{}\" is not a turning step; steps are {}"),
                                 t.skip[i], known)});
        const Resolution r = resolveProfile(t.profile, ctx.shownUnit);
        for (const auto& p : r.problems) add(p);
        if (!r.ok()) return report;
        checkThreads(t.profile, r.profile, ctx.library, ctx.shownUnit, add);
        static const std::vector<Tool> none;
        TurnDeformation d =
            deformTurned(t.profile, r.profile, t.tools, t.skip, ctx.library ? *ctx.library : none, ctx.bar, ctx.shownUnit);
        for (const auto& p : d.deformation.problems) add(p);
        if (!d.deformation.ok() || !ctx.bar) return report;
        checkInBar(d.deformation.profile, t.profile, *ctx.bar, ctx.shownUnit, [&](std::string field, std::string message) {
            report.diagnostics.push_back({Severity::Error, unitNo, TurnUnit::kName, std::move(field), std::move(message)});
        });
        // Passed: the plan cuts this deformation (job/job_check.h CheckedJob::turned).
        if (!hasErrors(report.diagnostics)) report.turned = partOf(unitNo - 1, r, std::move(d));
        return report;
    }

    std::optional<Quad> outline(const TurnUnit&) const override { return std::nullopt; }
    void move(TurnUnit&, Point2) const override {}
    std::vector<Step> planInput(const TurnUnit& t, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        if (!ctx.job || !ctx.job->bar) return {};
        // The deformed profile turned() made (the pipeline hands it on), or made here.
        std::optional<TurnedPart> own;
        const TurnedPart* part = ctx.turned;
        if (!part) part = &own.emplace(*turned(ModuleInput(t), ctx));
        if (part->deformed.edges.empty()) return {};
        TurnPlanRequest q;
        q.unit = ctx.unit;
        q.deformed = &part->deformed;
        q.bar = *ctx.job->bar;
        q.library = &ctx.library;
        q.material = ctx.material;
        q.pins = t.tools;
        q.cutting = ctx.job->units[static_cast<std::size_t>(ctx.unit)].cutting;
        q.skip = {t.skip.begin(), t.skip.end()};
        q.tech = ctx.tech.turning;
        q.boreBefore = q.bar.bore;
        q.shown = ctx.shownUnit;
        if (ctx.machine) {
            q.maxRpm = ctx.machine->maxSpindleSpeed > 0 ? ctx.machine->maxSpindleSpeed : q.maxRpm;
            if (const double rapid = ctx.machine->slowestRapid(); rapid > 0) q.rapid = rapid;
            q.maxFeed = ctx.machine->maxFeed;
        }
        // The job's first turned unit faces the bar; its last outer unit parts it off.
        int firstTurn = -1, lastOuter = -1;
        for (std::size_t u = 0; u < ctx.job->units.size(); ++u) {
            const TurnUnit* other = ctx.job->units[u].module.getIf<TurnUnit>();
            if (!other) continue;
            if (firstTurn < 0) firstTurn = static_cast<int>(u);
            if (other->profile.side == ProfileSide::Outer) lastOuter = static_cast<int>(u);
        }
        q.facing = firstTurn == ctx.unit;
        q.parting = lastOuter == ctx.unit;
        TurnPlanResult r = planTurnedUnit(q);
        for (auto& p : r.problems)
            out.push_back({Severity::Error, ctx.unit + 1, TurnUnit::kName, std::move(p.field), std::move(p.message)});
        for (auto& n : r.notes) out.push_back({Severity::Warning, ctx.unit + 1, TurnUnit::kName, "", std::move(n)});
        return std::move(r.steps);
    }
    // The fields above the profile table, all the door's: the job file holds
    // them in the profile's grammar. The tables themselves are the station's
    // profile editor (ui/profile_editor.h).
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        using form::number;
        if (t.bind == "side") {
            FormField side = number<TurnUnit>(
                t.key, t.label, t.checks,
                [](const TurnUnit& u) { return u.profile.side == ProfileSide::Inner ? 2.0 : 1.0; },
                [](TurnUnit& u, double v) { u.profile.side = std::lround(v) == 2 ? ProfileSide::Inner : ProfileSide::Outer; });
            side.kind = FormFieldKind::Code;
            return side;
        }
        if (t.bind == "start.x")
            return number<TurnUnit>(
                t.key, t.label, t.checks, [](const TurnUnit& u) { return u.profile.startX; },
                [](TurnUnit& u, double v) { u.profile.startX = v; });
        if (t.bind == "start.z")
            return number<TurnUnit>(
                t.key, t.label, t.checks, [](const TurnUnit& u) { return u.profile.startZ; },
                [](TurnUnit& u, double v) { u.profile.startZ = v; });
        return std::nullopt;
    }

private:
    // The profile, allowances included, lies within the bar: an outer
    // profile no larger than the bar's diameter, an inner one inside it,
    // every Z between the face stock and the bar's end.
    // The rows' threads (docs/turning.md "Threading"): on a straight outer
    // row along the axis, cut toward the chuck, not ground; a pitch the
    // library's threading inserts cut; a depth the row's diameter holds.
    template <class Add>
    static void checkThreads(const TurnedProfile& p, const ResolvedProfile& resolved, const std::vector<Tool>* library, LengthUnit shown,
                             Add add)
    {
        for (std::size_t i = 0; i < p.rows.size(); ++i) {
            const ProfileRow& row = p.rows[i];
            if (!row.attributes.thread) continue;
            const std::string field = fmt::format("rows[{}].thread", i + 1);
            const std::string id = edgeId(row.id);
            const ThreadSpec& th = *row.attributes.thread;
            const auto len = [&](double mm) { return msg::quote({mm, shown}); };
            if (p.side == ProfileSide::Inner) {
                add({field, fmt::format(
                                TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg",
                                    "{} is on an inner profile: internal threads are not cut yet (only external ones)"),
                                id)});
                continue;
            }
            const Edge* e = resolved.find(id);
            if (!e) continue;
            if (row.kind != ElementKind::Line || e->geometry.arc) {
                add({field,
                     fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                      "{} is an arc: a thread is cut on a straight row along the axis"),
                                 id)});
                continue;
            }
            if (std::abs(e->geometry.a.r - e->geometry.b.r) > 1e-6 || e->geometry.b.z >= e->geometry.a.z) {
                add({field,
                     fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not a cylinder cut toward the chuck (a "
                                                                    "taper or a face): a thread is cut on a straight "
                                                                    "row along the axis, from the front back"),
                                 id)});
                continue;
            }
            for (const auto& a : p.allowances)
                if (a.edge == id)
                    add({field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                 "{} has a grinding allowance: a thread is not ground"),
                                            id)});
            if (th.pitch < kMinThreadPitch || th.pitch > kMaxThreadPitch) {
                add({field + ".pitch",
                     fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a pitch of {} is out of range: {} to {}"),
                                 len(th.pitch), len(kMinThreadPitch), len(kMaxThreadPitch))});
                continue;
            }
            const double depth = row.attributes.threadDepth(), diameter = 2.0 * e->geometry.a.r;
            // A 60° thread is no deeper than its sharp V (0.866 P); the core
            // keeps at least half the row's diameter.
            const double deepest = std::min(0.866 * th.pitch, diameter / 4.0);
            if (!(depth > 0.0) || depth > deepest + 1e-9) {
                add({field + ".depth",
                     fmt::format(
                         TAIWA_TRANSLATE_NOOP(
                             "taiwa::msg",
                             "a thread {} deep does not fit Ø{} with pitch {}: at most {} (the sharp V's height, and "
                             "a core of half the diameter)"),
                         len(depth), len(diameter), len(th.pitch), len(deepest))});
                continue;
            }
            if (library) {
                bool tool = false;
                for (const Tool& t : *library)
                    tool = tool || (t.type == ToolType::Threading && !t.turning.inside && th.pitch >= t.turning.pitchMin - 1e-9 &&
                                    th.pitch <= t.turning.pitchMax + 1e-9);
                if (!tool)
                    add({field + ".pitch",
                         fmt::format(
                             TAIWA_TRANSLATE_NOOP(
                                 "taiwa::msg", "no external threading insert of the tool library cuts a pitch of {}"),
                             len(th.pitch))});
            }
        }
    }

    template <class Report>
    static void checkInBar(const DeformedProfile& d, const TurnedProfile& p, const BarStock& bar, LengthUnit shown, Report report)
    {
        const auto len = [&](double mm) { return msg::quote({mm, shown}); };
        double rMax = 0.0, zMin = 0.0, zMax = 0.0;
        bool first = true;
        for (const auto& e : d.edges) {
            for (ZR q : {e.geometry.a, e.geometry.b}) {
                rMax = std::max(rMax, q.r);
                zMin = first ? q.z : std::min(zMin, q.z);
                zMax = first ? q.z : std::max(zMax, q.z);
                first = false;
            }
            if (e.geometry.arc) {
                const ZR top{e.geometry.centre.z, e.geometry.centre.r + e.geometry.radius};
                if (contains(e.geometry, top)) rMax = std::max(rMax, top.r);
            }
        }
        if (2.0 * rMax > bar.diameter + 1e-9)
            report("rows", p.allowances.empty()
                               ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                  "the profile reaches Ø{}, more than the bar's Ø{}"),
                                             len(2.0 * rMax), len(bar.diameter))
                               : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                                  "the profile with its grinding allowances reaches "
                                                                  "Ø{}, more than the bar's Ø{}"),
                                             len(2.0 * rMax), len(bar.diameter)));
        if (zMax > bar.face + 1e-9)
            report("rows", fmt::format(TAIWA_TRANSLATE_NOOP(
                                           "taiwa::msg", "the profile reaches Z{}, beyond the bar's face stock (Z{})"),
                                       len(zMax), len(bar.face)));
        if (zMin < bar.face - bar.length - 1e-9)
            report("rows", fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                            "the profile reaches Z{}, beyond the bar's end (Z{})"),
                                       len(zMin), len(bar.face - bar.length)));
    }
};

}  // namespace

const ModuleKind& turnModule() { return moduleInstance<TurnKind>(); }

}  // namespace taiwa
