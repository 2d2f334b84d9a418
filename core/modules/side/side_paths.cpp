// Tool path of side milling (module SIDE): for each Z layer (roughing: at
// most γ·D deep; finishing: full depth or F2's incisions) and each radial
// pass of the step (the tool edge `o` from the contour, outermost first),
// the tool centre runs the exact offset of the contour by R + o on the
// tool's side (paths/contour_offset.h: lines and arcs, G1/G2/G3), in the
// direction the step travels. Rapids stay at the safe height; the tool
// goes down at the feed beside the part:
//  - an open contour is entered and left along the tangents of its first
//    and last elements, R + clearance beyond its ends;
//  - a closed contour's loop starts at the middle of its longest piece and
//    is entered and left on quarter circles from the tool's side whose
//    start lies a pass's spacing beyond the outermost pass (W + R +
//    clearance out for the first roughing pass), made smaller when the
//    contour bends back towards it.
#include "modules/side/side.h"

#include "paths/contour_offset.h"
#include "paths/generators.h"
#include "paths/loop_lead.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa::side {

using namespace paths;  // the shared path builders

namespace {

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }
Point2 leftOf(Point2 d) { return {-d.y, d.x}; }

// The loop started at the middle of its longest piece (lines first); a
// full circle where it starts.
Contour fromMiddle(const Contour& loop)
{
    const std::size_t k = longestPiece(loop);
    const ContourSegment& s = loop.segments[k];
    return s.isArc() && s.start == s.end ? loop : startedAtMiddle(loop, k);
}

}  // namespace

ToolPath millingPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const SidePasses& run = step.payload.as<SidePasses>();
    if (run.contour.empty()) throw std::logic_error("side milling step without a contour");
    if (run.offsets.empty()) throw std::logic_error("side milling step without passes");
    const Contour& contour = run.contour;
    const double R = tool.radius();
    const bool left = run.toolOnLeft;
    const std::vector<double> depths = incisionDepths(step, tool, tech);
    // The spacing of the step's passes: beyond the outermost lies what the
    // unit clears (W) or air; a single pass takes at most the tool's width.
    const double outermost = run.offsets.front();
    const double spacing = run.offsets.size() > 1 ? run.offsets[0] - run.offsets[1]
                          : run.offsets.front() > 0.0 ? 2 * R : R;

    // The chains of each pass, made once for all layers.
    std::vector<std::vector<Contour>> passes;
    for (const double o : run.offsets) {
        auto chains = offsetSide(contour, left, R + o);
        if (!chains) throw std::logic_error("side milling offset failed: " + chains.error());
        if (chains->empty()) throw std::logic_error("the tool does not fit beside the contour");
        passes.push_back(std::move(*chains));
    }

    const double approachZ = -millingOf(step).startDepth + p.clearance;
    std::optional<PathBuilder> b;
    const auto enter = [&](Point2 from, double z) {
        if (!b) b.emplace(at(from, p.safeZ));
        b->rapid(at({b->at().x, b->at().y}, p.safeZ));
        b->rapid(at(from, p.safeZ));
        b->rapid(at(from, approachZ));
        b->feed(at(from, z), FeedKind::Plunge);
    };
    for (const double depth : depths) {
        for (std::size_t k = 0; k < passes.size(); ++k) {
            const double o = run.offsets[k];
            for (const Contour& raw : passes[k]) {
                if (raw.segments.empty()) continue;
                const double z = -depth;
                if (!contour.closed) {
                    // Along the end tangents, R + clearance beyond the ends.
                    const Point2 d0 = raw.segments.front().startDirection(), d1 = raw.segments.back().endDirection();
                    const Point2 from = raw.start() - (R + p.clearance) * d0, to = raw.end() + (R + p.clearance) * d1;
                    enter(from, z);
                    b->feed(at(raw.start(), z));
                    appendPieces(*b, raw, z);
                    b->feed(at(to, z));
                    b->rapid(at(to, p.safeZ));
                    continue;
                }
                const Contour loop = fromMiddle(raw);
                const Point2 start = loop.start(), dir = loop.segments.front().startDirection();
                const Point2 out = left ? leftOf(dir) : -1.0 * leftOf(dir);  // towards the tool's side
                // The lead circle: its start a spacing beyond the outermost
                // pass, at most as large as keeps its centre R + o + lead
                // from the contour.
                const double wanted = (outermost - o) + spacing + p.clearance;
                const double lead = largestLead(
                    wanted, [&](double l) { return distanceTo(contour, start + l * out) >= R + o + l - 1e-9; });
                const Point2 c = start + lead * out;
                const Point2 from = c - lead * dir, to = c + lead * dir;
                // Round the circle onto the loop: counter-clockwise with the
                // tool on the left of the travel, clockwise on the right.
                enter(from, z);
                if (lead > 0) b->arc(left, at(start, z), c);
                appendPieces(*b, loop, z);
                if (lead > 0) b->arc(left, at(to, z), c);
                b->rapid(at(to, p.safeZ));
            }
        }
    }
    if (!b) throw std::logic_error("side milling step without a pass");
    return b->take();
}

}  // namespace taiwa::side
