// Tool path of a face-milling step (module FACE): parallel passes across the
// face at the step's angle, at the step's depth. The first and last passes
// keep the tool's centre inside the face and its flat bottom 0.1 D beyond
// the sides; between them the passes lie at most stepOver·D apart. Each pass
// starts and ends with the whole tool R + clearance beyond the face, so the
// tool only goes down beside the stock and enters sideways (a face mill
// cannot plunge). Zigzag: the next pass is reached at depth beside the face;
// one way: the tool lifts above the top and comes back by rapid, every pass
// climb. docs/face-milling.md.
#include "modules/face/face.h"

#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa::face {

using namespace paths;  // the shared path builders

namespace {

constexpr double kOverhang = 0.1;  // the flat bottom beyond each side of the face [× D]

// A point in the passes' frame: u along the passes, v across them.
struct Frame {
    Point2 u, v;
    Point2 to(Point2 p) const { return {dot(p, u), dot(p, v)}; }
    Point2 from(double a, double b) const { return a * u + b * v; }
};

// The u extent of the face within the band lo <= v <= hi (the face in the
// passes' frame, convex): its corners and where its sides cross the band's
// edges.
std::pair<double, double> bandExtent(const std::array<Point2, 4>& q, double lo, double hi)
{
    double uMin = 1e300, uMax = -1e300;
    const auto take = [&](double u) { uMin = std::min(uMin, u), uMax = std::max(uMax, u); };
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 a = q[i], b = q[(i + 1) % 4];
        if (a.y >= lo && a.y <= hi) take(a.x);
        for (const double edge : {lo, hi})
            if ((a.y - edge) * (b.y - edge) < 0.0) take(a.x + (b.x - a.x) * (edge - a.y) / (b.y - a.y));
    }
    return {uMin, uMax};
}

// The passes' v, in the order cut: from the side where climb milling starts
// (the uncut face on the right of a pass along +u: from the high v down).
std::vector<double> passPositions(double vMin, double vMax, double flatRadius, double overhang, double pitch, bool climb)
{
    const double inset = flatRadius - overhang;  // the first and last centres from the sides
    const double width = vMax - vMin;
    std::vector<double> v;
    if (width <= 2 * inset) {
        v.push_back(0.5 * (vMin + vMax));
    } else {
        const int gaps = static_cast<int>(std::ceil((width - 2 * inset) / pitch - 1e-9));
        for (int k = 0; k <= gaps; ++k) v.push_back(vMin + inset + (width - 2 * inset) * k / gaps);
    }
    if (climb) std::reverse(v.begin(), v.end());
    return v;
}

}  // namespace

ToolPath millingPath(const Step& step, const Tool& tool, const TechnologyData&, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    if (!g.outline) throw std::logic_error("face-milling step without a face");
    const double D = tool.diameter, R = tool.radius();
    const double flat = R - std::max(tool.cornerRadius, 0.0);
    const double overhang = kOverhang * D;
    if (!(flat > overhang)) throw std::logic_error("face-milling tool without a flat bottom");
    // A corner radius narrows the flat bottom: the passes closer, so that the
    // flat bottoms of neighbours overlap (no change for a sharp-cornered tool).
    const double pitch = std::min(g.stepOver.value_or(0.75) * D, 1.8 * flat);
    if (!(pitch > 0.0)) throw std::logic_error("face-milling step-over must be positive");
    if (!(g.cutDepth > g.startDepth)) throw std::logic_error("face-milling layer without depth");

    const FacePasses& passes = step.payload.as<FacePasses>();
    const double a = passes.angle * std::numbers::pi / 180.0;
    const Frame f{{std::cos(a), std::sin(a)}, {-std::sin(a), std::cos(a)}};
    std::array<Point2, 4> q{};
    double vMin = 1e300, vMax = -1e300;
    for (std::size_t i = 0; i < 4; ++i) {
        q[i] = f.to(g.outline->corners[i]);
        vMin = std::min(vMin, q[i].y), vMax = std::max(vMax, q[i].y);
    }
    const std::vector<double> vs = passPositions(vMin, vMax, flat, overhang, pitch, p.climb);
    // Each pass from u0 to u1 with the whole tool R + clearance beyond the face.
    const double beyond = R + p.clearance;
    std::vector<std::pair<double, double>> spans;
    for (const double v : vs) {
        const auto [lo, hi] = bandExtent(q, v - R, v + R);
        spans.emplace_back(lo - beyond, hi + beyond);
    }
    // Zigzag: a link beside the face reaches as far out as both passes it
    // joins need (the tool over the band of either is outside the face).
    if (passes.zigzag)
        for (std::size_t k = 0; k + 1 < spans.size(); ++k) {
            auto& [a0, a1] = spans[k];
            auto& [b0, b1] = spans[k + 1];
            if (k % 2 == 0) a1 = b1 = std::max(a1, b1);  // pass k along +u, the next back along -u
            else a0 = b0 = std::min(a0, b0);
        }

    const double z = -g.cutDepth;
    const double down = -g.startDepth + p.clearance;  // rapid to here beside the face, then feed down
    const double above = std::max(down, p.clearance);    // one way: back above the stock's top
    const auto at = [&](double u, double v, double h) {
        const Point2 xy = f.from(u, v);
        return Point3{xy.x, xy.y, h};
    };
    const auto passStart = [&](std::size_t k) {
        const bool forward = !passes.zigzag || k % 2 == 0;
        return forward ? spans[k].first : spans[k].second;
    };
    const auto passEnd = [&](std::size_t k) {
        const bool forward = !passes.zigzag || k % 2 == 0;
        return forward ? spans[k].second : spans[k].first;
    };

    PathBuilder b(at(passStart(0), vs[0], p.safeZ));
    for (std::size_t k = 0; k < vs.size(); ++k) {
        if (k == 0 || !passes.zigzag) {
            if (k > 0) {
                b.rapid(at(passEnd(k - 1), vs[k - 1], above));
                b.rapid(at(passStart(k), vs[k], above));
            }
            b.rapid(at(passStart(k), vs[k], down));
            b.feed(at(passStart(k), vs[k], z), FeedKind::Plunge);
        } else {
            b.feed(at(passStart(k), vs[k], z));  // the link beside the face
        }
        b.feed(at(passEnd(k), vs[k], z));
    }
    b.rapid(at(passEnd(vs.size() - 1), vs.back(), p.safeZ));
    return b.take();
}

}  // namespace taiwa::face
