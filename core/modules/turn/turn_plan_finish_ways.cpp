// Turning steps: the finishing contour's ways in and out and its path
// (turn_planner.h, planFinishing): the ways onto the contour to try, the
// entry along -Z, the exit up and forward or straight out, and the moves
// with the nose compensation on along the contour.
#include "modules/turn/turn_planner.h"

namespace taiwa::turning::planner {

// The ways onto the contour to try, in order: the contour itself; without
// the short lines at its start the nose cannot sit against coming along -Z
// (a bore face's allowance: the side of the lip it stands on); with a
// lead-in along the part's edge before it (the front face facing cut, up to
// a front rounding).
std::vector<std::vector<Segment>> Planner::finishingWays(const std::vector<Segment>& contour, double rn) const
{
    std::vector<std::vector<Segment>> ways{contour};
    {
        std::vector<Segment> c = contour;
        const ZR in{-1.0, 0.0};
        // Only an edge of the allowance's own (a side), never the part's.
        const auto side = [&](const Segment& e) {
            for (std::size_t i = first_; i < last_; ++i)
                if (dist(chain_[i].a, e.a) < 1e-9 && dist(chain_[i].b, e.b) < 1e-9) return !mustReach(i);
            return false;
        };
        while (c.size() > 1 && !c.front().arc && side(c.front())) {
            const ZR t = tangentAtStart(c.front());
            if (s_ * cross(in, t) >= -1e-9 && dot(in, t) > -1e-9) break;  // not a concave turn from -Z
            const double phi = std::acos(std::clamp(dot(in, t), -1.0, 1.0));
            if (phi < std::numbers::pi - 1e-6 && length(c.front()) >= rn * std::tan(phi / 2.0) + 0.01) break;  // holds it
            c.erase(c.begin());
        }
        if (c.size() < contour.size()) ways.push_back(c);
    }
    if (first_ > 0) {
        const Segment& before = chain_[first_ - 1];
        if (dist(before.b, contour.front().a) < 1e-9) {
            const double l = length(before);
            std::vector<Segment> c = contour;
            c.insert(c.begin(), l > 2.0 * rn + 1e-6 ? piece(before, pointAt(before, l - 2.0 * rn), before.b) : before);
            ways.push_back(c);
        }
    }
    return ways;
}

// The exit up and forward, from the contour's last point.
ZR Planner::finishingUpAndOut(double rn) const
{
    return {t_.clearance, s_ * (t_.clearance + 2.0 * rn)};
}

// The exit's end (the programmed point) for a contour: off the part with
// compensation cancelled, up and forward, unless the last element falls
// toward its end (the tool would go back into it): then straight out, away
// from it. Straight out: the control cancels compensation moving the nose
// centre in a line from where it touches the last element, so the
// programmed end is that centre moved out, plus the tip's offset.
ZR Planner::finishingExit(const std::vector<Segment>& c, bool upAndForward, double rn, ZR tipFromCentre) const
{
    const ZR last = c.back().b;
    if (upAndForward) return last + finishingUpAndOut(rn);
    return last + rn * airNormal(tangentAtEnd(c.back())) + ZR{0.0, finishingUpAndOut(rn).r} + tipFromCentre;
}

// The entry: along -Z onto the contour's start, from a point clear of it by
// the clearance and two nose radii (as the nose centre runs it, the
// programmed point less the tip's offset).
ZR Planner::finishingEntry(const std::vector<Segment>& c, double rn) const
{
    const ZR first = c.front().a;
    return {first.z + t_.clearance + 2.0 * rn, first.r};
}

// The finishing path: to the entry point with the nose clear, compensation
// on along -Z onto the contour, along it, off at the exit, and away.
TurnPath Planner::finishingPath(const std::vector<Segment>& contour, bool upAndForward, double rn, ZR tipFromCentre) const
{
    TurnPath p;
    const ZR first = contour.front().a;
    const ZR entry = finishingEntry(contour, rn);
    p.start = {entry.z, safeR()};
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
    p.moves.push_back({TurnMove::Feed, finishingExit(contour, upAndForward, rn, tipFromCentre), {}, FeedKind::Cut});
    p.moves.push_back({TurnMove::Rapid, {p.moves.back().end.z, safeR()}, {}, FeedKind::Cut});
    // Out of a bore along the axis before the turret moves on.
    if (inner_) p.moves.push_back({TurnMove::Rapid, {entry.z, safeR()}, {}, FeedKind::Cut});
    return p;
}

}  // namespace taiwa::turning::planner
