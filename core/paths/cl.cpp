// CL creation: the tool path of a step by its kind, and time estimates.
#include "paths/cl.h"

#include "paths/pocket.h"
#include "paths/walls.h"

#include <cmath>

namespace taiwa {

ToolPath makeToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params)
{
    switch (step.kind) {
    case StepKind::PilotHole: return paths::pilotHole(step, tool, params);
    case StepKind::Roughing: return paths::pocketRoughing(step, tool, tech, params);
    case StepKind::FloorFinishing: return paths::floorFinishing(step, tool, params);
    case StepKind::WallFinishing: return paths::wallFinishing(step, tool, tech, params);
    case StepKind::InclinedFaceFinishing: return paths::inclinedFace(step, tool, params);
    }
    return {};
}

double estimateMinutes(const ToolPath& path, const SpeedsFeeds& sf, double rapidRate)
{
    // Each move's length at its own rate: cutting feed, plunge/ramp feed or rapid.
    double minutes = 0.0;
    Point3 at = path.start;
    for (const auto& m : path.moves) {
        ToolPath one{at, {m}};
        const PathLength len = pathLength(one);
        const double feed = m.kind == MoveKind::DrillCycle || m.feed == FeedKind::Cut ? sf.feed : sf.plungeFeed;
        if (feed > 0) minutes += len.feed / feed;
        minutes += len.rapid / rapidRate;
        if (m.kind != MoveKind::DrillCycle) at = m.end;
    }
    return minutes;
}

}  // namespace taiwa
