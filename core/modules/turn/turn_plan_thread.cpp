// Turning steps: external threads on the rows that ask for one
// (turn_planner.h; docs/turning.md "Threading"). One step per threaded
// edge, after finishing and grooving (the thread's relief is cut first):
// the library's threading insert for the pitch, a fixed spindle speed (G97)
// from its surface speed at the thread's diameter, and the passes of the
// control's G76 as LinuxCNC makes them (interp_convert.cc,
// convert_threading_cycle), so that the path is what the tape runs.
#include "modules/turn/turn_planner.h"
#include "model/translate_noop.h"

namespace taiwa::turning::planner {

namespace {

// The last pass of a constant-area infeed cuts at least this much (radius)
// [mm]: it sets the number of passes, n = depth / (2 × this).
constexpr double kLastPass = 0.08;
constexpr int kMinPasses = 3, kMaxPasses = 40;
// The run-in in front of the thread, in pitches: the axis reaches the
// pitch's feed before the tool meets the part.
constexpr double kRunInPitches = 3.0;
// The run-out into the relief behind the thread, in pitches.
constexpr double kRunOutPitches = 0.5;
// The compound (flank) infeed angle for a 60° thread [deg].
constexpr double kCompoundAngle = 29.5;
// The tapes give depths as diameters to 0.001 mm: the plan rounds to that grid.
constexpr double kDiameterGrid = 0.001;

double onDiameterGrid(double r, bool up)
{
    const double d = 2.0 * r / kDiameterGrid;
    return (up ? std::ceil(d - 1e-6) : std::round(d)) * kDiameterGrid / 2.0;
}

}  // namespace

double Planner::highestIn(double zLo, double zHi, std::size_t skip) const
{
    double top = -1e300;
    for (std::size_t k = 0; k < chain_.size(); ++k) {
        if (k == skip) continue;
        const Segment& s = chain_[k];
        const int n = s.arc ? 64 : 1;
        for (int j = 0; j <= n; ++j) {
            const ZR p = pointAt(s, static_cast<double>(j) / n);
            if (p.z >= zLo - kTol && p.z <= zHi + kTol) top = std::max(top, p.r);
        }
        // A line crossing the range's ends counts where it crosses them.
        if (!s.arc)
            for (const double z : {zLo, zHi})
                if ((s.a.z - z) * (s.b.z - z) < 0) top = std::max(top, s.a.r + (s.b.r - s.a.r) * (z - s.a.z) / (s.b.z - s.a.z));
    }
    return top;
}

void Planner::planThreading()
{
    for (std::size_t i = first_; i < last_; ++i) {
        const DeformedEdge& e = d_.edges[i];
        if (!e.attributes.thread || e.origin != Origin::Original) continue;
        const ThreadSpec& spec = *e.attributes.thread;
        const Segment& s = chain_[i];
        // The input check refuses these with the row's field; the plan
        // stays safe without it.
        if (inner_ || s.arc || std::abs(s.a.r - s.b.r) > 1e-6 || s.b.z >= s.a.z) {
            problem("rows", fmt::format("{} cannot be threaded: only straight outer edges along the axis, cut toward the chuck", e.id));
            continue;
        }
        if (skipped(kThread)) {
            note(fmt::format("the thread on {} is left: threading is turned off", e.id));
            continue;
        }
        const Tool* tool = pinned(kThread);
        if (!tool)
            for (const auto& t : lib_)
                if (t.type == ToolType::Threading && !t.turning.inside && spec.pitch >= t.turning.pitchMin - kTol &&
                    spec.pitch <= t.turning.pitchMax + kTol && (!tool || t.id < tool->id))
                    tool = &t;
        if (!tool || tool->type != ToolType::Threading) {
            problem(std::string("tools.") + kThread,
                    fmt::format("the thread of pitch {} on {} needs an external threading insert for that pitch, and the tool library has none",
                                len(spec.pitch), e.id));
            continue;
        }
        const double crest = s.a.r, depth = onDiameterGrid(e.attributes.threadDepth(), false);
        const double runIn = kRunInPitches * spec.pitch, runOut = kRunOutPitches * spec.pitch;
        const double zStart = s.a.z + runIn, zEnd = s.b.z - runOut;
        // Nothing in front of the thread stands above its crest (the tool
        // comes in from the front), and behind it the relief lies below the
        // root for the run-out and the insert's width (a pitch).
        if (highestIn(s.a.z, zStart, i) > crest + 1e-6) {
            problem("rows", fmt::format("the thread on {} lies behind a larger diameter: the threading insert cannot reach it from the front", e.id));
            continue;
        }
        if (highestIn(zEnd - spec.pitch, s.b.z - 1e-3, i) > crest - depth - 1e-6) {
            problem("rows", fmt::format("the thread on {} ends at a shoulder: the insert needs a relief behind it at least {} long and "
                                        "deeper than the thread's {} (a groove below {})",
                                        e.id, len(runOut + spec.pitch), len(depth), dia(crest - depth)));
            continue;
        }
        auto cutting = cuttingOf(*tool, kThread, true);
        if (!cutting) continue;
        // A fixed speed (G97): the surface speed at the thread's diameter,
        // within the machine's spindle limit and its feed limit (the feed
        // is the pitch per revolution).
        double rpm = cutting->rpmAt(2.0 * crest, q_.maxRpm);
        cutting->constantSurfaceSpeed = false;
        if (q_.maxFeed > 0) rpm = std::min(rpm, q_.maxFeed / spec.pitch);
        cutting->rpm = std::floor(rpm);
        cutting->feedPerRev = cutting->plungeFeedPerRev = spec.pitch;

        TurnThread th;
        th.pitch = spec.pitch;
        th.depth = depth;
        th.crestR = crest;
        th.clearance = t_.clearance;
        th.zStart = zStart;
        th.zEnd = zEnd;
        th.compoundAngle = kCompoundAngle;
        th.springPasses = 1;
        const int n = std::clamp(static_cast<int>(std::ceil(depth / (2.0 * kLastPass) - 1e-9)), kMinPasses, kMaxPasses);
        th.firstDepth = onDiameterGrid(depth / std::sqrt(static_cast<double>(n)), true);
        // Clear of the depth after n passes, so that the control's own
        // comparison cannot add a pass the plan does not have.
        if (th.firstDepth * std::sqrt(static_cast<double>(n)) < depth + 1e-7) th.firstDepth += kDiameterGrid / 2.0;
        // LinuxCNC's loop: passes at firstDepth √k while below the depth,
        // then the full depth once and the spring passes.
        for (int k = 1; th.firstDepth * std::sqrt(static_cast<double>(k)) < depth; ++k)
            th.passDepths.push_back(th.firstDepth * std::sqrt(static_cast<double>(k)));
        for (int k = 0; k <= th.springPasses; ++k) th.passDepths.push_back(depth);

        TurnStep ts;
        ts.side = ProfileSide::Outer;
        ts.orientation = insertOrientation(false);
        ts.tipFromCentre = tipFromCentre(tool->cornerRadius, false);
        ts.depthOfCut = th.firstDepth;
        ts.cutting = *cutting;
        ts.region = fmt::format("{} thread {}×{}", e.id, dia(crest), len(spec.pitch));
        ts.path = threadPath(th);
        ts.thread = th;
        addStep(StepKind::Threading, MachiningType::Threading, *tool,
                tool == pinned(kThread) ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned")
                                        : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "external threading insert for pitch {}"), len(spec.pitch)), std::move(ts));
    }
}

TurnPath Planner::threadPath(const TurnThread& th)
{
    // As convert_threading_cycle: per pass back (above the drive line by
    // what is still to cut), in, synchronised along Z, out; the compound
    // angle shifts each pass's Z by its depth × tan(Q), and the last pass
    // ends on the thread's end.
    const double tanQ = std::tan(th.compoundAngle * std::numbers::pi / 180.0);
    const double rDrive = th.crestR + th.clearance;
    const double zTarget = th.zEnd + th.depth * tanQ;
    TurnPath p;
    p.start = {th.zStart, rDrive};
    for (const double d : th.passDepths) {
        const double zoff = d * tanQ, rOut = rDrive + th.depth - d;
        p.moves.push_back({TurnMove::Rapid, {th.zStart - zoff, rOut}, {}, FeedKind::Cut});
        p.moves.push_back({TurnMove::Rapid, {th.zStart - zoff, th.crestR - d}, {}, FeedKind::Cut});
        p.moves.push_back({TurnMove::Feed, {zTarget - zoff, th.crestR - d}, {}, FeedKind::Cut});
        p.moves.push_back({TurnMove::Rapid, {zTarget - zoff, rOut}, {}, FeedKind::Cut});
    }
    p.moves.push_back({TurnMove::Rapid, {th.zEnd, rDrive}, {}, FeedKind::Cut});
    return p;
}

}  // namespace taiwa::turning::planner
