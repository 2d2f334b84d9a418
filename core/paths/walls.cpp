// Wall finishing, inclined-face finishing and drilling tool paths.
#include "paths/walls.h"

#include "paths/contour.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa::paths {

namespace {

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }
Point2 leftOf(Point2 d) { return {-d.y, d.x}; }

// Length of the straight part of side 0 of a centre contour.
double firstSideLength(const Quad& centre)
{
    const Quad core = offsetInward(Quad{counterClockwise(centre.corners), centre.cornerRadius}, centre.cornerRadius);
    return distance(core.corners[0], core.corners[1]);
}

// One incision: lead-in arc, the closed contour, lead-out arc. The lead arcs
// are quarter circles tangent to the contour at the middle of its first
// side, on the pocket's side of it.
void incision(PathBuilder& b, const Quad& centre, double z, bool ccw, double lead, double approachZ)
{
    const ContourStart s = contourStart(centre, ccw);
    // The pocket lies left of the travel direction when counter-clockwise.
    const Point2 inward = ccw ? leftOf(s.direction) : -1.0 * leftOf(s.direction);
    const Point2 cIn = s.point + lead * inward;
    const Point2 from = cIn - lead * s.direction;
    const Point2 to = cIn + lead * s.direction;  // lead-out centre equals lead-in centre
    if (b.at().z > approachZ) {
        b.rapid(at(from, b.at().z));
        b.rapid(at(from, approachZ));
    } else {
        b.feed(at(from, b.at().z));
    }
    b.feed(at(from, z), FeedKind::Plunge);
    if (lead > 0) b.arc(ccw, at(s.point, z), cIn);
    else b.feed(at(s.point, z));
    appendContour(b, centre, z, ccw);
    if (lead > 0) b.arc(ccw, at(to, z), cIn);
}

}  // namespace

ToolPath wallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    if (!step.outline) throw std::logic_error("wall step without an outline");
    const double R = tool.radius();
    const double t = step.wallTaper > 0 ? tanDeg(step.wallTaper) : 0.0;
    // Incision depths: one at full depth, or even steps of at most gamma x D.
    std::vector<double> depths{step.cutDepth};
    if (step.multiIncision) {
        const double range = step.cutDepth - step.startDepth;
        const int n = std::max(1, static_cast<int>(std::ceil(range / (tech.gamma * tool.diameter) - 1e-9)));
        depths.clear();
        for (int k = 1; k <= n; ++k) depths.push_back(step.startDepth + range * k / n);
    }
    // For a tapered wall the outline is the top one; the tool tip runs where
    // its flank touches the whole wall: offset R + depth * tan(taper).
    const Quad first = centreQuad(*step.outline, R + depths.front() * t);
    const double room = std::max(0.0, maxOffset(*step.outline) - R - step.cutDepth * t);
    const double lead = std::max(0.0, std::min({p.leadRadius > 0 ? p.leadRadius : R, 0.45 * room,
                                                0.45 * firstSideLength(first)}));
    const ContourStart s0 = contourStart(first, p.climb);
    PathBuilder b({s0.point.x, s0.point.y, p.safeZ});
    for (const double d : depths) incision(b, centreQuad(*step.outline, R + d * t), -d, p.climb, lead, -step.startDepth + p.clearance);
    b.rapid(at({b.at().x, b.at().y}, p.safeZ));
    return b.take();
}

ToolPath inclinedFace(const Step& step, const Tool& tool, const PathParameters& p)
{
    if (!step.face) throw std::logic_error("inclined-face step without its face");
    const InclinedFace& f = *step.face;
    const double R = tool.radius(), T = step.cutDepth;
    const double theta = f.angle * std::numbers::pi / 180.0;
    const Point2 along = (1.0 / distance(f.topEdge[0], f.topEdge[1])) * (f.topEdge[1] - f.topEdge[0]);
    Point2 down = f.floorEdge[0] - f.topEdge[0];
    down = down - dot(down, along) * along;  // horizontal, across the face toward the floor
    const double run = length(down);          // T tan(theta)
    const Point2 downUnit = run > 0 ? (1.0 / run) * down : leftOf(along);
    // The ball centre sits R off the face along its normal (into the pocket).
    const Point2 nXY = std::cos(theta) * downUnit;
    const double nZ = std::sin(theta);
    // The passes stop short of the vertical end walls by the larger of the
    // tool and corner radius (the outline carries the corner radius).
    const double corner = step.outline ? step.outline->cornerRadius : 0.0;
    const double margin = std::max(R, corner);
    const double len = distance(f.topEdge[0], f.topEdge[1]);
    if (len <= 2 * margin) throw std::logic_error("inclined face shorter than the ball end mill");
    // Contact points from the top edge (t = 0) down to where the tip reaches -T.
    const double h = std::min(step.scallop, R);
    const double stepOver = 2 * std::sqrt(2 * R * h - h * h);
    const double tMax = std::max(0.0, (T - R * (1 - nZ)) / T);
    const double slope = tMax * T / std::cos(theta);
    const int n = std::max(1, static_cast<int>(std::ceil(slope / stepOver - 1e-9)));
    auto ballTip = [&](double t, double s) {
        const Point2 xy = f.topEdge[0] + (t * run) * downUnit + s * along + R * nXY;
        return Point3{xy.x, xy.y, -t * T + R * nZ - R};
    };
    const Point3 first = ballTip(0, margin);
    PathBuilder b({first.x, first.y, p.safeZ});
    b.rapid({first.x, first.y, p.clearance});
    for (int k = 0; k <= n; ++k) {
        const double t = tMax * k / n;
        const bool forward = k % 2 == 0;
        const Point3 a = ballTip(t, forward ? margin : len - margin), e = ballTip(t, forward ? len - margin : margin);
        b.feed(a, k == 0 ? FeedKind::Plunge : FeedKind::Cut);
        b.feed(e);
    }
    b.rapid({b.at().x, b.at().y, p.safeZ});
    return b.take();
}

ToolPath pilotHole(const Step& step, const Tool& tool, const PathParameters& p)
{
    PathBuilder b({step.position.x, step.position.y, p.safeZ});
    Move m{MoveKind::DrillCycle, {step.position.x, step.position.y, -step.cutDepth}};
    m.retractZ = p.clearance;
    m.peck = step.cutDepth > p.peckWhenDeeperThan * tool.diameter ? p.peckDepth * tool.diameter : 0.0;
    b.add(m);
    return b.take();
}

}  // namespace taiwa::paths
