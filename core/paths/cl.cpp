// CL creation: the tool path of a step by its kind, and time estimates.
#include "paths/cl.h"

#include "paths/generators.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa {

ToolPath makeToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    if (!step.holes.empty()) return paths::holeCycles(step, tool, params);  // hole patterns (module HOLES)
    if (step.region) {
        switch (step.kind) {
        case StepKind::Roughing:
            if (!(tech.gamma > 0.0)) throw std::invalid_argument("gamma must be positive");
            return paths::regionRoughing(step, tool, tech, params);
        case StepKind::FloorFinishing: return paths::regionFloorFinishing(step, tool, tech, params);
        case StepKind::WallFinishing: return paths::regionWallFinishing(step, tool, tech, params);
        default: break;
        }
    }
    switch (step.kind) {
    case StepKind::PilotHole: return paths::pilotHole(step, tool, params);
    case StepKind::Roughing:
        if (!(tech.gamma > 0.0)) throw std::invalid_argument("gamma must be positive");
        return paths::pocketRoughing(step, tool, tech, params);
    case StepKind::FloorFinishing: return paths::floorFinishing(step, tool, params);
    case StepKind::WallFinishing: return paths::wallFinishing(step, tool, tech, params);
    case StepKind::InclinedFaceFinishing: return paths::inclinedFace(step, tool, params);
    case StepKind::FaceMilling: return paths::faceMilling(step, tool, tech, params);
    case StepKind::SideMilling: return paths::sideMilling(step, tool, tech, params);
    case StepKind::AreaClearing: return paths::areaClearing(step, tool, tech, params);
    default: break;  // turning steps (Step::turn) get their paths from core/turning/
    }
    throw std::logic_error("no milling tool path for step " + step.label());
}

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
    if (!(rate > 0.0)) throw std::invalid_argument("a feed rate used by the path is not positive");
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

double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    if (!step.holes.empty()) return static_cast<double>(step.holes.size()) + 2;  // a cycle a hole
    const double D = std::max(tool.diameter, 1e-3);
    const double layers = std::ceil(std::max(step.cutDepth - step.startDepth, 0.0) / std::max(tech.gamma * D, 1e-3)) + 1;
    const double rings =
        std::ceil((step.region ? step.inscribed : step.outline ? inscribedRadius(step.outline->corners) : 0.0) /
                  std::max(std::min(step.stepOver.value_or(tech.stepOver), params.finishStepOver) * D, 1e-3)) + 1;
    if (step.region) {  // a ring of a contour has about as many moves as the flattened region has points
        double points = static_cast<double>(flatten(step.region->outer, 1e-4).size());
        for (const auto& i : step.region->islands) points += static_cast<double>(flatten(i, 1e-4).size());
        if (step.kind == StepKind::Roughing) return layers * rings * points;
        if (step.kind == StepKind::FloorFinishing) return rings * points;
        if (step.kind == StepKind::WallFinishing) {  // exact lines and arcs: about two moves a segment, a lead each loop
            double segments = static_cast<double>(step.region->outer.segments.size());
            for (const auto& i : step.region->islands) segments += static_cast<double>(i.segments.size()) + 6;
            return (step.multiIncision ? layers : 1) * (2 * segments + 10);
        }
    }
    if (step.kind == StepKind::SideMilling && step.sideContour) {  // each pass: about a move a segment, two a joint, leads
        const double passes = static_cast<double>(std::max<std::size_t>(step.sideOffsets.size(), 1));
        return (step.multiIncision ? layers : 1) * passes * (2 * static_cast<double>(step.sideContour->segments.size()) + 8);
    }
    constexpr double kMovesPerRing = 12;  // four sides, four corners, links
    switch (step.kind) {
    case StepKind::PilotHole: return 10;
    case StepKind::Roughing: return layers * rings * kMovesPerRing;
    case StepKind::FloorFinishing: return rings * kMovesPerRing * 2;
    case StepKind::WallFinishing: return (step.multiIncision ? layers : 1) * kMovesPerRing + 10;
    case StepKind::FaceMilling: {  // passes across the face, four moves each
        if (!step.outline) return 10;
        const double a = step.passAngle * std::numbers::pi / 180.0;
        double lo = 1e300, hi = -1e300;
        for (const Point2 c : step.outline->corners) {
            const double v = -std::sin(a) * c.x + std::cos(a) * c.y;
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        return (std::ceil((hi - lo) / std::max(step.stepOver.value_or(0.75) * D, 1e-3)) + 2) * 4 + 4;
    }
    case StepKind::InclinedFaceFinishing: {
        if (!step.face) return 10;
        const double R = D / 2, h = std::clamp(step.scallop, 1e-6, R);
        const double stepOver = 2 * std::sqrt(2 * R * h - h * h);
        const double span = distance(step.face->topEdge[0], step.face->floorEdge[0]) + step.cutDepth;
        return (std::ceil(span / std::max(stepOver, 1e-6)) + 1) * 4;
    }
    case StepKind::AreaClearing:  // a ramp and the drawn passes a layer
        return layers * (static_cast<double>(step.drawnPoints.size()) + 20);
    default: break;  // turning steps (Step::turn) come with their moves
    }
    if (step.turn) return static_cast<double>(step.turn->path.moves.size());
    return 10;
}

}  // namespace taiwa
