// Inclined-face finishing of module M2D (inclined_face.h): a ball end mill in
// passes parallel to the face's top edge, stepping down the slope by the
// step-over that leaves the set scallop height, alternating direction
// (zig-zag); and the moves that makes, estimated before.
#include "modules/inclined_face.h"

#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace taiwa {

using paths::PathBuilder;

ToolPath inclinedFacePath(const Step& step, const Tool& tool, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    const InclinedFace* face = step.payload.getIf<InclinedFace>();
    if (!face)
        throw std::logic_error("inclined-face step without its face (it holds " + std::string(step.payload.name()) + ")");
    if (tool.type != ToolType::BallEndMill) throw std::logic_error("inclined faces are finished with a ball end mill");
    const InclinedFace& f = *face;
    const double R = tool.radius(), T = g.cutDepth;
    const double theta = f.angle * std::numbers::pi / 180.0;
    const double len = distance(f.topEdge[0], f.topEdge[1]);
    const Point2 along = (1.0 / len) * (f.topEdge[1] - f.topEdge[0]);
    Point2 down = f.floorEdge[0] - f.topEdge[0];
    down = down - dot(down, along) * along;  // horizontal, across the face toward the floor
    const double run = length(down);          // T tan(theta)
    if (!(run > 0.0)) throw std::logic_error("inclined face without slope");
    const Point2 downUnit = (1.0 / run) * down;
    // Unit normal of the face, pointing into the pocket: horizontal part
    // cos(theta) toward the floor, vertical part sin(theta) upward. The ball
    // centre sits R off the face along it; the tip is R below the centre.
    const Point2 nXY = std::cos(theta) * downUnit;
    const double nZ = std::sin(theta);
    // Passes stop short of the vertical end walls by the larger of the ball
    // radius and their corner radius (the outline carries r1), so the ball
    // touches the face only where it is plane.
    const double corner = g.outline ? g.outline->cornerRadius : 0.0;
    const double margin = std::max(R, corner);
    if (len <= 2 * margin) throw std::logic_error("inclined face shorter than the ball end mill");
    // Contact points from the top edge (u = 0) down to where the tip reaches
    // the floor, at most one scallop step-over apart along the slope.
    if (!(f.scallop > 0.0)) throw std::logic_error("inclined face without a scallop height");
    const double h = std::min(f.scallop, R);
    const double stepOver = 2 * std::sqrt(2 * R * h - h * h);
    const double uMax = std::max(0.0, (T - R * (1 - nZ)) / T);
    const double slope = uMax * T / std::cos(theta);
    const int n = std::max(1, static_cast<int>(std::ceil(slope / stepOver - 1e-9)));
    const auto tip = [&](double u, double s) {
        const Point2 xy = f.topEdge[0] + (u * run) * downUnit + s * along + R * nXY;
        return Point3{xy.x, xy.y, -u * T + R * nZ - R};
    };
    const Point3 first = tip(0, margin);
    PathBuilder b({first.x, first.y, p.safeZ});
    b.rapid({first.x, first.y, -g.startDepth + p.clearance});
    // Links between passes run down the slope at the pass end, the ball
    // centre staying R off the face.
    for (int k = 0; k <= n; ++k) {
        const double u = uMax * k / n;
        const bool forward = k % 2 == 0;
        b.feed(tip(u, forward ? margin : len - margin), k == 0 ? FeedKind::Plunge : FeedKind::Cut);
        b.feed(tip(u, forward ? len - margin : margin));
    }
    b.rapid({b.at().x, b.at().y, p.safeZ});
    return b.take();
}

double inclinedFaceMoves(const Step& step, const Tool& tool)
{
    const InclinedFace* f = step.payload.getIf<InclinedFace>();
    if (!f) return 10;
    const double R = std::max(tool.diameter, 1e-3) / 2, h = std::clamp(f->scallop, 1e-6, R);
    const double stepOver = 2 * std::sqrt(2 * R * h - h * h);
    const double span = distance(f->topEdge[0], f->floorEdge[0]) + millingOf(step).cutDepth;
    return (std::ceil(span / std::max(stepOver, 1e-6)) + 1) * 4;
}

}  // namespace taiwa
