// The turning planner's parts shared by its files (internal to
// core/turning/): the step keys, the planner's constants and the Planner
// class, whose steps are planned in turn_plan.cpp (what they share),
// turn_plan_drill.cpp (facing, drilling), turn_plan_rough.cpp (roughing),
// turn_plan_finish.cpp (finishing), turn_plan_groove.cpp (grooves,
// parting off) and turn_plan_thread.cpp (threads). The one door outside
// is turn_plan.h.
#pragma once

#include "modules/turn/turn_plan.h"

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

namespace taiwa::turning::planner {

inline constexpr double kTol = 1e-7;
// The share of a tool's surface speed the spindle limit must still give at
// the smallest diameter a roughing or finishing step turns.
inline constexpr double kMinSpeedShare = 0.5;
// The widest groove a wall the finishing insert cannot go down may open
// (beyond it the wall is a shoulder facing the chuck) [mm].
inline constexpr double kGrooveReach = 30.0;

inline constexpr const char* kFacing = "facing";
inline constexpr const char* kCentreDrill = "centre-drill";
inline constexpr const char* kDrill = "drill";
inline constexpr const char* kRough = "turn-rough";
inline constexpr const char* kFinish = "turn-finish";
inline constexpr const char* kGroove = "groove";
inline constexpr const char* kThread = "thread";
inline constexpr const char* kPart = "part";

inline std::string toolWords(const Tool& t) { return msg::toolName(t); }

// Where the nose, along the finishing contour, would lie in the part.
struct NoseIntoPart {
    double depth = 0.0;
    ZR centre;         // the nose centre there
    std::string edge;  // the deformed edge it follows there (or the nearest)
};

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
        planThreading();
        if (!inner_) planParting();
        return std::move(out_);
    }

    // The insert the finishing step takes (run()'s choice), alone.
    const Tool* finishingInsert() { return first_ < chain_.size() ? chooseFinishing() : nullptr; }

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
    std::vector<Segment> makePartLoop() const;

    const Tool* pinned(const char* key) const;

    // The cutting data of a tool; nullopt (with a problem) when it has none for the material.
    std::optional<TurnCutting> cuttingOf(const Tool& tool, const char* key, bool css);

    Step& addStep(StepKind kind, MachiningType type, const Tool& tool, std::string reason, TurnStep turn);

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
    double safeR() const;

    // ---- the turning inserts ---------------------------------------------

    std::vector<const Tool*> inserts() const;

    // The first element (from the turned contour on) an insert cannot cut,
    // or -1: its holder's angles (no back-cut beyond the clearance) and its
    // nose in concave arcs. `tightArcs` false: a concave arc tighter than
    // the nose counts as reached (the finishing contour bridges it,
    // bridgeTightArcs).
    int firstUnreached(const Tool& t, std::size_t from, std::size_t to, bool tightArcs = true) const;

    // The part's own surfaces (as drawn, and the moved edges the grinder
    // finishes) must be turned; the allowance's sides and relief grooves
    // are grinding stock's shape, whose corners an insert may leave or
    // touch (the note says which).
    bool mustReach(std::size_t i) const;

    std::vector<bool> reachedBy(const Tool& t) const;

    std::string whyNot(const Tool& t, std::size_t i) const;

    // ---- facing ------------------------------------------------------------

    void planFacing();

    const Tool* roughingInsert(bool inside) const;

    // ---- drilling (a bore in a bar without one big enough) ----------------

    void planDrilling();

    // ---- finishing tool ----------------------------------------------------

    const Tool* chooseFinishing();

    // ---- roughing ------------------------------------------------------------

    void planRoughing();
    // Its parts: the profile's extreme radius, the passes.
    double profileExtreme() const;
    TurnPath roughingPasses(const ForbiddenRegion& F, double surface, double depth, int levels, double rn, ZR tip, bool& left) const;

    static double currentZ(const PathWriter& w) { return w.path.moves.empty() ? w.path.start.z : w.path.moves.back().end.z - w.tip.z; }

    std::optional<TurnCycle> roughingCycle(const Tool& tool, double surface) const;

    // The part for roughing's forbidden region: makePartLoop's, with the
    // bar behind the profile's end (outer) and the back face's edges
    // parting off cuts set `behind` further toward the chuck. No step
    // finishes that face (the finishing leaves the profile's end up and
    // forward), so the roughing leaves no allowance on it: its passes reach
    // the profile's end.
    std::vector<Segment> roughingLoop(double behind) const;

    void checkSpindleLimit(const Tool& tool, const TurnCutting& c, const char* key);

    // ---- finishing -----------------------------------------------------------

    // Runs of elements the finishing insert cannot reach: grooves for a blade.
    std::vector<std::pair<std::size_t, std::size_t>> unreachedRuns() const;

    void planFinishing(const Tool& tool);
    // Its parts: the contour as the insert cuts it, the ways onto it to
    // try, where it enters and leaves, the path along it.
    std::vector<Segment> finishingContour(const Tool& tool, double rn);
    std::vector<std::vector<Segment>> finishingWays(const std::vector<Segment>& contour, double rn) const;
    ZR finishingUpAndOut(double rn) const;
    ZR finishingExit(const std::vector<Segment>& c, bool upAndForward, double rn, ZR tipFromCentre) const;
    ZR finishingEntry(const std::vector<Segment>& c, double rn) const;
    TurnPath finishingPath(const std::vector<Segment>& contour, bool upAndForward, double rn, ZR tipFromCentre) const;

    // The air side's unit normal of a line's direction.
    ZR airNormal(ZR t) const { return inner_ ? leftNormal(t) : ZR{t.r, -t.z}; }

    // Runs of the allowance's own edges (relief grooves) the finishing
    // insert cannot follow: followed with compensation, the nose would cut
    // them but the insert's edges would cut what stands beside them, which
    // may be the finished part. The contour crosses such a run on a chord
    // the insert can follow, from before the run to after it, clear of the
    // part; the groove is left (a note says so). Where no such chord is
    // found within a few nose radii, the run is followed as drawn.
    void crossGrindingStockRuns(std::vector<Segment>& contour, const Tool& tool);

    // A concave corner the nose can sit in only if both lines are long
    // enough to hold it (the control refuses the move otherwise: "concave
    // corner cannot be reached by the tool without gouging"). Where a line
    // is shorter (the step at a grinding allowance's end, lower than the
    // nose), the contour runs from the short line's start straight to where
    // the nose touches the next line, as far along it as needed: what the
    // nose leaves there is the fillet it cannot help leaving.
    void reachableCorners(std::vector<Segment>& contour, double rn);

    // turn_plan_corners.cpp. A concave arc (the material outside its circle).
    bool concaveArc(const Segment& s) const;
    // Whether any of the elements a chord replaces lies on its air side
    // (the nose along the chord would cut it).
    bool overChord(const std::vector<Segment>& skipped, const Segment& chord) const;
    // A concave arc no wider than the nose (a fillet, a picked rounding):
    // the compensated path cannot follow it (the control refuses it: "Arc
    // move in concave corner cannot be reached by the tool without
    // gouging"). The contour leaves it: its neighbours run on along their
    // tangents where the nose touches both, to the corner they make there,
    // and a note says how much material the nose leaves in it.
    void bridgeTightArcs(std::vector<Segment>& contour, double rn, const Tool& tool);
    // reachableCorners for a concave corner next to an arc: where the nose
    // touching both would lie beyond one of them (a short step between two
    // arcs, at an allowance's end), that one is replaced by a line to where
    // the nose touches the other, a little past it. Whether it changed any.
    bool reachableArcCorners(std::vector<Segment>& contour, double rn);
    // For a short B after a convex arc A (a concave corner between them):
    // the point of A nearest its end from which a line to B's end lies over
    // the rest of A and makes a corner with A the nose holds; none when A is
    // not a convex arc or no such point exists.
    // The deepest the nose (radius rn) goes into the part along the
    // compensated contour (its centre's offsets trimmed at concave corners
    // where they cross; at convex ones it rolls round the corner); none
    // within 2 µm. `withEntry`: the contour begins with the entry (a line
    // whose start is where the nose centre is less its offset), measured
    // against the whole part as the verification closes it, with the step
    // onto the first element where their offsets do not cross. `exitTo`:
    // where the nose centre ends the exit, straight from the last offset's
    // end (compensation cancelled): the exit alone measured, likewise.
    // The first element of `contour` (its index) the control's nose
    // compensation cannot run as programmed, or none: at each concave corner
    // the nose centre's offsets of the two elements must cross on both, and
    // along each element the point where it leaves the previous corner must
    // come before the point where it meets the next one. Otherwise the
    // control refuses the tape (LinuxCNC: "... in concave corner cannot be
    // reached by the tool without gouging") or runs the element backwards
    // into the part. The entry, when it is the contour's first element, is
    // held to the same.
    std::optional<std::size_t> unheldCorner(const std::vector<Segment>& contour, double rn) const;
    // Where unheldCorner finds an element too short to hold the nose at its
    // concave corners after the other repairs (a stub of a convex arc left
    // between two lines that end on it: a relief groove's bottom, a rounding
    // an allowance's side steps up from), the element and its neighbour
    // after it (else before it) become one line, where that line lies over
    // what it replaces (the material under it is left, as at every corner
    // the nose cannot reach). Whether it changed any.
    bool mergeUnheldElements(std::vector<Segment>& contour, double rn);
    // The id of the deformed edge nearest `p`.
    std::string edgeNear(ZR p) const;
    std::optional<NoseIntoPart> noseIntoPart(const std::vector<Segment>& contour, double rn,
                                             std::optional<ZR> exitTo = std::nullopt, bool withEntry = false) const;
    std::optional<ZR> ontoConvex(const Segment& A, const Segment& B, double rn) const;

    // ---- grooving --------------------------------------------------------

    void planGrooves();
    // Its parts: the blades for a run, the plunges' bottoms, the blade's path.
    std::vector<const Tool*> groovingBlades(double width) const;
    std::vector<ZR> groovePlunges(const ForbiddenRegion& F, double zLo, double zHi, double w, double rTop) const;
    TurnPath groovePath(const ForbiddenRegion& F, const std::vector<ZR>& bottoms, double zHi, double w, double rTop) const;

    const Tool* finishingTool() const { return finishTool_; }

    // The unit normal into the air of the profile where the blade's corner
    // ends (its bottom under the blade): of the groove's elements the one
    // nearest the corner's contact.
    ZR surfaceNormal(ZR corner, std::size_t i, std::size_t j, double w) const;

    // ---- threading -------------------------------------------------------

    void planThreading();
    // The passes of the control's G76 for the thread, as the programmed point.
    static TurnPath threadPath(const TurnThread& th);
    // The highest radius the part's chain reaches for zLo <= z <= zHi,
    // element `skip` left out (-1e300 where it has none there).
    double highestIn(double zLo, double zHi, std::size_t skip) const;

    // ---- parting off -----------------------------------------------------

    void planParting();
    // The rearmost Z of the part (its deformed profile) and, when it lies
    // behind the profile's end, the profile edge whose allowance reaches there.
    std::pair<double, std::optional<std::string>> rearmost() const;

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

}  // namespace taiwa::turning::planner
