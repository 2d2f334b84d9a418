// Pocket clearing: the rings of one layer, the layers of a step, the entry.
#include "paths/pocket.h"

#include "paths/contour.h"
#include "paths/coverage.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa::paths {

namespace {

// Offsets (from the step outline) of the centre rings, innermost first:
// the outermost is exactly the tool radius, the others step in by the
// step-over until the outline collapses.
std::vector<double> ringOffsets(const Quad& outline, double radius, double stepOver)
{
    const double deepest = maxOffset(outline) - 1e-4;
    std::vector<double> d{radius};
    while (d.back() + stepOver < deepest) d.push_back(d.back() + stepOver);
    if (deepest > d.back() + 1e-3) d.push_back(deepest);
    std::reverse(d.begin(), d.end());
    return d;
}

// Equal layers of at most maxDepth from start to end depth (positive).
std::vector<double> layerDepths(double start, double end, double maxDepth)
{
    const int n = std::max(1, static_cast<int>(std::ceil((end - start) / maxDepth - 1e-9)));
    std::vector<double> z;
    for (int k = 1; k <= n; ++k) z.push_back(start + (end - start) * k / n);
    return z;
}

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }

// One layer's rings at height z, the builder being at the entry point; then
// the cleanup points. Rings are linked by straight feeds (the centre region
// is convex, so a straight link never leaves it).
void appendRings(PathBuilder& b, const Quad& outline, const std::vector<double>& offsets,
                 const std::vector<Point2>& cleanup, double z, bool ccw)
{
    for (const double d : offsets) {
        const Quad centre = centreQuad(outline, d);
        b.feed(at(contourStart(centre, ccw).point, z));
        appendContour(b, centre, z, ccw);
    }
    for (const auto& c : cleanup) b.feed(at(c, z));
}

// A helical ramp around `centre` from the current height down to z.
void helix(PathBuilder& b, Point2 centre, double radius, double z, double angleDeg)
{
    const double perTurn = 2 * std::numbers::pi * radius * std::tan(angleDeg * std::numbers::pi / 180.0);
    const Point2 a{centre.x + radius, centre.y}, o{centre.x - radius, centre.y};
    b.feed(at(a, b.at().z), FeedKind::Ramp);
    double zNow = b.at().z;
    while (zNow > z + 1e-9) {
        const double half = std::max(z, zNow - perTurn / 2);
        b.arc(true, at(o, half), centre, FeedKind::Ramp);
        zNow = half;
        const double full = std::max(z, zNow - perTurn / 2);
        b.arc(true, at(a, full), centre, FeedKind::Ramp);
        zNow = full;
    }
    // One full turn at depth clears the helix's core.
    b.arc(true, at(o, z), centre, FeedKind::Cut);
    b.arc(true, at(a, z), centre, FeedKind::Cut);
    b.feed(at(centre, z));
}

struct Entry {
    Point2 point;
    bool pilotHole = false;
    double helixRadius = 0.0;
};

Entry entryFor(const Step& step, const Quad& outline, double radius)
{
    Entry e;
    if (step.holeDiameter > 0 && step.kind == StepKind::Roughing) {
        e.point = step.position;
        e.pilotHole = true;
        return e;
    }
    // The centre of the largest circle inside the allowed region: the middle
    // of the innermost offset.
    const Quad inner = centreQuad(outline, maxOffset(outline) - 1e-4);
    e.point = centroid(inner.corners);
    const double room = std::max(0.0, maxOffset(outline) - radius);
    e.helixRadius = std::clamp(std::min(0.5 * radius, room * 0.9), 0.0, radius);
    return e;
}

void enter(PathBuilder& b, const Entry& e, double z, double angle)
{
    if (e.pilotHole || e.helixRadius < 0.05) {
        b.feed(at(e.point, b.at().z));
        b.feed(at(e.point, z), FeedKind::Plunge);
    } else {
        b.feed(at(e.point, b.at().z));
        helix(b, e.point, e.helixRadius, z, angle);
    }
}

ToolPath clear(const Step& step, const Tool& tool, const std::vector<double>& depths, double stepOver,
               const PathParameters& p)
{
    if (!step.outline) throw std::logic_error("pocket step without an outline");
    const Quad& outline = *step.outline;
    const double R = tool.radius();
    if (outline.cornerRadius < R - 1e-9 && outline.cornerRadius > 0)
        throw std::logic_error("pocket corner radius smaller than the tool radius");
    const Entry e = entryFor(step, outline, R);
    const auto offsets = ringOffsets(outline, R, stepOver);

    // Prove the layer is cleared and find what the rings leave.
    std::vector<Point2> cleanup;
    for (int round = 0; round < 3; ++round) {
        PathBuilder probe({e.point.x, e.point.y, 0});
        if (!e.pilotHole && e.helixRadius >= 0.05) helix(probe, e.point, e.helixRadius, 0, p.rampAngle);
        appendRings(probe, outline, offsets, cleanup, 0, p.climb);
        const auto more = cleanupPoints(outline, centreQuad(outline, R), probe.take(), R);
        if (more.empty()) break;
        cleanup.insert(cleanup.end(), more.begin(), more.end());
    }

    PathBuilder b({e.point.x, e.point.y, p.safeZ});
    b.rapid(at(e.point, -step.startDepth + p.clearance));
    for (const double d : depths) {
        enter(b, e, -d, p.rampAngle);
        appendRings(b, outline, offsets, cleanup, -d, p.climb);
    }
    b.rapid(at({b.at().x, b.at().y}, p.safeZ));
    return b.take();
}

}  // namespace

ToolPath pocketRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const auto depths = layerDepths(step.startDepth, step.cutDepth, tech.gamma * tool.diameter);
    return clear(step, tool, depths, p.stepOver * tool.diameter, p);
}

ToolPath floorFinishing(const Step& step, const Tool& tool, const PathParameters& p)
{
    return clear(step, tool, {step.cutDepth}, p.stepOver * tool.diameter, p);
}

}  // namespace taiwa::paths
