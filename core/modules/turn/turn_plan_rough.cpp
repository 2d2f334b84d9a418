// Turning steps: roughing, as passes and as the control's cycle (turn_planner.h).
#include "modules/turn/turn_planner.h"
#include "model/translate_noop.h"

namespace taiwa::turning::planner {

void Planner::planRoughing()
{
    if (skipped(kRough)) return;
    const Tool* tool = pinned(kRough);
    std::string reason = TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned");
    if (tool) {
        if (!insertGeometry(*tool) || tool->turning.inside != inner_) {
            problem(std::string("tools.") + kRough, inner_ ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not an inside turning insert"), toolWords(*tool))
                                                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not an outside turning insert"), toolWords(*tool)));
            return;
        }
    } else {
        tool = roughingInsert(inner_);
        if (!tool) return;  // chooseFinishing said it
        reason = TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest nose radius for its side (the strongest edge)");
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
    // The bar behind the profile's end moved back by what the region adds
    // to a face (the allowance, the flattening's growth, the nose
    // polygon's excess over the nose) and a micrometre: the passes' tips
    // reach the profile's end, none stops an allowance short of it.
    const ToolShape shape = insertShape(g);
    double noseBack = 0.0;  // how far the shape reaches toward the chuck from the nose centre
    for (const ZR q : shape) noseBack = std::max(noseBack, -q.z);
    const ForbiddenRegion F =
        ForbiddenRegion::make(roughingLoop(t_.allowanceZ + kFlatten + (noseBack - rn) + 0.001), shape, t_.allowanceX, t_.allowanceZ);

    // Levels of the nose's cutting point (outer: its lowest, inner: its
    // highest point) from the stock's surface to the profile's extreme.
    const double surface = inner_ ? std::max(q_.boreBefore, drilled_) / 2.0 : R_;
    const double extreme = profileExtreme() + s_ * t_.allowanceX;
    const double depth = s_ * (surface - extreme);
    if (depth <= kTol) {
        note(fmt::format("no roughing: the stock is already within the finishing allowance", q_.unit + 1));
        return;
    }
    const int levels = std::max(1, static_cast<int>(std::ceil(depth / t_.depthOfCut - 1e-9)));
    bool left = false;  // pockets the insert cannot enter
    ts.path = roughingPasses(F, surface, depth, levels, rn, ts.tipFromCentre, left);
    if (left) note(fmt::format("roughing with {} leaves pockets its insert cannot enter for the finishing tool", toolWords(*tool)));
    ts.region = fmt::format("{} to {}, Z{} to Z{}", dia(surface), dia(extreme), len(zFront_), len(zEnd_));

    // The control's own cycle where the profile allows it: the contour
    // monotone (one element after the other outward and toward the
    // chuck), reached by the insert everywhere. Then the nose runs
    // clear of every element with the tip on the contour plus the
    // allowance (docs/turning.md).
    if (const auto cycle = roughingCycle(*tool, surface)) ts.path.cycle = *cycle;
    addStep(StepKind::TurnRoughing, MachiningType::TurnRoughing, *tool, reason, std::move(ts));
}

// The profile's extreme radius (outer: its least, inner: its greatest),
// the arcs' own extremes included.
double Planner::profileExtreme() const
{
    double extreme = inner_ ? -1e300 : 1e300;
    for (std::size_t i = first_; i < last_; ++i)
        for (const ZR p : {chain_[i].a, chain_[i].b}) extreme = inner_ ? std::max(extreme, p.r) : std::min(extreme, p.r);
    for (std::size_t i = first_; i < last_; ++i)
        if (chain_[i].arc) {
            const ZR c = chain_[i].centre;
            const ZR ext{c.z, c.r - s_ * chain_[i].radius};
            if (contains(chain_[i], ext)) extreme = inner_ ? std::max(extreme, ext.r) : std::min(extreme, ext.r);
        }
    return extreme;
}

// The roughing passes: levels of the nose's cutting point from the stock's
// surface `depth` down in `levels` even steps, each along what is free at
// that level and every level above (the part's shadow), pockets entered by
// a plunge at their front end. `left`: pockets the insert cannot enter.
TurnPath Planner::roughingPasses(const ForbiddenRegion& F, double surface, double depth, int levels, double rn, ZR tip, bool& left) const
{
    const double zApproach = std::max(zFront_, q_.facing ? zFront_ : q_.bar.face) + t_.clearance + rn;
    const double zLo = std::min(zBarEnd_, zEnd_) - 1.0;
    const double rSafe = safeR() + s_ * rn;
    PathWriter w{{}, tip};
    w.begin({zApproach, rSafe});
    std::vector<std::pair<double, double>> open{{zLo, zApproach}};
    double rPrev = surface + s_ * rn;  // nose centre on the stock surface
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
                // A pocket: plunge at its front end from the level above, the
                // rapid stopping a retract short of it (on it, the insert
                // touches the stock at rapid speed).
                const double above = s_ > 0 ? std::min(rPrev + t_.retract, rSafe) : std::max(rPrev - t_.retract, rSafe);
                if (!F.segmentFree({b, above}, {b, rc})) {
                    left = true;
                    continue;
                }
                w.rapid({currentZ(w), rSafe});
                w.rapid({b, rSafe});
                w.rapid({b, above});
                w.feed({b, rc}, FeedKind::Plunge);
            } else {
                // Back from a pocket (the tool above the bar behind the
                // profile): over to the front first, then down to the level.
                if (std::abs(currentZ(w) - zApproach) > 1e-9) w.rapid({zApproach, rSafe});
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
    return std::move(w.path);
}

std::vector<Segment> Planner::roughingLoop(double behind) const
{
    if (inner_) return partLoop_;  // a bore's bar goes on past the profile's end: no face there
    std::vector<Segment> loop(chain_.begin(), chain_.begin() + static_cast<long>(last_));
    const ZR start = chain_.front().a, end = chain_[last_ - 1].b;
    const double zLo = std::min(zBarEnd_, zEnd_) - 1.0, zWall = std::max(zEnd_ - behind, zLo + kTol);
    const std::vector<ZR> pts{end, {zWall, end.r}, {zWall, R_}, {zLo, R_}, {zLo, 0.0}, {start.z, 0.0}, start};
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        if (dist(pts[i], pts[i + 1]) > kTol) loop.push_back(lineSegment(pts[i], pts[i + 1]));
    return loop;
}

std::optional<TurnCycle> Planner::roughingCycle(const Tool& tool, double surface) const
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
    // LinuxCNC's G71 cannot take two lines in a row on one line ("Cannot
    // intersect parallel lines"): such lines are joined, and a contour
    // that starts along Z starts at the cycle's start plane (the post's
    // approach to the first point would be another such line).
    std::vector<Segment> joined;
    for (const Segment& s : c.contour) {
        if (!joined.empty() && !s.arc && !joined.back().arc) {
            const ZR u = unit(joined.back().b - joined.back().a), v = unit(s.b - s.a);
            if (std::abs(cross(u, v)) < 1e-9 && dot(u, v) > 0) {
                joined.back() = lineSegment(joined.back().a, s.b);
                continue;
            }
        }
        joined.push_back(s);
    }
    if (!joined.front().arc && std::abs(joined.front().a.r - joined.front().b.r) < 1e-9 && joined.front().a.z < c.start.z)
        joined.front() = lineSegment({c.start.z, joined.front().a.r}, joined.front().b);
    c.contour = std::move(joined);
    c.depthOfCut = t_.depthOfCut;
    c.allowanceX = t_.allowanceX;
    c.allowanceZ = t_.allowanceZ;
    c.retract = t_.retract;
    return c;
}

}  // namespace taiwa::turning::planner
