// Geometry oracle for the tests: finished pocket solids and tool gouge depth.
#include "support/pocket_geometry.h"

#include "modules/area/area.h"
#include "modules/cp/cp.h"
#include "modules/face/face.h"
#include "support/face_oracle.h"
#include "modules/m2d/m2d.h"
#include "modules/holes/holes.h"
#include "modules/m4/m4.h"
#include "support/side_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

namespace taiwa::test {

namespace {

// Signed distance to a sharp convex polygon (counter-clockwise).
double signedDistanceSharp(const std::array<Point2, 4>& pIn, Point2 c)
{
    const auto p = counterClockwise(pIn);
    bool inside = true;
    double inner = std::numeric_limits<double>::infinity(), outer = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 a = p[i], b = p[(i + 1) % 4];
        const Point2 ab = b - a;
        const double len = length(ab);
        const double side = cross(ab, c - a) / len;  // > 0 left = inside
        if (side < 0) inside = false;
        inner = std::min(inner, side);
        const double t = std::clamp(dot(c - a, ab) / (len * len), 0.0, 1.0);
        outer = std::min(outer, distance(c, a + t * ab));
    }
    return inside ? -inner : outer;
}
}  // namespace

Quad pocketSection(const ModuleInput& m, double depth)
{
    if (const auto* m4 = (m).getIf<M4Pocket>()) {
        const Quad top{counterClockwise(m4->corners), m4->cornerRadius};
        if (m4->taper == 0.0) return top;
        // The wall leans inward: the section shrinks by depth * tan(S); the
        // rounded corners shrink with it, no smaller than zero.
        Quad q = offsetInward(top, depth * tanDeg(m4->taper));
        q.cornerRadius = std::max(q.cornerRadius, 0.0);
        return q;
    }
    return m2dCrossSection((m).as<M2DPocket>(), depth);
}

double pocketDepth(const ModuleInput& m)
{
    if (const auto* f = m.getIf<FaceUnit>()) return faceDepth(*f);
    if (const auto t = sideDepth(m)) return *t;
    if (const auto* h = m.getIf<HolePattern>()) return h->depth;
    if (const auto* cp = m.getIf<ContourPocket>()) return cp->depth;
    if (const auto* a = m.getIf<AreaClearing>()) return a->depth;
    if (const auto* m4 = m.getIf<M4Pocket>()) return m4->depth;
    return m.as<M2DPocket>().depth;
}

double toolRadiusAt(const Tool& tool, double h)
{
    const double r = tool.radius();
    switch (tool.type) {
    case ToolType::BallEndMill: return h >= r ? r : std::sqrt(std::max(0.0, r * r - (r - h) * (r - h)));
    case ToolType::TaperEndMill: return r + h * tanDeg(tool.taperAngle);
    case ToolType::Drill:
    case ToolType::CentreDrill: return std::min(r, h * tanDeg(90.0 - tool.pointAngle / 2.0));
    default: return r;
    }
}

double signedDistance(const Quad& q, Point2 p)
{
    // A rounded convex outline is its sharp core (sides moved in by the
    // radius) grown by the radius.
    const double rho = std::max(q.cornerRadius, 0.0);
    const Quad core = offsetInward(Quad{q.corners, rho}, rho);
    return signedDistanceSharp(core.corners, p) - rho;
}

namespace {

// The exact region's signed distance of a contour pocket, made once per
// unit (and again when the unit's region changes).
std::shared_ptr<RegionDistance> regionDistance(const ContourPocket& cp)
{
    static std::mutex lock;
    static std::map<const ContourPocket*, std::pair<Region, std::shared_ptr<RegionDistance>>> known;
    const std::lock_guard<std::mutex> hold(lock);
    auto& [region, d] = known[&cp];
    if (!d || !(region == cp.contours.region.value())) {
        region = cp.contours.region.value();
        d = std::make_shared<RegionDistance>(normalised(region));
    }
    return d;
}

}  // namespace

double wallDistance(const ModuleInput& m, Point3 tip)
{
    if (const auto* f = m.getIf<FaceUnit>()) return faceWallDistance(*f, tip);
    if (const auto d = sideWallDistance(m, tip)) return *d;
    if (const auto* cp = m.getIf<ContourPocket>()) return (*regionDistance(*cp))({tip.x, tip.y});
    if (const auto* a = m.getIf<AreaClearing>()) return RegionDistance(normalised(a->area.region.value()))({tip.x, tip.y});
    return signedDistance(pocketSection(m, -tip.z), {tip.x, tip.y});
}

double gouge(const ModuleInput& m, const Tool& tool, Point3 tip)
{
    if (const auto* f = m.getIf<FaceUnit>()) return faceGouge(*f, tool, tip);
    if (const auto g = sideGouge(m, tool, tip)) return *g;
    if (tip.z >= 0.0) return -std::numeric_limits<double>::infinity();
    if (const auto* h = m.getIf<HolePattern>()) {
        // Hole patterns: the tool inside the nearest hole's circle (of the
        // thread's size when tapped: the tap drill is narrower), its tip no
        // deeper than the drill's point allows (1 mm under the depth for a
        // pre-drill, 3 pitches for a tap drill, then at most a 90° point).
        const holes::Thread* thread = holes::findThread(h->thread);
        const double d = thread ? thread->size : h->diameter;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Point2 c : holes::positions(*h)) nearest = std::min(nearest, distance(c, {tip.x, tip.y}));
        const double below = thread ? 3 * thread->pitch : h->hole == "drilled" ? 0.0 : 1.0;
        return std::max(nearest + tool.radius() - d / 2, -tip.z - (h->depth + below + d / 2));
    }
    const double tipDepth = -tip.z;
    if (const auto* cp = m.getIf<ContourPocket>()) {
        // A contour pocket: vertical walls round the exact region (outline
        // and islands, model/contour.h), the tool's widest disc up to the
        // stock top against them, its tip against the floor.
        const auto distanceTo = regionDistance(*cp);
        return std::max(tipDepth - cp->depth, (*distanceTo)({tip.x, tip.y}) + toolRadiusAt(tool, tipDepth));
    }
    if (const auto* a = m.getIf<AreaClearing>()) {
        // Drawn passes: the tool inside the area (outline and islands, exact),
        // its tip no deeper than T.
        static thread_local std::pair<Region, std::shared_ptr<RegionDistance>> known;
        if (!known.second || !(known.first == a->area.region.value())) {
            known.first = a->area.region.value();
            known.second = std::make_shared<RegionDistance>(normalised(known.first));
        }
        return std::max(tipDepth - a->depth, (*known.second)({tip.x, tip.y}) + toolRadiusAt(tool, tipDepth));
    }
    double worst = tipDepth - pocketDepth(m);  // below the floor
    // The tool solid is discs of radius toolRadiusAt(h) at depth tipDepth - h;
    // each must lie inside the pocket section at its depth. Fine steps near
    // the tip, where ball and taper profiles change fastest.
    const int n = 800;
    for (int i = 0; i <= n; ++i) {
        const double h = tipDepth * std::pow(static_cast<double>(i) / n, 2.0);
        const double r = toolRadiusAt(tool, h);
        const Quad section = pocketSection(m, tipDepth - h);
        worst = std::max(worst, signedDistance(section, {tip.x, tip.y}) + r);
    }
    return worst;
}

}  // namespace taiwa::test
