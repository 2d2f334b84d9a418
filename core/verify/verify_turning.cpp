// The verifying simulation of a lathe job (verify_turning.h): the bar's
// half-section in (z, r) as polygons on the core's 0.1 µm grid (Clipper),
// every move of every step taking off what its tool's outline sweeps (an
// insert's nose and the edge above it, a blade's rectangle, a drill's body;
// along the finishing contour the nose runs where the control's
// compensation puts it: verify_turning_traces.cpp), and the checks on the way: a feed or an arc whose
// tool enters its unit's finished part (a gouge), a rapid whose tool meets
// stock still there, material left after roughing and after a unit's
// finishing, the machine's travel. A threading step is judged against
// the part less the thread's depth along its passes. Arcs are flattened
// and the nose drawn within a tenth of the resolution; outlines are sampled
// at the resolution.
#include "verify/verify_turning.h"
#include "verify/verify_turning_shapes.h"
#include "verify/verify_turning_traces.h"

#include "model/translate_noop.h"

#include "machine/machine.h"
#include "model/turned_geometry.h"
#include "model/turn_path.h"
#include "sim/turned_clipper.h"
#include "sim/turned_shapes.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <tuple>

namespace taiwa::verify {

namespace {

using ClipperLib::Path;
using ClipperLib::Paths;
using sim::zrOf;
using turning::ZR;
using namespace turned;

constexpr double kGougeTolerance = 0.001;  // a tool this far inside the part touches it [mm]
constexpr double kTouch = 0.001;           // a rapid this far into stock touches it [mm]

// A TURN unit's finished part and what its steps are meant to leave of the stock.
struct UnitData {
    Paths part;  // the deformed profile's material (sim::partOf, closed at its ends)
    std::optional<Outline> outline;
    bool inner = false;
    double zLo = 0.0, zHi = 0.0;  // the profile's extent along Z
    int lastFinish = -1;          // the unit's last finishing step
    int lastCheck = -1;           // the step after which it is finished (its grooves cut too)
    double allowance = kInf;      // the least its finishing steps leave
    double nose = 0.0;            // the largest nose radius they finish with
    Paths bridged;                // what the finishing leaves on purpose (bridgedOf)
};

// Where a finding is on a lathe: X a diameter, as the tape writes it.
Point3 onLathe(ZR p)
{
    return {2.0 * p.r, 0.0, p.z};
}

class TurningVerifier {
public:
    TurningVerifier(const Plan& plan, double resolution)
        : plan_(plan), bar_(*plan.mmJob.bar), res_(resolution), tol_(resolution / 10.0)
    {
        const double R = bar_.diameter / 2.0;
        stock_ = {box(bar_.face - bar_.length, bar_.face, bar_.bore / 2.0, R)};
        units_.resize(plan.mmJob.units.size());
        for (const TurnedPart& p : plan.turned) {
            if (p.unit < 0 || p.unit >= static_cast<int>(units_.size()) || p.deformed.edges.empty()) continue;
            UnitData& u = units_[static_cast<std::size_t>(p.unit)];
            u.part = {sim::clipperPolygon(sim::partOf(plan, p.unit, R + 5.0, std::nullopt))};
            u.outline.emplace(u.part);
            u.inner = p.deformed.side == turning::ProfileSide::Inner;
            u.zLo = kInf;
            u.zHi = -kInf;
            for (const auto& e : p.deformed.edges)
                for (const ZR q : {e.geometry.a, e.geometry.b}) {
                    u.zLo = std::min(u.zLo, q.z);
                    u.zHi = std::max(u.zHi, q.z);
                }
        }
        for (std::size_t k = 0; k < plan.steps.size(); ++k) {
            const Step& s = plan.steps[k];
            const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
            if (!turnOf(s) || !t || s.unit < 0 || s.unit >= static_cast<int>(units_.size())) continue;
            UnitData& u = units_[static_cast<std::size_t>(s.unit)];
            if (s.machiningType == MachiningType::TurnFinishing) {
                u.lastFinish = static_cast<int>(k);
                u.allowance = std::min({u.allowance, turnOf(s)->allowanceX, turnOf(s)->allowanceZ});
                u.nose = std::max(u.nose, t->cornerRadius);
            }
            if (u.lastFinish >= 0 &&
                (s.machiningType == MachiningType::TurnFinishing || s.machiningType == MachiningType::Grooving))
                u.lastCheck = static_cast<int>(k);
        }
        // What the finishing bridges, and a nose radius about it: the cusps
        // the nose leaves where a bridging chord meets the profile.
        for (const TurnedPart& p : plan.turned) {
            if (p.unit < 0 || p.unit >= static_cast<int>(units_.size())) continue;
            UnitData& u = units_[static_cast<std::size_t>(p.unit)];
            if (u.lastFinish >= 0) u.bridged = grown(bridgedOf(p.deformed, u.nose), u.nose, tol_);
        }
    }

    Report run()
    {
        Report r;
        r.resolution = res_;
        r.removed.assign(plan_.steps.size(), 0.0);
        for (std::size_t k = 0; k < plan_.steps.size(); ++k) {
            const Step& s = plan_.steps[k];
            const Tool* t = s.tool ? plan_.tool(s.tool->toolId) : nullptr;
            if (!turnOf(s) || !t) continue;
            const double before = volumeOf(stock_);
            cutStep(static_cast<int>(k), *t);
            r.removed[k] = before - volumeOf(stock_);
            restAfterRoughing(static_cast<int>(k), *t);
            restAfterFinishing(static_cast<int>(k));
        }
        travel();
        for (auto& [key, f] : found_) r.findings.push_back(f);
        std::stable_sort(r.findings.begin(), r.findings.end(), [](const Finding& a, const Finding& b) {
            return std::tie(a.step, a.kind, a.move) < std::tie(b.step, b.kind, b.move);
        });
        for (const Path& q : stock_) {
            std::vector<ZR> loop;
            for (const auto& v : q) loop.push_back(zrOf(v));
            r.section.push_back(std::move(loop));
        }
        return r;
    }

private:
    // Sides of a polygon that holds a nose of radius r within the flattening tolerance.
    int sidesFor(double r) const
    {
        const double half = std::acos(1.0 / (1.0 + tol_ / std::max(r, tol_)));
        return std::clamp(static_cast<int>(std::ceil(std::numbers::pi / half)), 8, 720);
    }

    // What a shape sweeps along a trace: one convex hull per piece.
    static Paths swept(const std::vector<ZR>& shape, const std::vector<ZR>& trace)
    {
        Paths out;
        for (std::size_t i = 0; i + 1 < trace.size(); ++i) {
            std::vector<ZR> two;
            two.reserve(2 * shape.size());
            for (const ZR q : shape) {
                two.push_back(trace[i] + q);
                two.push_back(trace[i + 1] + q);
            }
            out.push_back(sim::clipperPolygon(turning::convexHull(std::move(two))));
        }
        return out;
    }

    // The cuts not yet taken out of the stock, taken out.
    void flush()
    {
        if (pending_.empty()) return;
        stock_ = boolean(ClipperLib::ctDifference, stock_, pending_);
        pending_.clear();
        stockOutline_.reset();
    }

    void add(FindingKind kind, int step, int move, Deepest d, double size, double area, const std::string& part = "")
    {
        Finding& f = found_[{static_cast<int>(kind), step, move, part}];
        f.kind = kind;
        f.step = step;
        f.move = move;
        f.part = part;
        f.area += area;
        if (size > f.size) {
            f.size = size;
            f.position = onLathe(d.at);
        }
    }

    void cutStep(int k, const Tool& t)
    {
        const Step& s = plan_.steps[static_cast<std::size_t>(k)];
        const TurnStep& ts = *turnOf(s);
        const bool insert = t.type == ToolType::TurningInsert;
        const int sides = sidesFor(t.cornerRadius);
        const std::vector<ZR> shape = sim::shapeOf(s, t, sides);
        // The gouge is judged with the nose alone (the edge above it is chip).
        const std::vector<ZR> nose =
            insert ? turning::circumscribedCircle(ZR{} - ts.tipFromCentre, std::max(t.cornerRadius, 0.01), sides)
                   : shape;
        const UnitData* unit =
            s.unit >= 0 && s.unit < static_cast<int>(units_.size()) && units_[static_cast<std::size_t>(s.unit)].outline
                ? &units_[static_cast<std::size_t>(s.unit)]
                : nullptr;
        // A threading insert cuts the thread into the finished row by
        // design: it is judged against the part less the thread's depth
        // over the stretch its passes run.
        std::optional<Paths> threaded;
        if (unit && ts.thread) {
            double zLo = kInf, zHi = -kInf;
            for (const TurnMove& mv : ts.path.moves) {
                zLo = std::min(zLo, mv.end.z);
                zHi = std::max(zHi, mv.end.z);
            }
            const double root = ts.thread->crestR - ts.thread->depth - kGougeTolerance;
            threaded = boolean(ClipperLib::ctDifference, unit->part, {box(zLo, zHi, root, kFar)});
        }
        const auto all = traces(ts, t.cornerRadius, tol_);
        for (int m = 0; m < static_cast<int>(all.size()); ++m) {
            const std::vector<ZR>& trace = all[static_cast<std::size_t>(m)];
            if (trace.size() < 2) continue;
            Paths cut = swept(shape, trace);
            if (ts.path.moves[static_cast<std::size_t>(m)].kind == TurnMove::Rapid) {
                flush();
                const Paths into = boolean(ClipperLib::ctIntersection, cut, stock_);
                if (!into.empty()) {
                    if (!stockOutline_) stockOutline_.emplace(stock_);
                    const Deepest d = deepest(into, *stockOutline_, res_);
                    if (d.depth > kTouch) add(FindingKind::RapidIntoStock, k, m, d, d.depth, areaOf(into));
                }
            } else if (unit) {
                const Paths into = boolean(ClipperLib::ctIntersection, swept(nose, trace), threaded ? *threaded : unit->part);
                if (!into.empty()) {
                    const Deepest d = deepest(into, *unit->outline, res_);
                    if (d.depth > kGougeTolerance + res_) add(FindingKind::Gouge, k, m, d, d.depth, areaOf(into));
                }
            }
            pending_.insert(pending_.end(), std::make_move_iterator(cut.begin()), std::make_move_iterator(cut.end()));
        }
        flush();
    }

    // The unit's region: the profile's extent along Z, from the axis out past the bar.
    Path regionOf(const UnitData& u) const { return box(u.zLo, u.zHi, 0.0, bar_.diameter / 2.0 + 1.0); }

    // Material left where it should not be: reported on `step`, its size
    // how far its farthest point is from the part, less what the step
    // leaves. What an opening by two flattening tolerances and 1 µm takes
    // away does not count: slivers, the polygons' own error along a cut.
    void rest(int step, const UnitData& u, const Paths& found, double allowance)
    {
        const double sliver = 2.0 * tol_ + kGougeTolerance;
        const Paths left = grown(grown(found, -sliver, tol_), sliver, tol_);
        const double area = areaOf(left);
        if (area <= res_ * res_) return;
        const Deepest d = deepest(left, *u.outline, res_);
        if (d.depth - allowance > kGougeTolerance + res_)
            add(FindingKind::RestMaterial, step, -1, d, d.depth - allowance, area);
    }

    // Roughing clears the unit's region down to its allowance, except
    // within one depth of cut and two nose radii of it (the stairs between
    // its passes and the nose's cusps) and in the part's shadow (pockets
    // its passes along Z do not enter; the finishing takes them).
    void restAfterRoughing(int k, const Tool& t)
    {
        const Step& s = plan_.steps[static_cast<std::size_t>(k)];
        if (s.machiningType != MachiningType::TurnRoughing || s.unit < 0 || s.unit >= static_cast<int>(units_.size())) return;
        const UnitData& u = units_[static_cast<std::size_t>(s.unit)];
        if (!u.outline) return;
        const TurnStep& ts = *turnOf(s);
        const double allowance = std::max(ts.allowanceX, ts.allowanceZ);
        const double near = allowance + std::max(ts.depthOfCut, t.cornerRadius) + t.cornerRadius + res_;
        const Paths reach =
            boolean(ClipperLib::ctDifference, {regionOf(u)}, shadowOf(grown(u.part, near, tol_), u.inner));
        rest(k, u, boolean(ClipperLib::ctIntersection, stock_, reach), allowance);
    }

    // Once a unit's finishing (and the grooves after it) is cut, nothing is
    // left in its region but the finishing allowance, the inside corners
    // its nose cannot reach and what its contour bridges on purpose.
    void restAfterFinishing(int k)
    {
        for (const UnitData& u : units_) {
            if (u.lastCheck != k || !u.outline) continue;
            const Paths air = boolean(ClipperLib::ctDifference, {regionOf(u)}, u.part);
            const Paths reached = grown(grown(air, -u.nose, tol_), u.nose, tol_);
            Paths kept = grown(u.part, u.allowance + kGougeTolerance + res_, tol_);
            const Paths corners = boolean(ClipperLib::ctDifference, air, reached);
            kept.insert(kept.end(), corners.begin(), corners.end());
            kept.insert(kept.end(), u.bridged.begin(), u.bridged.end());
            const Paths left =
                boolean(ClipperLib::ctDifference, boolean(ClipperLib::ctIntersection, stock_, air), kept);
            rest(u.lastFinish, u, left, u.allowance);
        }
    }

    // The programmed points against the machine's travel, as milling does:
    // their span along each axis (X a diameter when the machine programs
    // it so) against the axis' travel, on the step and move of the
    // extreme farther out (X: from the spindle axis; Z: from the bar's face).
    void travel()
    {
        const Machine* machine = findMachine(plan_.mmJob.machine);
        if (!machine) return;
        const double xScale = machine->xDiameter ? 2.0 : 1.0;
        struct Extreme {
            double value;
            int step, move;
            ZR at;
        };
        Extreme xLo{kInf, -1, -1, {}}, xHi{-kInf, -1, -1, {}}, zLo{kInf, -1, -1, {}}, zHi{-kInf, -1, -1, {}};
        for (std::size_t k = 0; k < plan_.steps.size(); ++k) {
            const Step& s = plan_.steps[k];
            if (!turnOf(s)) continue;
            const TurnPath& p = turnOf(s)->path;
            const auto see = [&](ZR q, int m) {
                const int step = static_cast<int>(k);
                if (xScale * q.r < xLo.value) xLo = {xScale * q.r, step, m, q};
                if (xScale * q.r > xHi.value) xHi = {xScale * q.r, step, m, q};
                if (q.z < zLo.value) zLo = {q.z, step, m, q};
                if (q.z > zHi.value) zHi = {q.z, step, m, q};
            };
            see(p.start, -1);
            for (std::size_t m = 0; m < p.moves.size(); ++m) see(p.moves[m].end, static_cast<int>(m));
        }
        if (xLo.value > xHi.value) return;
        const auto check = [&](const char* axis, const Extreme& lo, const Extreme& hi, double from) {
            const auto t = machine->travel.find(axis);
            if (t == machine->travel.end()) return;
            const double excess = (hi.value - lo.value) - (t->second.max - t->second.min);
            if (excess <= 0.0) return;
            const Extreme& far = std::abs(lo.value - from) > std::abs(hi.value - from) ? lo : hi;
            add(FindingKind::TravelLimit, far.step, far.move, {0.0, far.at}, excess, 0.0, axis);
        };
        check("x", xLo, xHi, 0.0);
        check("z", zLo, zHi, bar_.face);
    }

    const Plan& plan_;
    const BarStock& bar_;
    double res_;
    double tol_;  // chords and the nose's polygon within it [mm]
    Paths stock_;
    Paths pending_;
    std::optional<Outline> stockOutline_;  // of stock_, made when a rapid meets it
    std::vector<UnitData> units_;
    std::map<std::tuple<int, int, int, std::string>, Finding> found_;  // by kind, step, move, part
};

}  // namespace

Report verifyTurning(const Plan& plan, const Options& options)
{
    const bool cuts = std::any_of(plan.steps.begin(), plan.steps.end(), [&](const Step& s) {
        return turnOf(s) && s.tool && plan.tool(s.tool->toolId) && !turnOf(s)->path.moves.empty();
    });
    if (!cuts) {
        Report r;
        r.resolution = options.resolution;
        r.skipped = TAIWA_TRANSLATE_NOOP("taiwa::msg", "a lathe job with no turning step: nothing to cut");
        return r;
    }
    return TurningVerifier(plan, options.resolution).run();
}

}  // namespace taiwa::verify
