// Moves, tool shapes and parts of the turning simulations (turned_shapes.h).
#include "sim/turned_shapes.h"

#include "model/turned_geometry.h"
#include "model/turn_path.h"

#include <algorithm>

namespace taiwa::sim {

using turning::ZR;

std::vector<ZR> movePoints(ZR from, const TurnMove& m, double tol)
{
    if (m.kind != TurnMove::ArcCW && m.kind != TurnMove::ArcCCW) return {from, m.end};
    const turning::Segment s = turning::arcSegment(from, m.end, m.centre, m.kind == TurnMove::ArcCCW);
    std::vector<ZR> pts = turning::flatten({s}, tol);
    pts.push_back(m.end);
    return pts;
}

std::vector<ZR> shapeOf(const Step& s, const Tool& t, int sides)
{
    const TurnStep& ts = *turnOf(s);
    const bool inner = ts.side == turning::ProfileSide::Inner;
    if (t.type == ToolType::Drill || t.type == ToolType::CentreDrill)
        return {{0.0, 0.0}, {200.0, 0.0}, {200.0, t.radius()}, {0.0, t.radius()}};
    if (t.type == ToolType::Grooving) {
        const double w = t.turning.width, h = inner ? -30.0 : 30.0;
        return {{-w, 0.0}, {0.0, 0.0}, {0.0, h}, {-w, h}};
    }
    const ZR centre{-ts.tipFromCentre.z, -ts.tipFromCentre.r};
    std::vector<ZR> pts = turning::circumscribedCircle(centre, std::max(t.cornerRadius, 0.01), sides);
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) pts.push_back(pts[i] + ZR{0.0, inner ? -100.0 : 100.0});
    return turning::convexHull(pts);
}

std::vector<ZR> partOf(const Plan& plan, int unit, double rOut, std::optional<double> heldEnd)
{
    for (const TurnedPart& p : plan.turned) {
        if (p.unit != unit || p.deformed.edges.empty()) continue;
        std::vector<turning::Segment> chain;
        for (const auto& e : p.deformed.edges) chain.push_back(e.geometry);
        std::vector<ZR> pts = turning::flatten(chain, turning::kFlatten);
        const ZR a = chain.front().a, b = chain.back().b;
        pts.push_back(b);
        if (p.deformed.side == turning::ProfileSide::Inner) {
            pts.push_back({b.z, rOut});
            pts.push_back({a.z, rOut});
        } else if (heldEnd) {  // with the bar behind it, held in the chuck
            const double end = std::min(b.z, *heldEnd) - 1.0;
            pts.push_back({b.z, rOut});
            pts.push_back({end, rOut});
            pts.push_back({end, 0.0});
            pts.push_back({a.z, 0.0});
        } else {
            pts.push_back({b.z, 0.0});
            pts.push_back({a.z, 0.0});
        }
        return pts;
    }
    return {};
}

}  // namespace taiwa::sim
