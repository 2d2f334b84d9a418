// CL creation: the move and time estimates every step's path shares.
#include "paths/cl.h"


#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa {

namespace {

double distance3(Point3 a, Point3 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)); }

// Length of a feed or arc move (helices: the planar arc and the Z change).
double cutLength(Point3 from, const Move& m)
{
    if (m.kind == MoveKind::Feed) return distance3(from, m.end);
    const double radius = std::hypot(from.x - m.centre.x, from.y - m.centre.y);
    return std::hypot(std::abs(arcSweep(from, m)) * radius, m.end.z - from.z);
}

double minutesAt(double mm, double rate)
{
    if (mm <= 0.0) return 0.0;
    if (!(rate > 0.0)) throw std::logic_error("a feed rate used by the path is not positive");
    return mm / rate;
}

}  // namespace

double estimateMinutes(const ToolPath& path, const SpeedsFeeds& sf, double rapidRate)
{
    double cut = 0.0, plunge = 0.0, rapid = 0.0;
    Point3 at = path.start;
    for (const auto& m : path.moves) {
        switch (m.kind) {
        case MoveKind::Rapid: rapid += distance3(at, m.end); break;
        case MoveKind::Feed:
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: (m.feed == FeedKind::Cut ? cut : plunge) += cutLength(at, m); break;
        case MoveKind::DrillCycle: {
            // G98 cycle: rapid over the hole and down to the R plane, drill
            // at the feed; each peck retracts to the R plane and rapids back
            // to its depth; rapid out to R and back to the initial level.
            const double drilled = m.retractZ - m.end.z;
            // Tapping and reaming come out at the feed, the others rapid.
            const bool fedOut = m.cycle == CycleKind::Tap || m.cycle == CycleKind::Ream;
            rapid += std::hypot(m.end.x - at.x, m.end.y - at.y) + 2 * std::abs(at.z - m.retractZ) + (fedOut ? 0.0 : drilled);
            cut += fedOut ? 2 * drilled : drilled;
            if (m.peck > 0.0)
                for (double reached = m.peck; reached < drilled - 1e-9; reached += m.peck) rapid += 2 * reached;
            at = {m.end.x, m.end.y, at.z};
            continue;
        }
        }
        at = m.end;
    }
    return minutesAt(cut, sf.feed) + minutesAt(plunge, sf.plungeFeed) + minutesAt(rapid, rapidRate);
}

double estimatedLayers(const Step& step, const Tool& tool, const TechnologyData& tech)
{
    const double D = std::max(tool.diameter, 1e-3);
    return std::ceil(std::max(millingOf(step).cutDepth - millingOf(step).startDepth, 0.0) / std::max(tech.gamma * D, 1e-3)) + 1;
}

double estimatedRings(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    const MillingGeometry& g = millingOf(step);
    const double D = std::max(tool.diameter, 1e-3);
    return std::ceil((g.region ? g.inscribed : g.outline ? inscribedRadius(g.outline->corners) : 0.0) /
                     std::max(std::min(g.stepOver.value_or(tech.stepOver), params.finishStepOver) * D, 1e-3)) + 1;
}

}  // namespace taiwa
