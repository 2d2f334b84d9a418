// Lathe tool geometry for the turning paths (turn_tools.h).
#include "turning/turn_tools.h"

#include "model/turned_geometry.h"
#include "tools/insert_code.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::turning {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// How far the insert's edges are drawn from the nose: about a cutting edge
// (the holder behind them stays out of the half-section's air it works in).
double edgeLength(const InsertGeometry& g) { return std::max(8.0, 6.0 * g.noseRadius); }

}  // namespace

std::optional<InsertGeometry> insertGeometry(const Tool& t)
{
    if (t.type != ToolType::TurningInsert) return std::nullopt;
    const auto code = parseInsertCode(t.turning.insertCode);
    if (!code) return std::nullopt;
    InsertGeometry g;
    g.noseRadius = t.cornerRadius;
    g.approach = t.turning.approachAngle > 0.0 ? t.turning.approachAngle : 95.0;
    g.tipAngle = code->tipAngle > 0.0 ? code->tipAngle : 80.0;
    g.inside = t.turning.inside;
    return g;
}

double riseDegrees(ZR tangent, ProfileSide side)
{
    const double s = side == ProfileSide::Outer ? 1.0 : -1.0;
    return std::atan2(s * tangent.r, -tangent.z) / kDeg;
}

bool reaches(const InsertGeometry& g, const Segment& s, ProfileSide side)
{
    const auto ok = [&](ZR t) {
        const double th = riseDegrees(t, side);
        return th >= g.minRise() - 1e-9 && th <= g.maxRise() + 1e-9;
    };
    if (!s.arc) return ok(tangentAtStart(s));
    // The tangent turns monotonically along an arc: its ends and every
    // axis direction it passes bound the angles it takes.
    if (!ok(tangentAtStart(s)) || !ok(tangentAtEnd(s))) return false;
    const double len = length(s);
    for (int i = 1; i < 16; ++i)
        if (!ok(tangentAt(s, pointAt(s, len * i / 16.0)))) return false;
    return true;
}

ToolShape insertShape(const InsertGeometry& g)
{
    // Leading edge at κr from the feed direction (-Z), trailing edge a tip
    // angle further; a boring bar is the same mirrored across Z.
    const double s = g.inside ? -1.0 : 1.0;
    const double L = edgeLength(g);
    const double a1 = g.approach * kDeg, a2 = (g.approach + g.tipAngle) * kDeg;
    const ZR lead{-std::cos(a1), s * std::sin(a1)}, trail{-std::cos(a2), s * std::sin(a2)};
    std::vector<ZR> pts = circumscribedCircle({0.0, 0.0}, g.noseRadius, 24);
    // The edges are tangent to the nose on the outside of the wedge between
    // them: from the nose's touching points outward.
    const ZR nLead = leftNormal(lead), nTrail = leftNormal(trail);
    for (const ZR& n : {nLead, -1.0 * nLead})
        if (dot(n, trail) < 0) pts.push_back(g.noseRadius * n + L * lead);
    for (const ZR& n : {nTrail, -1.0 * nTrail})
        if (dot(n, lead) < 0) pts.push_back(g.noseRadius * n + L * trail);
    return convexHull(pts);
}

ToolShape bladeShape(double width, double reach, bool inside)
{
    const double s = inside ? -1.0 : 1.0;
    // Half a micrometre narrower on each side: a blade fits a groove of its
    // own width (turn_region's arithmetic would otherwise shut it out).
    constexpr double e = 0.0005;
    return convexHull({{-e, 0.0}, {-width + e, 0.0}, {-width + e, s * reach}, {-e, s * reach}});
}

int insertOrientation(bool inside) { return inside ? 3 : 2; }

ZR tipFromCentre(double noseRadius, bool inside)
{
    // LinuxCNC orientation 2 (OD, toward the chuck): the control point at
    // X −r, Z −r from the nose centre; 3 (boring): X +r, Z −r.
    return {-noseRadius, inside ? noseRadius : -noseRadius};
}

}  // namespace taiwa::turning
