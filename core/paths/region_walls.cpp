// Wall finishing of a pocket of any outline with islands (contour units):
// the exact tool-centre loops of the outline and of every island
// (paths/region_offset.h: lines stay lines, arcs stay arcs on the tape), one
// or several Z incisions each, entered and left on a quarter circle tangent
// to the wall at the middle of the loop's longest piece.
#include "paths/generators.h"

#include "paths/loop_lead.h"
#include "paths/region_offset.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa::paths {

namespace {

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }
Point2 leftOf(Point2 d) { return {-d.y, d.x}; }

}  // namespace

ToolPath regionWallFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    if (!g.region) throw std::logic_error("contour wall step without a region");
    const double R = tool.radius();
    const double d = R + g.wallAllowance;
    const Region region = normalised(*g.region);
    auto pieces = offsetRegion(region, d);
    if (!pieces) throw std::logic_error("contour wall offset failed: " + pieces.error());
    if (pieces->empty()) throw std::logic_error("the tool does not fit into the contour region");

    const std::vector<double> depths = incisionDepths(step, tool, tech);

    // Loops are run with the material on the right (climb milling with M3),
    // or reversed; the cleared side is then on the left, or on the right.
    const RegionDistance distanceTo(region);
    const double wanted = p.leadRadius > 0 ? p.leadRadius : R;
    const double approachZ = -g.startDepth + p.clearance;
    std::optional<PathBuilder> b;
    for (Contour loop : loopsOf(*pieces)) {
        if (loop.segments.empty()) continue;
        if (!p.climb) loop = reversed(loop);
        loop = startedAtMiddle(loop, longestPiece(loop));
        const Point2 start = loop.start(), dir = loop.segments.front().startDirection();
        const Point2 inward = p.climb ? leftOf(dir) : -1.0 * leftOf(dir);
        // The largest lead circle, at most `wanted`, that stays where the
        // tool centre may go: its centre at least its radius inside that.
        const double lead =
            largestLead(wanted, [&](double l) { return distanceTo(start + l * inward) <= -(d + l) + 1e-9; });
        const Point2 c = start + lead * inward;
        const Point2 from = c - lead * dir, to = c + lead * dir;
        if (!b) b.emplace(at(from, p.safeZ));
        b->rapid(at({b->at().x, b->at().y}, p.safeZ));
        b->rapid(at(from, p.safeZ));
        b->rapid(at(from, approachZ));
        for (const double depth : depths) {
            b->feed(at(from, b->at().z));  // after an incision: back across the lead circle
            b->feed(at(from, -depth), FeedKind::Plunge);
            if (lead > 0) b->arc(p.climb, at(start, -depth), c);
            appendPieces(*b, loop, -depth);
            if (lead > 0) b->arc(p.climb, at(to, -depth), c);
        }
    }
    if (!b) throw std::logic_error("contour wall step without a loop");
    b->rapid(at({b->at().x, b->at().y}, p.safeZ));
    return b->take();
}

}  // namespace taiwa::paths
