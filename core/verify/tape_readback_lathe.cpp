// The read-back of a lathe tape (tape_readback.h, docs/verification.md
// "The tape read back"): the tape read by readLatheTape and each motion
// held against what its line was written for: a turning step's move (its
// TurnStep path, model/turn_path.h), its control cycle (G71 against the
// step's TurnCycle, G76 against its TurnThread), or the frame (to the tool
// change point, to the path's or the cycle's start; a gang slide's Z clear
// and X arrival), by where it ends; a rapid right after a motion the plan
// does not have must also stay out of the material. How deep a motion
// goes is how far its programmed point gets inside the bar's half-section
// (Report::section after the last step, else the bar as it was); another
// path's motion (a two-path lathe's program, PathProgram) turned into path
// 1's coordinates first.
#include "verify/tape_readback.h"

#include "machine/machine.h"
#include "model/turn_path.h"
#include "verify/tape_reader.h"
#include "verify/tape_readback_two_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace taiwa::verify {

namespace {

using turning::ZR;

// The material a motion is measured in: closed loops in (z, r), holes
// clockwise (inside: a non-zero winding).
class Material {
public:
    Material(const Report& report, const BarStock& bar) : loops_(report.section)
    {
        if (loops_.empty()) {
            const double z0 = bar.face - bar.length, z1 = bar.face, r0 = bar.bore / 2.0, r1 = bar.diameter / 2.0;
            loops_.push_back({{z0, r0}, {z1, r0}, {z1, r1}, {z0, r1}});
        }
        for (const auto& l : loops_)
            for (const ZR& p : l) lo_ = {std::min(lo_.z, p.z), std::min(lo_.r, p.r)}, hi_ = {std::max(hi_.z, p.z), std::max(hi_.r, p.r)};
    }

    static constexpr double kOnAxis = 1e-6;  // [mm]

    // How far inside the material `p` is (0 outside): to its nearest
    // surface; across the axis (another path's side) at its distance from it.
    double depth(ZR p) const
    {
        p.r = std::abs(p.r);
        if (p.z < lo_.z || p.z > hi_.z || p.r < lo_.r || p.r > hi_.r) return 0.0;
        int winding = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& l : loops_)
            for (std::size_t i = 0; i < l.size(); ++i) {
                const ZR a = l[i], b = l[(i + 1) % l.size()];
                if (a.r <= p.r) {
                    if (b.r > p.r && cross(a, b, p) > 0) ++winding;
                } else if (b.r <= p.r && cross(a, b, p) < 0) {
                    --winding;
                }
                // The axis bounds the half-section but is no surface: the way out is elsewhere.
                if (a.r > kOnAxis || b.r > kOnAxis) nearest = std::min(nearest, distance(p, a, b));
            }
        return winding != 0 ? nearest : 0.0;
    }
    // The deepest of the points `at(t)`, t in [0, 1], every ~0.05 mm of `length`.
    template <class At>
    double deepest(double length, At at) const
    {
        const int n = std::clamp(static_cast<int>(std::ceil(length / 0.05)), 1, 20000);
        double d = 0.0;
        for (int k = 0; k <= n; ++k) d = std::max(d, depth(at(static_cast<double>(k) / n)));
        return d;
    }
    ZR low() const { return lo_; }
    ZR high() const { return hi_; }

private:
    static double cross(ZR a, ZR b, ZR p) { return (b.z - a.z) * (p.r - a.r) - (p.z - a.z) * (b.r - a.r); }
    static double distance(ZR p, ZR a, ZR b)
    {
        const double dz = b.z - a.z, dr = b.r - a.r, l2 = dz * dz + dr * dr;
        const double t = l2 > 0 ? std::clamp(((p.z - a.z) * dz + (p.r - a.r) * dr) / l2, 0.0, 1.0) : 0.0;
        return std::hypot(p.z - a.z - t * dz, p.r - a.r - t * dr);
    }

    std::vector<std::vector<ZR>> loops_;
    ZR lo_{1e300, 1e300}, hi_{-1e300, -1e300};
};

bool near(double tape, double planned, double tol) { return std::abs(tape - planned) <= tol; }

class LatheJudge {
public:
    LatheJudge(const std::vector<Step>& steps, const post::Dialect& dialect, const PostOptions& post, const TapeReading& tape,
               const Material& material, const PathProgram& which)
        : steps_(steps), tape_(tape), material_(material), which_(which), signedU_(dialect.macroSyntax == "fanuc"),
          change_{post.latheChangeZ, post.latheChangeX / 2.0}
    {
        const int decimals = tape.inches ? dialect.lengthDecimals.inch : dialect.lengthDecimals.mm;
        tol_ = 1.5 * std::pow(10.0, -decimals) * (tape.inches ? 25.4 : 1.0);
        const Machine* m = findMachine(post.machine);
        gang_ = m && m->layout.gang;
    }

    // Whether `m` (in mm, X a diameter) is what line source `src` was written for.
    bool planned(const TapeMotion& m, BlockSource src)
    {
        const bool ok = judge(m, src);
        afterUnplanned_ = !ok;
        return ok;
    }

    // How deep [mm] the motion's programmed point goes into the material
    // (another path's motion turned into path 1's coordinates first).
    double depth(const TapeMotion& motion) const
    {
        const TapeMotion m = inPath1(motion);
        const ZR a{m.start.z, m.start.x / 2.0}, b{m.end.z, m.end.x / 2.0};
        if (m.kind == TapeMotion::Cycle) {
            const TapeCycle& c = tape_.cycles[static_cast<std::size_t>(m.cycle)];
            const ZR lo = toPath1({c.zLow, c.xLow / 2.0}), hi = toPath1({c.zHigh, c.xHigh / 2.0});
            const double zl = std::min(lo.z, hi.z), zh = std::max(lo.z, hi.z), rl = std::min(lo.r, hi.r), rh = std::max(lo.r, hi.r);
            double d = 0.0;
            const int n = std::clamp(static_cast<int>(std::max(zh - zl, rh - rl) / 0.1), 1, 200);
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) d = std::max(d, material_.depth({zl + (zh - zl) * i / n, rl + (rh - rl) * j / n}));
            return d;
        }
        // A coordinate the tape has not set yet is anywhere across the bar.
        if (std::isnan(b.z) || std::isnan(b.r)) {
            const ZR lo = material_.low(), hi = material_.high();
            const ZR from = std::isnan(b.z) ? ZR{lo.z, b.r} : ZR{b.z, lo.r}, to = std::isnan(b.z) ? ZR{hi.z, b.r} : ZR{b.z, hi.r};
            if (std::isnan(from.z) || std::isnan(from.r)) return 0.0;
            return material_.deepest(std::hypot(to.z - from.z, to.r - from.r), [&](double t) { return lerp(from, to, t); });
        }
        if (std::isnan(a.z) || std::isnan(a.r)) return material_.depth(b);
        if (m.kind != TapeMotion::Arc)
            return material_.deepest(std::hypot(b.z - a.z, b.r - a.r), [&](double t) { return lerp(a, b, t); });
        const ZR c{m.centre.y, m.centre.x / 2.0};
        const double a0 = std::atan2(a.r - c.r, a.z - c.z), radius = std::hypot(a.r - c.r, a.z - c.z);
        double sweep = std::atan2(b.r - c.r, b.z - c.z) - a0;
        if (m.rotation > 0 && sweep <= 0) sweep += 2 * std::numbers::pi;
        if (m.rotation < 0 && sweep >= 0) sweep -= 2 * std::numbers::pi;
        return material_.deepest(std::abs(sweep) * radius, [&](double t) {
            return ZR{c.z + radius * std::cos(a0 + sweep * t), c.r + radius * std::sin(a0 + sweep * t)};
        });
    }

private:
    ZR toPath1(ZR p) const { return which_.layout ? which_.layout->toPath1(p, which_.path) : p; }
    // `m` in path 1's coordinates: its points moved, an arc's turn reversed by one mirrored axis.
    TapeMotion inPath1(TapeMotion m) const
    {
        if (!which_.layout || which_.path == 0) return m;
        const auto point = [&](Point3 p) {
            const ZR q = toPath1({p.z, p.x / 2.0});
            return Point3{2.0 * q.r, 0.0, q.z};
        };
        m.start = point(m.start);
        m.end = point(m.end);
        const ZR c = toPath1({m.centre.y, m.centre.x / 2.0});
        m.centre = {2.0 * c.r, c.z};
        const LathePath &one = which_.layout->paths.at(0), &here = which_.layout->paths.at(which_.path);
        if (one.zDirection * here.zDirection * one.xDirection * here.xDirection < 0) m.rotation = -m.rotation;
        return m;
    }
    static ZR lerp(ZR a, ZR b, double t) { return {a.z + (b.z - a.z) * t, a.r + (b.r - a.r) * t}; }
    bool at(const Point3& p, ZR planned) const { return near(p.x, 2.0 * planned.r, tol_) && near(p.z, planned.z, tol_); }
    bool clear(const TapeMotion& m) const { return depth(m) <= 0.01; }

    bool judge(const TapeMotion& m, BlockSource src) const
    {
        const bool traverse = m.kind == TapeMotion::Traverse;
        if (src.step < 0 || src.step >= static_cast<int>(steps_.size()))  // the program's end: to the change point
            return traverse && (at(m.end, change_) || gangMove(m, change_)) && (!afterUnplanned_ || clear(m));
        const Step& s = steps_[static_cast<std::size_t>(src.step)];
        const TurnStep* ts = turnOf(s);
        if (!ts) return false;
        const TurnPath& p = ts->path;
        if (src.move < 0) {
            if (m.kind == TapeMotion::Cycle) return cycleMatches(tape_.cycles[static_cast<std::size_t>(m.cycle)], *ts);
            const bool to = at(m.end, change_) || at(m.end, p.start) || (p.cycle && at(m.end, p.cycle->start)) || gangMove(m, p.start);
            return traverse && to && (!afterUnplanned_ || clear(m));
        }
        if (src.move >= static_cast<int>(p.moves.size())) return false;
        const TurnMove& pm = p.moves[static_cast<std::size_t>(src.move)];
        const TurnCutting& c = ts->cutting;
        const double feedTol = tol_ / 1.5 * 0.5 + 1e-9;
        switch (pm.kind) {
        case TurnMove::Rapid: return traverse && at(m.end, pm.end) && (!afterUnplanned_ || clear(m));
        case TurnMove::Feed:
            if (m.kind != TapeMotion::Feed || !at(m.end, pm.end)) return false;
            if (ts->thread) return m.synchronised && near(m.feed, ts->thread->pitch, feedTol);
            return !m.synchronised && near(m.feed, pm.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev, feedTol);
        case TurnMove::ArcCW:
        case TurnMove::ArcCCW:
            return m.kind == TapeMotion::Arc && at(m.end, pm.end) && (m.rotation < 0) == (pm.kind == TurnMove::ArcCW) &&
                   near(m.centre.x, 2.0 * pm.centre.r, 2.0 * tol_) && near(m.centre.y, pm.centre.z, 2.0 * tol_) &&
                   near(m.feed, pm.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev, feedTol);
        }
        return false;
    }

    // A gang slide's change (post/gang_post.h): Z alone out (or staying),
    // or X alone to where the next motion starts (the change point's X at the end).
    bool gangMove(const TapeMotion& m, ZR next) const
    {
        if (!gang_ || m.kind != TapeMotion::Traverse) return false;
        const bool zAlone = (std::isnan(m.start.x) || near(m.end.x, m.start.x, tol_)) && (std::isnan(m.start.z) || m.end.z >= m.start.z - tol_);
        const bool xAlone = !std::isnan(m.start.z) && near(m.end.z, m.start.z, tol_) && near(m.end.x, 2.0 * next.r, tol_);
        return zAlone || xAlone;
    }

    bool cycleMatches(const TapeCycle& c, const TurnStep& ts) const
    {
        const TurnPath& p = ts.path;
        if (c.kind == TapeCycle::Threading) {
            if (!ts.thread) return false;
            const TurnThread& th = *ts.thread;
            return at(c.start, p.start) && near(c.rootX, 2.0 * (th.crestR - th.depth), tol_) && near(c.zEnd, th.zEnd, tol_) &&
                   near(c.depth, th.depth, tol_) && near(c.firstDepth, th.firstDepth, tol_) && near(c.feed, th.pitch, tol_) &&
                   (c.crestX < 0 || near(c.crestX, 2.0 * th.crestR, tol_)) && (c.springPasses < 0 || c.springPasses == th.springPasses);
        }
        if (!p.cycle) return false;
        const TurnCycle& pc = *p.cycle;
        const bool sideOk = !signedU_ || pc.allowanceX == 0 || (c.allowanceX < 0) == pc.inner;
        if (!at(c.start, pc.start) || !near(c.depth, pc.depthOfCut, tol_) || !near(std::abs(c.allowanceX), pc.allowanceX, tol_) ||
            !sideOk || (!std::isnan(c.allowanceZ) && !near(c.allowanceZ, pc.allowanceZ, tol_)) || (c.retract != 0 && !near(c.retract, pc.retract, tol_)) ||
            !near(c.feed, ts.cutting.feedPerRev, tol_))
            return false;
        // The contour as the post writes it: onto the first point at the
        // start's Z, down to it, then each segment (no zero-length ones).
        std::vector<TapeCycle::Point> want;
        const auto add = [&](ZR b, int turn, ZR centre) {
            if (!want.empty() && turn == 0 && near(want.back().x, 2.0 * b.r, 1e-9) && near(want.back().z, b.z, 1e-9)) return;
            want.push_back({2.0 * b.r, b.z, turn, 2.0 * centre.r, centre.z});
        };
        if (pc.contour.empty()) return false;
        add({pc.start.z, pc.contour.front().a.r}, 0, {});
        add(pc.contour.front().a, 0, {});
        for (const auto& sgm : pc.contour) add(sgm.b, sgm.arc ? (sgm.ccw ? 1 : -1) : 0, sgm.centre);
        std::vector<TapeCycle::Point> got;
        for (const auto& q : c.contour)
            if (got.empty() || q.turn != 0 || !near(got.back().x, q.x, 1e-9) || !near(got.back().z, q.z, 1e-9)) got.push_back(q);
        if (got.size() != want.size()) return false;
        for (std::size_t i = 0; i < got.size(); ++i) {
            const auto &g = got[i], &w = want[i];
            if (!near(g.x, w.x, tol_) || !near(g.z, w.z, tol_) || g.turn != w.turn) return false;
            if (g.turn != 0 && (!near(g.cx, w.cx, 2.0 * tol_) || !near(g.cz, w.cz, 2.0 * tol_))) return false;
        }
        return true;
    }

    const std::vector<Step>& steps_;
    const TapeReading& tape_;
    const Material& material_;
    const PathProgram& which_;
    bool signedU_;  // FANUC's and Haas's U: negative in a bore
    ZR change_;
    bool gang_ = false;
    double tol_ = 0.0;
    bool afterUnplanned_ = false;
};

}  // namespace

// The lathe's readBack (tape_readback.cpp calls it for a job with a bar):
// a two-path lathe's programs (tape_readback_two_path.h), else the one tape.
void readBackLathe(Report& report, const Plan& plan, const PostedJob& posted, const post::Dialect& dialect, const PostOptions& post)
{
    const Machine* m = findMachine(plan.mmJob.machine);
    if (m && m->layout.multiPath) {
        // Programs that cannot be written (the export refuses the job) are not read.
        if (posted.twoPath && *posted.twoPath) readBackTwoPath(report, plan, **posted.twoPath, dialect, post);
        return;
    }
    readBackLathePath(report, plan.steps, *plan.mmJob.bar, posted.tape, dialect, post, {});
}

TapeReading readBackLathePath(Report& report, const std::vector<Step>& steps, const BarStock& bar, const PostedProgram& program,
                              const post::Dialect& dialect, const PostOptions& post, const PathProgram& which)
{
    TapeReading tape = readLatheTape(program.nc, dialect, which.waits);
    const double k = tape.inches ? 25.4 : 1.0;
    for (TapeCycle& c : tape.cycles) {
        for (auto& q : c.contour) q.x *= k, q.z *= k, q.cx *= k, q.cz *= k;
        c.start = {c.start.x * k, 0.0, c.start.z * k};
        for (double* v : {&c.depth, &c.allowanceX, &c.allowanceZ, &c.retract, &c.feed, &c.rootX, &c.zEnd, &c.firstDepth, &c.xLow,
                          &c.xHigh, &c.zLow, &c.zHigh})
            *v *= k;
        if (c.crestX >= 0) c.crestX *= k;
    }
    const Material material(report, bar);
    LatheJudge judge(steps, dialect, post, tape, material, which);
    int added = 0;
    for (TapeMotion m : tape.motions) {
        if (added >= kMaxTapeFindings) break;
        m.start = {m.start.x * k, 0.0, m.start.z * k};
        m.end = {m.end.x * k, 0.0, m.end.z * k};
        m.centre = {m.centre.x * k, m.centre.y * k};
        m.feed *= k;
        const std::size_t i = static_cast<std::size_t>(m.line) - 1;
        const BlockSource src = i < program.lines.size() ? program.lines[i] : BlockSource{};
        // A straight move to where the tool is is no motion.
        const bool still = m.kind != TapeMotion::Arc && m.kind != TapeMotion::Cycle && !std::isnan(m.start.x) &&
                           !std::isnan(m.start.z) && m.end.x == m.start.x && m.end.z == m.start.z;
        if (still || judge.planned(m, src)) continue;
        Finding f;
        f.kind = FindingKind::UnplannedMove;
        f.step = src.step >= 0 ? src.step + which.stepOffset : src.step;
        f.line = m.line;
        f.program = which.program;
        f.position = m.end;
        // A hundredth of a mm is a touch, not a cut.
        const double depth = judge.depth(m);
        f.size = depth > 0.01 ? depth : 0.0;
        f.part = m.kind == TapeMotion::Traverse ? "rapid" : m.kind == TapeMotion::Feed ? "feed" : m.kind == TapeMotion::Arc ? "arc" : "cycle";
        report.findings.push_back(f);
        ++added;
    }
    addUnreadTape(report, tape, which.program);
    return tape;
}

}  // namespace taiwa::verify
