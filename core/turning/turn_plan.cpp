// The turning steps of one turned-profile unit (turn_plan.h): which steps,
// which tools, and every path, computed with the nose centre and written as
// the programmed point (the imaginary tip of the tool's orientation).
#include "turning/turn_plan.h"

#include "check/messages.h"
#include "model/turned_geometry.h"
#include "tools/cutting.h"
#include "turning/turn_region.h"
#include "turning/turn_tools.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace taiwa::turning {

namespace {

constexpr double kTol = 1e-7;
// The share of a tool's surface speed the spindle limit must still give at
// the smallest diameter a roughing or finishing step turns.
constexpr double kMinSpeedShare = 0.5;
// The widest groove a wall the finishing insert cannot go down may open
// (beyond it the wall is a shoulder facing the chuck) [mm].
constexpr double kGrooveReach = 30.0;

const char* kFacing = "facing";
const char* kCentreDrill = "centre-drill";
const char* kDrill = "drill";
const char* kRough = "turn-rough";
const char* kFinish = "turn-finish";
const char* kGroove = "groove";
const char* kPart = "part";

std::string toolWords(const Tool& t) { return msg::toolName(t); }

// The whole plan of one unit, built step by step.
class Planner {
public:
    explicit Planner(const TurnPlanRequest& q) : q_(q), d_(*q.deformed), lib_(*q.library), t_(q.tech)
    {
        side_ = d_.side;
        inner_ = side_ == ProfileSide::Inner;
        s_ = inner_ ? -1.0 : 1.0;
        R_ = q.bar.diameter / 2.0;
        zBarEnd_ = q.bar.face - q.bar.length;
        for (const auto& e : d_.edges) chain_.push_back(e.geometry);
        zFront_ = -1e300;
        for (const auto& s : chain_) zFront_ = std::max({zFront_, s.a.z, s.b.z});
        zEnd_ = chain_.back().b.z;
        rEnd_ = chain_.back().b.r;
        // Leading edges on the front plane (a face from the axis, or out of
        // the bore) are the facing step's; the turned contour starts after them.
        while (first_ < chain_.size() && std::abs(chain_[first_].a.z - zFront_) < 1e-6 && std::abs(chain_[first_].b.z - zFront_) < 1e-6)
            ++first_;
        // Trailing edges on the back plane (an outer profile's back face
        // down toward the axis) are parting off's.
        last_ = chain_.size();
        while (last_ > first_ + 1 && std::abs(chain_[last_ - 1].a.z - zEnd_) < 1e-6 && std::abs(chain_[last_ - 1].b.z - zEnd_) < 1e-6 &&
               s_ * (chain_[last_ - 1].b.r - chain_[last_ - 1].a.r) < 0)
            --last_;
        partLoop_ = makePartLoop();
    }

    TurnPlanResult run()
    {
        if (first_ >= chain_.size()) {
            problem("rows", "the profile has no element to turn: every row lies on the front face");
            return std::move(out_);
        }
        planFacing();
        if (inner_) planDrilling();
        if (drilledToSize_ || !out_.problems.empty()) return std::move(out_);
        const Tool* finishing = chooseFinishing();
        planRoughing();
        if (finishing) planFinishing(*finishing);
        planGrooves();
        if (!inner_) planParting();
        return std::move(out_);
    }

private:
    // ---- what the steps share --------------------------------------------

    void problem(std::string field, std::string message) { out_.problems.push_back({std::move(field), std::move(message)}); }
    void note(std::string text) { out_.notes.push_back(std::move(text)); }
    bool skipped(const char* key) const { return q_.skip.count(key) > 0; }
    std::string len(double mm) const { return msg::quote({mm, q_.shown}); }
    std::string dia(double r) const { return "Ø" + len(2.0 * r); }

    // The part for the forbidden regions: the deformed profile closed toward
    // the axis (outer) or out to the bar (inner), with the bar that stays
    // behind the profile's end (it is parted off after, or held).
    std::vector<Segment> makePartLoop() const
    {
        std::vector<Segment> loop = chain_;
        std::vector<ZR> pts;
        const ZR start = chain_.front().a, end = chain_.back().b;
        const double zLo = std::min(zBarEnd_, zEnd_) - 1.0;
        if (!inner_) {
            pts = {end, {zEnd_, R_}, {zLo, R_}, {zLo, 0.0}, {start.z, 0.0}, start};
        } else {
            const double rOut = R_ + 1.0;
            pts = {end, {zLo, rEnd_}, {zLo, rOut}, {start.z, rOut}, start};
        }
        for (std::size_t i = 0; i + 1 < pts.size(); ++i)
            if (dist(pts[i], pts[i + 1]) > kTol) loop.push_back(lineSegment(pts[i], pts[i + 1]));
        return loop;
    }

    const Tool* pinned(const char* key) const
    {
        const auto it = q_.pins.find(key);
        return it == q_.pins.end() ? nullptr : findTool(lib_, it->second);
    }

    // The cutting data of a tool; nullopt (with a problem) when it has none for the material.
    std::optional<TurnCutting> cuttingOf(const Tool& tool, const char* key, bool css)
    {
        const CuttingData* cd = tool.cuttingFor(q_.material);
        if (!cd) {
            problem(std::string("tools.") + key, fmt::format("{} has no cutting data for {}; add it in the tool library", toolWords(tool), q_.material));
            return std::nullopt;
        }
        TurnCutting c;
        c.constantSurfaceSpeed = css;
        c.surfaceSpeed = cd->surfaceSpeed;
        c.maxRpm = q_.maxRpm;
        c.feedPerRev = cd->feedPerTooth;
        c.plungeFeedPerRev = cd->feedPerTooth * std::clamp(cd->plungeFactor, 0.1, 1.0);
        if (!css) {  // drills: one feed, at the rpm of their diameter
            c.rpm = std::min(q_.maxRpm, std::round(1000.0 * cd->surfaceSpeed / (std::numbers::pi * std::max(tool.diameter, 0.1))));
            c.plungeFeedPerRev = cd->feedPerTooth;
        }
        return c;
    }

    Step& addStep(StepKind kind, MachiningType type, const Tool& tool, std::string reason, TurnStep turn)
    {
        Step s;
        s.unit = q_.unit;
        s.module = "TURN";
        s.kind = kind;
        s.machiningType = type;
        s.number = 1 + static_cast<int>(std::count_if(out_.steps.begin(), out_.steps.end(), [&](const Step& o) { return o.kind == kind; }));
        s.tool = ToolChoice{tool.id, std::move(reason)};
        s.minutes = turnMinutes(turn.path, turn.cutting, q_.rapid);
        s.cutDepth = 0.0;
        s.turn = std::move(turn);
        out_.steps.push_back(std::move(s));
        return out_.steps.back();
    }

    // A path under construction in nose-centre coordinates, written as the
    // programmed point.
    struct PathWriter {
        TurnPath path;
        ZR tip;
        bool started = false;
        void begin(ZR centre) { path.start = centre + tip; started = true; }
        void rapid(ZR c) { path.moves.push_back({TurnMove::Rapid, c + tip, {}, FeedKind::Cut}); }
        void feed(ZR c, FeedKind k = FeedKind::Cut) { path.moves.push_back({TurnMove::Feed, c + tip, {}, k}); }
    };

    // Clear of the stock: above the bar, or inside the hole that is there.
    double safeR() const
    {
        return inner_ ? std::max(std::max(q_.boreBefore, drilled_) / 2.0 - t_.clearance, 0.0) : R_ + t_.clearance;
    }

    // ---- the turning inserts ---------------------------------------------

    std::vector<const Tool*> inserts() const
    {
        std::vector<const Tool*> v;
        for (const auto& t : lib_)
            if (t.type == ToolType::TurningInsert && t.turning.inside == inner_ && insertGeometry(t)) v.push_back(&t);
        return v;
    }

    // The first element (from the turned contour on) an insert cannot cut,
    // or -1: its holder's angles (no back-cut beyond the clearance) and its
    // nose in concave arcs.
    int firstUnreached(const Tool& t, std::size_t from, std::size_t to) const
    {
        const auto g = *insertGeometry(t);
        for (std::size_t i = from; i < to; ++i) {
            const Segment& s = chain_[i];
            if (!reaches(g, s, side_)) return static_cast<int>(i);
            // A concave arc (material outside the arc's circle) must be wider than the nose.
            if (s.arc) {
                const bool materialOutside = (s.ccw ? 1.0 : -1.0) * s_ < 0;  // a turn away from the material
                if (materialOutside && s.radius <= g.noseRadius + kTol) return static_cast<int>(i);
            }
        }
        return -1;
    }

    // The part's own surfaces (as drawn, and the moved edges the grinder
    // finishes) must be turned; the allowance's sides and relief grooves
    // are grinding stock's shape, whose corners an insert may leave or
    // touch (the note says which).
    bool mustReach(std::size_t i) const
    {
        const Origin o = d_.edges[i].origin;
        return o == Origin::Original || o == Origin::Moved;
    }

    std::vector<bool> reachedBy(const Tool& t) const
    {
        std::vector<bool> ok(chain_.size(), true);
        for (std::size_t i = first_; i < last_; ++i) ok[i] = !mustReach(i) || firstUnreached(t, i, i + 1) < 0;
        return ok;
    }

    std::string whyNot(const Tool& t, std::size_t i) const
    {
        const auto g = *insertGeometry(t);
        const Segment& s = chain_[i];
        if (s.arc && !reaches(g, s, side_)) return fmt::format("its arc turns beyond what {} can follow", toolWords(t));
        if (s.arc) return fmt::format("its concave radius {} is not larger than the nose radius {} of {}", len(s.radius), len(g.noseRadius), toolWords(t));
        const double th = riseDegrees(tangentAtStart(s), side_);
        if (th > g.maxRise())
            return fmt::format("it rises {:.1f}° against the feed, more than the {:.1f}° the holder of {} allows (it would cut backward)", th, g.maxRise(), toolWords(t));
        return fmt::format("it falls {:.1f}° behind the insert, more than the {:.1f}° clearance of {}", -th, -g.minRise(), toolWords(t));
    }

    // ---- facing ------------------------------------------------------------

    void planFacing()
    {
        if (!q_.facing || skipped(kFacing) || q_.bar.face <= zFront_ + kTol) return;
        const Tool* tool = pinned(kFacing);
        std::string reason;
        if (tool) {
            if (!insertGeometry(*tool) || tool->turning.inside) {
                problem(std::string("tools.") + kFacing, fmt::format("{} is not an outside turning insert; facing needs one", toolWords(*tool)));
                return;
            }
            reason = "pinned";
        } else {
            tool = roughingInsert(false);
            if (!tool) {
                problem("rows", "the bar has face stock but the tool library has no outside turning insert to face it");
                return;
            }
            reason = "the outside roughing insert faces the bar (largest nose radius)";
        }
        const auto cutting = cuttingOf(*tool, kFacing, true);
        if (!cutting) return;
        const double rn = tool->cornerRadius;
        TurnStep ts;
        ts.side = ProfileSide::Outer;
        ts.orientation = insertOrientation(false);
        ts.tipFromCentre = tipFromCentre(rn, false);
        ts.depthOfCut = t_.depthOfCut;
        ts.region = fmt::format("front face Z{} from the bar's Z{}", len(zFront_), len(q_.bar.face));
        ts.cutting = *cutting;
        PathWriter w{{}, ts.tipFromCentre};
        const double stock = q_.bar.face - zFront_;
        const int passes = std::max(1, static_cast<int>(std::ceil(stock / t_.depthOfCut - 1e-9)));
        const double rTop = R_ + t_.clearance + rn, rBottom = q_.boreBefore > 0 ? q_.boreBefore / 2.0 - t_.clearance : 0.0;
        w.begin({q_.bar.face + t_.clearance + rn, rTop});
        for (int k = 1; k <= passes; ++k) {
            const double z = q_.bar.face - stock * k / passes + rn;  // nose centre: its front point on the face
            w.rapid({z + 0.0, rTop});
            w.feed({z, rBottom});
            w.feed({z + t_.retract, rBottom + t_.retract});
            w.rapid({z + t_.retract, rTop});
        }
        ts.path = std::move(w.path);
        addStep(StepKind::Facing, MachiningType::Facing, *tool, reason, std::move(ts));
    }

    const Tool* roughingInsert(bool inside) const
    {
        const Tool* best = nullptr;
        for (const auto& t : lib_)
            if (t.type == ToolType::TurningInsert && t.turning.inside == inside && insertGeometry(t) &&
                (!best || t.cornerRadius > best->cornerRadius + kTol))
                best = &t;
        return best;
    }

    // ---- drilling (a bore in a bar without one big enough) ----------------

    void planDrilling()
    {
        // The narrowest point of the bore, less the finishing allowance.
        double rMin = 1e300;
        for (std::size_t i = first_; i < last_; ++i) rMin = std::min({rMin, chain_[i].a.r, chain_[i].b.r});
        const Tool* bar = roughingInsert(true);
        const double need = bar ? bar->turning.minBore : 0.0;
        if (q_.boreBefore >= need - kTol && q_.boreBefore > 0) return;  // the bar's bore takes the boring bar
        if (skipped(kDrill)) return;
        const double maxDrill = 2.0 * (rMin - t_.allowanceX) - 1.0;
        const Tool* drill = pinned(kDrill);
        std::string reason = "pinned";
        // A plain bore narrower than the boring bar enters: drilled to size.
        bool plain = true;
        for (std::size_t i = first_; i < last_; ++i)
            plain = plain && !chain_[i].arc && std::abs(chain_[i].a.r - rMin) < 1e-6 && std::abs(chain_[i].b.r - rMin) < 1e-6;
        if (!drill && plain && maxDrill < need)
            for (const auto& t : lib_)
                if (t.type == ToolType::Drill && std::abs(t.diameter - 2.0 * rMin) < 1e-6) {
                    drill = &t;
                    reason = fmt::format("drills the plain bore to size ({}: the boring bar needs {})", dia(rMin), dia(need / 2.0));
                    drilledToSize_ = true;
                }
        if (!drill) {
            for (const auto& t : lib_)
                if (t.type == ToolType::Drill && t.diameter <= maxDrill + kTol && t.diameter >= need - kTol &&
                    (!drill || t.diameter > drill->diameter))
                    drill = &t;
            if (!drill) {
                problem("rows", maxDrill < need
                                    ? fmt::format("the bore is too narrow for the boring bar (it enters {}; the bore less its allowance leaves {}) "
                                                  "and no drill of the library makes it to size", dia(need / 2.0), dia(maxDrill / 2.0))
                                    : fmt::format("the bore needs a drilled hole of {} to {} (the boring bar enters {}), and the tool library has no drill in that range",
                                                  dia(need / 2.0), dia(maxDrill / 2.0), dia(need / 2.0)));
                return;
            }
            reason = fmt::format("largest drill within the bore less its allowance ({}), not smaller than the boring bar's bore {}", dia(maxDrill / 2.0), dia(need / 2.0));
        }
        // Centre drill first.
        if (!skipped(kCentreDrill)) {
            const Tool* cd = pinned(kCentreDrill);
            if (!cd)
                for (const auto& t : lib_)
                    if (t.type == ToolType::CentreDrill && (!cd || t.diameter < cd->diameter)) cd = &t;
            if (cd) {
                if (auto c = cuttingOf(*cd, kCentreDrill, false)) {
                    TurnStep ts;
                    ts.side = ProfileSide::Inner;
                    ts.orientation = 7;
                    ts.region = "centre of the front face";
                    ts.cutting = *c;
                    PathWriter w{{}, {}};
                    w.begin({zFront_ + t_.clearance, 0.0});
                    w.feed({zFront_ - cd->diameter, 0.0}, FeedKind::Plunge);
                    w.rapid({zFront_ + t_.clearance, 0.0});
                    ts.path = std::move(w.path);
                    addStep(StepKind::CentreDrilling, MachiningType::CentreDrilling, *cd, "smallest centre drill", std::move(ts));
                }
            }
        }
        const auto c = cuttingOf(*drill, kDrill, false);
        if (!c) return;
        // The drill's full diameter reaches the bore's end; through the bar at most.
        const double point = drill->diameter / 2.0 / std::tan(drill->pointAngle / 2.0 * std::numbers::pi / 180.0);
        const double bottom = std::max(zEnd_ - point - 0.5, zBarEnd_ - point - 1.0);
        TurnStep ts;
        ts.side = ProfileSide::Inner;
        ts.orientation = 7;
        ts.region = fmt::format("{} to Z{}", dia(drill->radius()), len(bottom));
        ts.cutting = *c;
        PathWriter w{{}, {}};
        const double zIn = zFront_ + t_.clearance;
        w.begin({zIn, 0.0});
        // Pecks of three diameters, out of the hole between them for the chips.
        const double peck = 3.0 * drill->diameter;
        double at = zFront_;
        while (at > bottom + kTol) {
            const double to = std::max(bottom, at - peck);
            if (at < zFront_) w.rapid({at + 0.5, 0.0});
            w.feed({to, 0.0}, FeedKind::Plunge);
            w.rapid({zIn, 0.0});
            at = to;
        }
        ts.path = std::move(w.path);
        addStep(StepKind::Drilling, MachiningType::Drilling, *drill, reason, std::move(ts));
        drilled_ = drill->diameter;
    }

    // ---- finishing tool ----------------------------------------------------

    const Tool* chooseFinishing()
    {
        if (skipped(kFinish)) return nullptr;
        if (const Tool* t = pinned(kFinish)) {
            if (!insertGeometry(*t) || t->turning.inside != inner_) {
                problem(std::string("tools.") + kFinish, fmt::format("{} is not an {} turning insert", toolWords(*t), inner_ ? "inside" : "outside"));
                return nullptr;
            }
            finishReason_ = "pinned";
            finishReach_ = reachedBy(*t);
            finishTool_ = t;
            return t;
        }
        // The insert that reaches every element; of those the smallest nose
        // radius (the finest finish), then the lowest number. Failing that,
        // the one reaching most, the rest left for a grooving blade.
        // Of equal reach over the part, the one that also follows more of
        // the allowance's relief grooves (fewer left).
        const Tool* best = nullptr;
        int bestMissing = 1 << 30, bestGrooves = 1 << 30;
        for (const Tool* t : inserts()) {
            const auto ok = reachedBy(*t);
            const int missing = static_cast<int>(std::count(ok.begin() + static_cast<long>(first_), ok.end(), false));
            int grooves = 0;
            for (std::size_t i = first_; i < last_; ++i) grooves += !mustReach(i) && firstUnreached(*t, i, i + 1) >= 0;
            if (!best || missing < bestMissing || (missing == bestMissing && grooves < bestGrooves) ||
                (missing == bestMissing && grooves == bestGrooves && t->cornerRadius < best->cornerRadius - kTol)) {
                best = t;
                bestMissing = missing;
                bestGrooves = grooves;
            }
        }
        if (!best) {
            problem("rows", fmt::format("the tool library has no {} turning insert", inner_ ? "inside (boring)" : "outside"));
            return nullptr;
        }
        finishReach_ = reachedBy(*best);
        finishTool_ = best;
        finishReason_ = bestMissing == 0
                            ? "reaches every element; smallest nose radius of those that do"
                            : fmt::format("reaches all but {} element(s); smallest nose radius of those that reach most", bestMissing);
        return best;
    }

    // ---- roughing ------------------------------------------------------------

    void planRoughing()
    {
        if (skipped(kRough)) return;
        const Tool* tool = pinned(kRough);
        std::string reason = "pinned";
        if (tool) {
            if (!insertGeometry(*tool) || tool->turning.inside != inner_) {
                problem(std::string("tools.") + kRough, fmt::format("{} is not an {} turning insert", toolWords(*tool), inner_ ? "inside" : "outside"));
                return;
            }
        } else {
            tool = roughingInsert(inner_);
            if (!tool) return;  // chooseFinishing said it
            reason = "largest nose radius for its side (the strongest edge)";
        }
        const auto cutting = cuttingOf(*tool, kRough, true);
        if (!cutting) return;
        checkSpindleLimit(*tool, *cutting, kRough);
        const auto g = *insertGeometry(*tool);
        const double rn = g.noseRadius;
        TurnStep ts;
        ts.side = side_;
        ts.orientation = insertOrientation(inner_);
        ts.tipFromCentre = tipFromCentre(rn, inner_);
        ts.depthOfCut = t_.depthOfCut;
        ts.allowanceX = t_.allowanceX;
        ts.allowanceZ = t_.allowanceZ;
        ts.cutting = *cutting;
        const ForbiddenRegion F = ForbiddenRegion::make(partLoop_, insertShape(g), t_.allowanceX, t_.allowanceZ);

        // Levels of the nose's cutting point (outer: its lowest, inner: its
        // highest point) from the stock's surface to the profile's extreme.
        const double surface = inner_ ? std::max(q_.boreBefore, drilled_) / 2.0 : R_;
        double extreme = inner_ ? -1e300 : 1e300;
        for (std::size_t i = first_; i < last_; ++i)
            for (const ZR p : {chain_[i].a, chain_[i].b}) extreme = inner_ ? std::max(extreme, p.r) : std::min(extreme, p.r);
        for (std::size_t i = first_; i < last_; ++i)
            if (chain_[i].arc) {
                const ZR c = chain_[i].centre;
                const ZR ext{c.z, c.r - s_ * chain_[i].radius};
                if (contains(chain_[i], ext)) extreme = inner_ ? std::max(extreme, ext.r) : std::min(extreme, ext.r);
            }
        extreme += s_ * t_.allowanceX;
        const double depth = s_ * (surface - extreme);
        if (depth <= kTol) {
            note(fmt::format("no roughing: the stock is already within the finishing allowance", q_.unit + 1));
            return;
        }
        const int levels = std::max(1, static_cast<int>(std::ceil(depth / t_.depthOfCut - 1e-9)));
        const double zApproach = std::max(zFront_, q_.facing ? zFront_ : q_.bar.face) + t_.clearance + rn;
        const double zLo = std::min(zBarEnd_, zEnd_) - 1.0;
        const double rSafe = safeR() + s_ * rn;
        PathWriter w{{}, ts.tipFromCentre};
        w.begin({zApproach, rSafe});
        std::vector<std::pair<double, double>> open{{zLo, zApproach}};
        double rPrev = surface + s_ * rn;  // nose centre on the stock surface
        bool left = false;
        for (int k = 1; k <= levels; ++k) {
            const double cut = surface - s_ * depth * k / levels;  // the cutting point's radius
            const double rc = cut + s_ * rn;
            // Free at this level and at every level above (the part's shadow).
            std::vector<std::pair<double, double>> here;
            for (const auto& f : F.freeAlongZ(rc, zLo, zApproach))
                for (const auto& o : open) {
                    const double a = std::max(f.first, o.first), b = std::min(f.second, o.second);
                    if (b - a > 1e-6) here.emplace_back(a, b);
                }
            std::vector<std::pair<double, double>> kept;
            for (auto it = here.rbegin(); it != here.rend(); ++it) {
                const auto [a, b] = *it;
                if (b <= zLo + 0.5) continue;
                if (a - rn >= zFront_ - 1e-6) continue;  // in front of the face: air
                const bool front = b >= zApproach - 1e-9;
                if (!front) {
                    // A pocket: plunge at its front end from the level above.
                    if (!F.segmentFree({b, rPrev}, {b, rc})) {
                        left = true;
                        continue;
                    }
                    w.rapid({currentZ(w), rSafe});
                    w.rapid({b, rSafe});
                    w.rapid({b, rPrev});
                    w.feed({b, rc}, FeedKind::Plunge);
                } else {
                    w.rapid({zApproach, rc});
                }
                w.feed({a, rc});
                const ZR back{a + t_.retract, rc + s_ * t_.retract};
                if (F.segmentFree({a, rc}, back)) w.feed(back);
                else w.feed({a, rc + s_ * t_.retract});
                if (front) w.rapid({zApproach, rc + s_ * t_.retract});
                else w.rapid({currentZ(w), rSafe});
                kept.emplace_back(a, b);
            }
            std::reverse(kept.begin(), kept.end());
            open = kept;
            rPrev = rc;
        }
        w.rapid({zApproach, rSafe});
        if (left) note(fmt::format("roughing with {} leaves pockets its insert cannot enter for the finishing tool", toolWords(*tool)));
        ts.region = fmt::format("{} to {}, Z{} to Z{}", dia(surface), dia(extreme), len(zFront_), len(zEnd_));
        ts.path = std::move(w.path);

        // The control's own cycle where the profile allows it: the contour
        // monotone (one element after the other outward and toward the
        // chuck), reached by the insert everywhere. Then the nose runs
        // clear of every element with the tip on the contour plus the
        // allowance (docs/turning.md).
        if (const auto cycle = roughingCycle(*tool, surface)) ts.path.cycle = *cycle;
        addStep(StepKind::TurnRoughing, MachiningType::TurnRoughing, *tool, reason, std::move(ts));
    }

    static double currentZ(const PathWriter& w) { return w.path.moves.empty() ? w.path.start.z : w.path.moves.back().end.z - w.tip.z; }

    std::optional<TurnCycle> roughingCycle(const Tool& tool, double surface) const
    {
        for (std::size_t i = first_; i < last_; ++i) {
            const Segment& s = chain_[i];
            const double th0 = riseDegrees(tangentAtStart(s), side_), th1 = riseDegrees(tangentAtEnd(s), side_);
            if (th0 < -1e-6 || th1 < -1e-6 || th0 > 90.0 + 1e-6 || th1 > 90.0 + 1e-6) return std::nullopt;
        }
        if (firstUnreached(tool, first_, last_) >= 0) return std::nullopt;
        TurnCycle c;
        c.inner = inner_;
        c.contour.assign(chain_.begin() + static_cast<long>(first_), chain_.begin() + static_cast<long>(last_));
        // Out of the part at the end: the cycle's last element leaves along X.
        const ZR end = chain_[last_ - 1].b;
        const ZR out{end.z, surface + s_ * t_.clearance};
        if (s_ * (out.r - end.r) > kTol) c.contour.push_back(lineSegment(end, out));
        c.start = {zFront_ + t_.clearance, surface + s_ * t_.clearance};
        c.depthOfCut = t_.depthOfCut;
        c.allowanceX = t_.allowanceX;
        c.allowanceZ = t_.allowanceZ;
        c.retract = t_.retract;
        return c;
    }

    void checkSpindleLimit(const Tool& tool, const TurnCutting& c, const char* key)
    {
        double rMin = 1e300;
        for (std::size_t i = first_; i < last_; ++i) rMin = std::min({rMin, chain_[i].a.r, chain_[i].b.r});
        if (rMin <= 0.01) return;
        const double vcAt = std::numbers::pi * 2.0 * rMin * q_.maxRpm / 1000.0;
        if (vcAt < kMinSpeedShare * c.surfaceSpeed)
            problem(std::string("tools.") + key,
                    fmt::format("the spindle limit of {:.0f} rpm turns {} at only {:.0f} m/min, less than half the {:.0f} m/min {} needs there; "
                                "choose a machine with a higher speed limit or a tool for lower speeds",
                                q_.maxRpm, dia(rMin), vcAt, c.surfaceSpeed, toolWords(tool)));
    }

    // ---- finishing -----------------------------------------------------------

    // Runs of elements the finishing insert cannot reach: grooves for a blade.
    std::vector<std::pair<std::size_t, std::size_t>> unreachedRuns() const
    {
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        for (std::size_t i = first_; i < last_;) {
            if (finishReach_.empty() || finishReach_[i]) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < last_ && !finishReach_[j]) ++j;
            // A wall the insert cannot go down opens a groove: the run goes
            // on to where the profile comes back up to its mouth (within
            // kGrooveReach), the bottom in the insert's shadow too.
            const double mouth = chain_[i].a.r;
            if (s_ * (chain_[j - 1].b.r - mouth) < -1e-6) {
                std::size_t k = j;
                while (k < last_ && s_ * (chain_[k].b.r - mouth) < -1e-6 && chain_[i].a.z - chain_[k].b.z <= kGrooveReach) ++k;
                if (k < last_ && chain_[i].a.z - chain_[k].b.z <= kGrooveReach) j = k + 1;
            }
            runs.emplace_back(i, j);  // [i, j)
            i = j;
        }
        return runs;
    }

    void planFinishing(const Tool& tool)
    {
        const auto cutting = cuttingOf(tool, kFinish, true);
        if (!cutting) return;
        checkSpindleLimit(tool, *cutting, kFinish);
        const auto g = *insertGeometry(tool);
        const double rn = g.noseRadius;
        TurnStep ts;
        ts.side = side_;
        ts.orientation = insertOrientation(inner_);
        ts.tipFromCentre = tipFromCentre(rn, inner_);
        ts.cutting = *cutting;
        ts.region = fmt::format("the deformed profile from Z{} to Z{}", len(zFront_), len(zEnd_));
        // The contour as cut: the profile, each groove the insert cannot
        // enter bridged by a line across its mouth (the blade cuts it after).
        std::vector<Segment> contour;
        const auto runs = unreachedRuns();
        for (std::size_t i = first_; i < last_;) {
            const auto run = std::find_if(runs.begin(), runs.end(), [&](const auto& r) { return r.first == i; });
            if (run == runs.end()) {
                contour.push_back(chain_[i]);
                ++i;
                continue;
            }
            const ZR a = chain_[run->first].a, b = chain_[run->second - 1].b;
            if (dist(a, b) > kTol) contour.push_back(lineSegment(a, b));
            i = run->second;
        }
        crossGrindingStockRuns(contour, tool);
        reachableCorners(contour, rn);
        TurnPath& p = ts.path;
        const ZR first = contour.front().a;
        const ZR entry{first.z + t_.clearance + 2.0 * rn, first.r};
        p.start = {entry.z, safeR()};
        // To the entry point with the nose clear, then compensation on along -Z onto the contour.
        p.moves.push_back({TurnMove::Rapid, {entry.z, safeR()}, {}, FeedKind::Cut});
        p.moves.push_back({TurnMove::Rapid, entry, {}, FeedKind::Cut});
        p.comp = inner_ ? NoseCompensation::Left : NoseCompensation::Right;
        p.compFrom = static_cast<int>(p.moves.size());
        p.moves.push_back({TurnMove::Feed, first, {}, FeedKind::Cut});
        for (const auto& s : contour) {
            if (s.arc) p.moves.push_back({s.ccw ? TurnMove::ArcCCW : TurnMove::ArcCW, s.b, s.centre, FeedKind::Cut});
            else p.moves.push_back({TurnMove::Feed, s.b, {}, FeedKind::Cut});
        }
        p.compTo = static_cast<int>(p.moves.size());
        // Off the part with compensation cancelled: up and forward.
        const ZR last = contour.back().b;
        p.moves.push_back({TurnMove::Feed, {last.z + t_.clearance, last.r + s_ * (t_.clearance + 2.0 * rn)}, {}, FeedKind::Cut});
        p.moves.push_back({TurnMove::Rapid, {last.z + t_.clearance, safeR()}, {}, FeedKind::Cut});
        // Out of a bore along the axis before the turret moves on.
        if (inner_) p.moves.push_back({TurnMove::Rapid, {entry.z, safeR()}, {}, FeedKind::Cut});
        addStep(StepKind::TurnFinishing, MachiningType::TurnFinishing, tool, finishReason_, std::move(ts));
    }

    // The air side's unit normal of a line's direction.
    ZR airNormal(ZR t) const { return inner_ ? leftNormal(t) : ZR{t.r, -t.z}; }

    // Runs of the allowance's own edges (relief grooves) the finishing
    // insert cannot follow: followed with compensation, the nose would cut
    // them but the insert's edges would cut what stands beside them, which
    // may be the finished part. The contour crosses such a run on a chord
    // the insert can follow, from before the run to after it, clear of the
    // part; the groove is left (a note says so). Where no such chord is
    // found within a few nose radii, the run is followed as drawn.
    void crossGrindingStockRuns(std::vector<Segment>& contour, const Tool& tool)
    {
        const auto g = *insertGeometry(tool);
        const double rn = g.noseRadius;
        std::vector<std::string> left;
        for (std::size_t i = first_; i < last_;) {
            if (mustReach(i) || firstUnreached(tool, i, i + 1) < 0) {
                ++i;
                continue;
            }
            // The whole run of the allowance's edges around it (a relief
            // groove is several), from one edge of the part to the next.
            std::size_t j = i;
            while (j < last_ && !mustReach(j)) ++j;
            while (i > first_ && !mustReach(i - 1)) --i;
            const ZR a = chain_[i].a, b = chain_[j - 1].b;
            // The run in the contour: the element starting at a, the one ending at b.
            std::size_t ka = contour.size(), kb = contour.size();
            for (std::size_t k = 0; k < contour.size(); ++k) {
                if (ka == contour.size() && dist(contour[k].a, a) < 1e-9) ka = k;
                if (dist(contour[k].b, b) < 1e-9) kb = k;
            }
            if (ka >= contour.size() || kb >= contour.size() || kb < ka || ka == 0 || kb + 1 >= contour.size()) {
                i = j;
                continue;
            }
            for (double reach = 2.0 * rn; reach <= 16.0 * rn; reach *= 2.0) {
                const Segment& before = contour[ka - 1];
                const Segment& after = contour[kb + 1];
                if (length(before) < reach || length(after) < reach) break;
                const ZR p = pointAt(before, length(before) - reach), q = pointAt(after, reach);
                const Segment chord = lineSegment(p, q);
                if (!reaches(g, chord, side_)) continue;
                bool clear = true;
                for (const auto& e : chain_)
                    for (const ZR x : crossings(e, chord))
                        clear = clear && (dist(x, p) < 1e-7 || dist(x, q) < 1e-7);
                if (!clear) continue;
                const Segment head = piece(before, before.a, p), tail = piece(after, q, after.b);
                contour.erase(contour.begin() + static_cast<long>(ka) - 1, contour.begin() + static_cast<long>(kb) + 2);
                contour.insert(contour.begin() + static_cast<long>(ka) - 1, {head, chord, tail});
                left.push_back(d_.edges[i].id + (j - i > 1 ? "…" + d_.edges[j - 1].id : ""));
                break;
            }
            i = j;
        }
        if (!left.empty())
            note(fmt::format("{} of the grinding allowance cannot be followed by {} and is left (the finishing contour "
                             "crosses it); cut it with a form tool or grind it out",
                             fmt::join(left, ", "), toolWords(tool)));
    }

    // A concave corner the nose can sit in only if both lines are long
    // enough to hold it (the control refuses the move otherwise: "concave
    // corner cannot be reached by the tool without gouging"). Where a line
    // is shorter (the step at a grinding allowance's end, lower than the
    // nose), the contour runs from the short line's start straight to where
    // the nose touches the next line, as far along it as needed: what the
    // nose leaves there is the fillet it cannot help leaving.
    void reachableCorners(std::vector<Segment>& contour, double rn)
    {
        // A line shorter than two nose radii into a concave corner: the
        // contour runs from its start straight to the point two nose radii
        // on (through whatever lines and arcs follow), or to the first
        // outside corner before it.
        for (std::size_t k = 0; k + 1 < contour.size(); ++k) {
            const Segment& A = contour[k];
            if (A.arc || length(A) >= 2.0 * rn) continue;
            const ZR ta = tangentAtEnd(A), tb = tangentAtStart(contour[k + 1]);
            if (cross(ta, tb) * (inner_ ? -1.0 : 1.0) >= -1e-9) continue;  // a left turn (outer) goes round the material: convex
            // Two nose radii on, or the first outside corner before that: a
            // chord past an outside corner would cut through the material
            // the corner holds.
            const auto convexAfter = [&](std::size_t e) {
                return e + 1 < contour.size() &&
                       cross(tangentAtEnd(contour[e]), tangentAtStart(contour[e + 1])) * (inner_ ? -1.0 : 1.0) > 1e-9;
            };
            double left = 2.0 * rn;
            std::size_t m = k + 1;
            while (m < contour.size() && length(contour[m]) <= left && !convexAfter(m)) left -= length(contour[m++]);
            if (m >= contour.size()) break;
            const bool corner = length(contour[m]) <= left && convexAfter(m);
            const ZR q = corner ? contour[m].b : pointAt(contour[m], left);
            const Segment chord = lineSegment(A.a, q);
            if (corner) {
                contour.erase(contour.begin() + static_cast<long>(k), contour.begin() + static_cast<long>(m) + 1);
                contour.insert(contour.begin() + static_cast<long>(k), chord);
            } else {
                const Segment rest = piece(contour[m], q, contour[m].b);
                contour.erase(contour.begin() + static_cast<long>(k), contour.begin() + static_cast<long>(m) + 1);
                contour.insert(contour.begin() + static_cast<long>(k), {chord, rest});
            }
        }
        for (int guard = 0; guard < 1000; ++guard) {
            bool changed = false;
            for (std::size_t k = 0; k + 1 < contour.size() && !changed; ++k) {
                Segment& A = contour[k];
                Segment& B = contour[k + 1];
                if (A.arc || B.arc) continue;
                const ZR ta = unit(A.b - A.a), tb = unit(B.b - B.a);
                const double turn = cross(ta, tb) * (inner_ ? -1.0 : 1.0);
                if (turn >= -1e-9) continue;  // straight on or convex: concave turns toward the air
                // Where the nose centre sits against both lines.
                const Curve ca = lineThrough(A.a + rn * airNormal(ta), ta), cb = lineThrough(B.a + rn * airNormal(tb), tb);
                const auto hit = intersections(ca, cb);
                if (hit.empty()) continue;
                const double onA = dot(hit.front() - (A.a + rn * airNormal(ta)), ta);
                const double onB = dot(hit.front() - (B.a + rn * airNormal(tb)), tb);
                const double lenA = dist(A.a, A.b), lenB = dist(B.a, B.b);
                if (onA >= -1e-9 && onB <= lenB + 1e-9) continue;
                if (onA < -1e-9) {
                    // A is too short: from A's start to where the nose touches B, a little further on.
                    const double along = std::min(lenB, std::max(onB, 0.0) + 0.05);
                    const ZR q = B.a + along * tb;
                    A = lineSegment(A.a, q);
                    if (along >= lenB - 1e-9) contour.erase(contour.begin() + static_cast<long>(k) + 1);
                    else B = lineSegment(q, B.b);
                } else {
                    // B is too short: from where the nose touches A straight to B's end.
                    const double along = std::max(0.0, std::min(lenA, onA) - 0.05);
                    const ZR q = A.a + along * ta;
                    B = lineSegment(q, B.b);
                    if (along <= 1e-9) contour.erase(contour.begin() + static_cast<long>(k));
                    else A = lineSegment(A.a, q);
                }
                changed = true;
                }
            if (!changed) break;
        }
    }

    // ---- grooving --------------------------------------------------------

    void planGrooves()
    {
        const auto runs = unreachedRuns();
        if (runs.empty()) return;
        for (const auto& [i, j] : runs) {
            const ZR a = chain_[i].a, b = chain_[j - 1].b;
            const double zHi = std::max(a.z, b.z), zLo = std::min(a.z, b.z);
            const double width = zHi - zLo;
            // The deepest point of the run: the blade must get there.
            double deepest = inner_ ? -1e300 : 1e300;
            for (std::size_t k = i; k < j; ++k)
                for (const ZR p : {chain_[k].a, chain_[k].b}) deepest = inner_ ? std::max(deepest, p.r) : std::min(deepest, p.r);
            const std::string elements = d_.edges[i].id + (j - i > 1 ? "…" + d_.edges[j - 1].id : "");
            // A wall that does not come back up is a shoulder facing the
            // chuck: no blade finishes the surface behind it.
            const bool groove = s_ * (b.r - a.r) >= -1e-6;
            bool own = false;
            for (std::size_t k = i; k < j; ++k) own = own || mustReach(k);
            if (!groove && own) {
                problem("rows", fmt::format("{} cannot be turned: {}; it is a shoulder facing the chuck, which needs a left-hand "
                                            "tool the library does not have (or turn the part round and make it a second job)",
                                            elements, whyNot(*finishingTool(), i)));
                continue;
            }
            // The widest blade not wider than the groove (fewer plunges);
            // for a narrower groove or a step, the narrowest (it may cut a
            // step from the air beside it).
            std::vector<const Tool*> blades;
            if (const Tool* pin = pinned(kGroove)) blades.push_back(pin);
            else
                for (const auto& t : lib_)
                    if (t.type == ToolType::Grooving && t.turning.inside == inner_ && t.turning.maxDiameter <= 0) blades.push_back(&t);
            std::sort(blades.begin(), blades.end(), [&](const Tool* x, const Tool* y) {
                const bool fx = x->turning.width <= width + kTol, fy = y->turning.width <= width + kTol;
                if (fx != fy) return fx;
                return fx ? x->turning.width > y->turning.width : x->turning.width < y->turning.width;
            });
            if (blades.empty()) {
                problem("rows", fmt::format("{} cannot be turned: {}; and the tool library has no {} grooving blade", elements,
                                            whyNot(*finishingTool(), i), inner_ ? "inside" : "outside"));
                continue;
            }
            if (skipped(kGroove)) {
                note(fmt::format("{} is left: grooving is turned off", elements));
                continue;
            }
            const Tool* blade = blades.front();
            const double w = blade->turning.width;
            const double mouth = inner_ ? std::min(a.r, b.r) : std::max(a.r, b.r);
            const double rTop = mouth + s_ * t_.clearance;
            const ForbiddenRegion F = ForbiddenRegion::make(partLoop_, bladeShape(w, 50.0, inner_), 0.0, 0.0, 0.0, 0.0002);
            // Plunges from the front wall back, less than a blade width apart.
            const double eps = 1e-4, span = std::max(width - w, 0.0);  // off the walls, inside the blade's own narrowing
            const int n = span <= kTol ? 1 : static_cast<int>(std::ceil(span / (0.8 * w) - 1e-9)) + 1;
            std::vector<ZR> bottoms;
            for (int k = 0; k < n; ++k) {
                const double z = zHi - eps - (n > 1 ? span * k / (n - 1) : 0.0);
                double bottom = rTop;
                for (const auto& f : F.freeAlongR(z, inner_ ? rTop - 1.0 : -1.0, inner_ ? R_ + 100.0 : rTop + 1.0))
                    if (f.first <= rTop + 1e-6 && f.second >= rTop - 1e-6) bottom = inner_ ? f.second : f.first;
                bottoms.push_back({z, bottom});
            }
            double reached = bottoms.front().r;
            for (const ZR p : bottoms) reached = inner_ ? std::max(reached, p.r) : std::min(reached, p.r);
            if (s_ * (reached - deepest) > 0.01) {
                problem("rows", fmt::format("{} cannot be turned: {}; as a groove it is {} wide and {} deep, and the blade {} ({} wide) "
                                            "gets no deeper than {} into it",
                                            elements, whyNot(*finishingTool(), i), len(width), len(std::abs(mouth - deepest)),
                                            toolWords(*blade), len(w), len(std::abs(mouth - reached))));
                continue;
            }
            const auto cutting = cuttingOf(*blade, kGroove, true);
            if (!cutting) continue;
            TurnStep ts;
            ts.side = side_;
            ts.orientation = inner_ ? 4 : 1;  // the blade's front corner
            ts.withdrawal = t_.withdrawal;
            ts.cutting = *cutting;
            ts.region = fmt::format("{}, Z{} to Z{}", elements, len(zLo), len(zHi));
            PathWriter wr{{}, {}};
            wr.begin({zHi, rTop});
            for (std::size_t k = 0; k < bottoms.size(); ++k) {
                wr.rapid({bottoms[k].z, rTop});
                wr.feed(bottoms[k], FeedKind::Plunge);
                if (k + 1 < bottoms.size()) wr.rapid({bottoms[k].z, rTop});
            }
            // Seed 002: withdrawn along the surface's normal at the end point by da.
            const ZR end = bottoms.back();
            const ZR normal = surfaceNormal(end, first_, chain_.size(), w);
            wr.feed(end + t_.withdrawal * normal);
            wr.rapid({wr.path.moves.back().end.z, rTop});
            if (inner_) wr.rapid({zFront_ + t_.clearance, rTop});
            ts.path = std::move(wr.path);
            addStep(StepKind::Grooving, MachiningType::Grooving, *blade,
                    blade == pinned(kGroove) ? "pinned"
                    : w <= width + kTol ? fmt::format("widest grooving blade not wider than the groove ({})", len(width))
                                        : fmt::format("narrowest grooving blade; it reaches {} from the air beside it", elements),
                    std::move(ts));
        }
    }

    const Tool* finishingTool() const { return finishTool_; }

    // The unit normal into the air of the profile where the blade's corner
    // ends (its bottom under the blade): of the groove's elements the one
    // nearest the corner's contact.
    ZR surfaceNormal(ZR corner, std::size_t i, std::size_t j, double w) const
    {
        const ZR mid{corner.z - 0.5 * w, corner.r};
        double best = 1e300;
        ZR n{0.0, s_};
        for (std::size_t k = i; k < j; ++k) {
            const Segment& s = chain_[k];
            ZR p;
            if (s.arc) {
                p = s.centre + s.radius * unit(mid - s.centre);
                if (!contains(s, p)) continue;
            } else {
                const ZR t = s.b - s.a;
                const double u = std::clamp(dot(mid - s.a, t) / std::max(dot(t, t), 1e-18), 0.0, 1.0);
                p = s.a + u * t;
            }
            const double d = dist(p, mid);
            if (d < best) {
                best = d;
                const ZR t = tangentAt(s, p);
                // Air is right of the travel for an outer profile, left for an inner one.
                n = inner_ ? leftNormal(t) : ZR{t.r, -t.z};
            }
        }
        return n;
    }

    // ---- parting off -----------------------------------------------------

    void planParting()
    {
        if (!q_.parting || skipped(kPart)) return;
        const Tool* blade = pinned(kPart);
        if (!blade)
            for (const auto& t : lib_)
                if (t.type == ToolType::Grooving && t.turning.maxDiameter >= q_.bar.diameter - kTol && (!blade || t.turning.width < blade->turning.width))
                    blade = &t;
        if (!blade) {
            note(fmt::format("no parting off: no blade of the tool library parts off the bar's {} (saw it off, or add a blade)", dia(R_)));
            return;
        }
        const double width = blade->turning.width;
        if (zEnd_ - width < zBarEnd_ - kTol) {
            note(fmt::format("no parting off: the part ends {} from the bar's end, less than the blade's width", len(zEnd_ - zBarEnd_)));
            return;
        }
        const auto cutting = cuttingOf(*blade, kPart, true);
        if (!cutting) return;
        TurnStep ts;
        ts.side = ProfileSide::Outer;
        ts.orientation = 1;
        ts.cutting = *cutting;
        ts.region = fmt::format("at Z{}", len(zEnd_));
        PathWriter w{{}, {}};
        const double rTop = R_ + t_.clearance;
        const double rBottom = q_.boreBefore > 0 ? q_.boreBefore / 2.0 - 0.5 : -0.5;
        w.begin({zEnd_, rTop});
        w.rapid({zEnd_, rTop});
        w.feed({zEnd_, rBottom}, FeedKind::Plunge);
        w.rapid({zEnd_, rTop});
        ts.path = std::move(w.path);
        addStep(StepKind::Parting, MachiningType::Parting, *blade,
                blade == pinned(kPart) ? "pinned" : fmt::format("narrowest parting blade for {}", dia(R_)), std::move(ts));
    }

    const TurnPlanRequest& q_;
    const DeformedProfile& d_;
    const std::vector<Tool>& lib_;
    TurningTechnology t_;
    ProfileSide side_ = ProfileSide::Outer;
    bool inner_ = false;
    double s_ = 1.0;          // +1 outer, -1 inner: toward the air from the material
    double R_ = 0.0;          // bar radius
    double zBarEnd_ = 0.0;
    double zFront_ = 0.0, zEnd_ = 0.0, rEnd_ = 0.0;
    double drilled_ = 0.0;
    bool drilledToSize_ = false;
    std::vector<Segment> chain_;
    std::size_t first_ = 0, last_ = 0;  // the turned contour: chain_[first_, last_)
    std::vector<Segment> partLoop_;
    std::vector<bool> finishReach_;
    const Tool* finishTool_ = nullptr;
    std::string finishReason_;
    TurnPlanResult out_;
};

}  // namespace

const std::vector<std::string>& turnStepKeys()
{
    static const std::vector<std::string> keys{kFacing, kCentreDrill, kDrill, kRough, kFinish, kGroove, kPart};
    return keys;
}

TurnPlanResult planTurnedUnit(const TurnPlanRequest& request)
{
    if (!request.deformed || request.deformed->edges.empty() || !request.library) return {};
    return Planner(request).run();
}

}  // namespace taiwa::turning
