// Lengths and times of turning paths (model/turn_path.h).
#include "model/turn_path.h"

#include "model/step.h"

#include "model/turned_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa {

namespace {

// The move from `from` as an exact segment of the half-plane.
turning::Segment segmentOf(turning::ZR from, const TurnMove& m)
{
    if (m.kind == TurnMove::ArcCW || m.kind == TurnMove::ArcCCW)
        return turning::arcSegment(from, m.end, m.centre, m.kind == TurnMove::ArcCCW);
    return turning::lineSegment(from, m.end);
}

}  // namespace

const TurnStep* turnOf(const Step& s) { return s.payload.getIf<TurnStep>(); }

double TurnCutting::rpmAt(double diameter, double limit) const
{
    if (!constantSurfaceSpeed) return rpm;
    return diameter > 0 ? std::min(limit, 1000.0 * surfaceSpeed / (std::numbers::pi * diameter)) : limit;
}

PathLength turnPathLength(const TurnPath& p)
{
    PathLength l;
    turning::ZR at = p.start;
    for (const auto& m : p.moves) {
        const double len = turning::length(segmentOf(at, m));
        (m.kind == TurnMove::Rapid ? l.rapid : l.feed) += len;
        at = m.end;
    }
    return l;
}

double turnMinutes(const TurnPath& p, const TurnCutting& c, double rapidMmPerMin)
{
    double minutes = 0.0;
    turning::ZR at = p.start;
    for (const auto& m : p.moves) {
        const turning::Segment s = segmentOf(at, m);
        const double len = turning::length(s);
        if (m.kind == TurnMove::Rapid) {
            minutes += len / std::max(rapidMmPerMin, 1.0);
        } else {
            // The spindle speed at the move's mean diameter (exact for
            // moves along Z; under G96 the speed changes along a face).
            const double rpm = c.rpmAt(std::max(std::abs(at.r) + std::abs(m.end.r), 1e-3), c.maxRpm);
            const double f = m.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev;
            minutes += len / std::max(f * rpm, 1e-6);
        }
        at = m.end;
    }
    return minutes;
}

}  // namespace taiwa
