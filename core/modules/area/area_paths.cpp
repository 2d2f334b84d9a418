// Tool path of an area cleared by drawn passes (module AREA): in layers of at
// most γ·D down to the step's depth, the tool ramps down along the first
// pass (back and forth on it, paths/entry.h) and then follows the passes in
// the order they were drawn, straight from each point to the next; between
// layers it lifts and returns to the start above the floor it cut.
#include "modules/area/area.h"

#include "paths/entry.h"
#include "paths/path_builder.h"

#include <cmath>
#include <stdexcept>

namespace taiwa {

using namespace paths;  // the shared path builders

ToolPath areaClearingPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const auto& points = step.payload.as<DrawnPoints>().points;
    if (points.size() < 2) throw std::logic_error("an area clearing step without a pass");
    if (!(tech.gamma > 0.0) || !(tool.diameter > 0.0)) throw std::logic_error("gamma and the diameter must be positive");
    const double T = millingOf(step).cutDepth;
    const int layers = std::max(1, static_cast<int>(std::ceil(T / (tech.gamma * tool.diameter) - 1e-9)));
    PathBuilder b({points.front().x, points.front().y, p.safeZ});
    double floor = 0.0;  // the depth cut so far at the start point
    for (int k = 1; k <= layers; ++k) {
        const double z = -T * k / layers;
        b.rapid({points.front().x, points.front().y, -floor + p.clearance});
        // Down and back along the start of the first pass: half the ramp's
        // length each way (no shorter than the tool is wide), so that it ends
        // at the start point at depth, the pass then cutting what it sloped.
        const double ramp = (z + floor - p.clearance) / -tanDeg(p.rampAngle);
        const Point2 along = points[1] - points.front();
        const double leg = std::min(length(along), std::max(0.5 * ramp, tool.diameter));
        const Point2 other = points.front() + (leg / length(along)) * along;
        appendEntry(b, Entry{Entry::Kind::LinearRamp, points.front(), 0.0, other}, z, p.rampAngle, p.climb);
        for (std::size_t i = 1; i < points.size(); ++i) b.feed({points[i].x, points[i].y, z});
        b.rapid({points.back().x, points.back().y, p.safeZ});
        if (k < layers) b.rapid({points.front().x, points.front().y, p.safeZ});
        floor = -z;
    }
    return b.take();
}

}  // namespace taiwa
