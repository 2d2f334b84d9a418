// Wall finishing: the tool-centre contour of the outline (vertical walls) or
// of the floor cross-section (tapered walls), one or several Z incisions,
// each entered and left on a quarter-circle arc tangent to the wall.
#include "paths/generators.h"

#include "paths/contour.h"
#include "paths/loop_lead.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa::paths {

namespace {

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }
Point2 leftOf(Point2 d) { return {-d.y, d.x}; }

// Largest lead radius, at most `wanted`, whose whole circle (tangent to the
// contour at its start, on the pocket's side) stays in the centre region.
double leadRadius(const Quad& centre, bool ccw, double wanted)
{
    const ContourStart s = contourStart(centre, ccw);
    const Point2 inward = ccw ? leftOf(s.direction) : -1.0 * leftOf(s.direction);
    return largestLead(wanted, [&](double l) { return signedDistance(centre, s.point + l * inward) <= -l + 1e-9; });
}

// One incision at depth z: approach above the lead-in start, plunge there
// (inside the cleared pocket), lead-in arc, the closed contour, lead-out arc.
// Lead-in and lead-out share one centre: quarter circles ending and starting
// tangentially at the middle of the contour's first side.
void incision(PathBuilder& b, const Quad& centre, double z, bool ccw, double wantedLead, double approachZ)
{
    const ContourStart s = contourStart(centre, ccw);
    const Point2 inward = ccw ? leftOf(s.direction) : -1.0 * leftOf(s.direction);
    const double lead = leadRadius(centre, ccw, wantedLead);
    const Point2 c = s.point + lead * inward;
    const Point2 from = c - lead * s.direction, to = c + lead * s.direction;
    if (b.at().z > approachZ) {
        b.rapid(at(from, b.at().z));
        b.rapid(at(from, approachZ));
    } else {
        b.feed(at(from, b.at().z));  // at the last incision's depth, inside the pocket
    }
    b.feed(at(from, z), FeedKind::Plunge);
    if (lead > 0) b.arc(ccw, at(s.point, z), c);
    appendContour(b, centre, z, ccw);
    if (lead > 0) b.arc(ccw, at(to, z), c);
}

}  // namespace

std::vector<double> incisionDepths(const Step& step, const Tool& tool, const TechnologyData& tech)
{
    const MillingGeometry& g = millingOf(step);
    // One at full depth, or equal steps of at most gamma x D.
    std::vector<double> depths{g.cutDepth};
    if (!g.multiIncision) return depths;
    if (!(tech.gamma > 0.0)) throw std::logic_error("gamma must be positive");
    const double range = g.cutDepth - g.startDepth;
    const int n = std::max(1, static_cast<int>(std::ceil(range / (tech.gamma * tool.diameter) - 1e-9)));
    depths.clear();
    for (int k = 1; k < n; ++k) depths.push_back(g.startDepth + range * k / n);
    depths.push_back(g.cutDepth);
    return depths;
}

ToolPath wallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    if (!g.outline) throw std::logic_error("wall step without an outline");
    const double R = tool.radius();
    // A tool within the fit tolerance of a vertical wall's corner radius runs
    // it as its own.
    const Quad outline{counterClockwise(g.outline->corners),
                       g.wallTaper == 0.0 ? std::max(g.outline->cornerRadius, R) : g.outline->cornerRadius};
    const double t = g.wallTaper > 0 ? tanDeg(g.wallTaper) : 0.0;
    // A flank steeper than the wall would cut into it above the tip.
    const double flank = tool.type == ToolType::TaperEndMill ? tool.taperAngle : 0.0;
    if (flank > g.wallTaper + 1e-9) throw std::logic_error("tool flank steeper than the wall");
    if (g.wallTaper == 0.0 && !fitsInto(R, g.outline->cornerRadius))
        throw std::logic_error("wall corner radius smaller than the tool radius");
    if (!offsetExists(outline, R + g.cutDepth * t)) throw std::logic_error("pocket narrower than the tool");

    const std::vector<double> depths = incisionDepths(step, tool, tech);
    // The tip runs on the wall's cross-section at its own depth d moved in
    // by R (vertical walls: the outline itself); for a tapered wall that is
    // the top outline moved in by R + d tan(S), and the flank of a taper end
    // mill of the wall's angle then touches the wall over its whole height.
    const double wantedLead = p.leadRadius > 0 ? p.leadRadius : R;
    const ContourStart s0 = contourStart(centreQuad(outline, R + depths.front() * t), p.climb);
    PathBuilder b({s0.point.x, s0.point.y, p.safeZ});
    for (const double d : depths)
        incision(b, centreQuad(outline, R + d * t), -d, p.climb, wantedLead, -g.startDepth + p.clearance);
    b.rapid(at({b.at().x, b.at().y}, p.safeZ));
    return b.take();
}

}  // namespace taiwa::paths
