// The bar's half-section after turning steps (turned_stock.h).
#include "sim/turned_stock.h"

#include "model/clipper_scale.h"
#include "model/turned_geometry.h"
#include "turning/turn_region.h"

#include <algorithm>
#include <cmath>

namespace taiwa::sim {

namespace {

using turning::ZR;

ClipperLib::IntPoint ip(ZR p) { return toClipper(Point2{p.z, p.r}); }

ClipperLib::Path path(const std::vector<ZR>& pts)
{
    ClipperLib::Path p;
    for (const ZR q : pts) p.push_back(ip(q));
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    return p;
}

// The points of a move from `from` (arcs every 2 µm of sagitta).
std::vector<ZR> movePoints(ZR from, const TurnMove& m)
{
    if (m.kind != TurnMove::ArcCW && m.kind != TurnMove::ArcCCW) return {from, m.end};
    const turning::Segment s = turning::arcSegment(from, m.end, m.centre, m.kind == TurnMove::ArcCCW);
    std::vector<ZR> pts = turning::flatten({s}, turning::kFlatten);
    pts.push_back(m.end);
    return pts;
}

// The tool's cutting shape about its programmed point.
std::vector<ZR> shapeOf(const Step& s, const Tool& t)
{
    const TurnStep& ts = *s.turn;
    const bool inner = ts.side == turning::ProfileSide::Inner;
    if (t.type == ToolType::Drill || t.type == ToolType::CentreDrill)
        return {{0.0, 0.0}, {200.0, 0.0}, {200.0, t.radius()}, {0.0, t.radius()}};
    if (t.type == ToolType::Grooving) {
        const double w = t.turning.width, h = inner ? -30.0 : 30.0;
        return {{-w, 0.0}, {0.0, 0.0}, {0.0, h}, {-w, h}};
    }
    // The nose and, above it, the cutting edge: everything over the nose
    // along a cut is chip (the stock's surface is never above the edge).
    const ZR centre{-ts.tipFromCentre.z, -ts.tipFromCentre.r};
    std::vector<ZR> pts = turning::circumscribedCircle(centre, std::max(t.cornerRadius, 0.01), 16);
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) pts.push_back(pts[i] + ZR{0.0, inner ? -100.0 : 100.0});
    return turning::convexHull(pts);
}

// The part of the step's unit, closed toward the axis (outer) or out past the bar (inner).
std::vector<ZR> partOf(const Plan& plan, int unit, double rOut, double barEnd)
{
    for (const TurnedPart& p : plan.turned) {
        if (p.unit != unit || p.deformed.edges.empty()) continue;
        std::vector<turning::Segment> chain;
        for (const auto& e : p.deformed.edges) chain.push_back(e.geometry);
        std::vector<ZR> pts = turning::flatten(chain, turning::kFlatten);
        const ZR a = chain.front().a, b = chain.back().b;
        pts.push_back(b);
        if (p.deformed.side == turning::ProfileSide::Outer) {  // with the bar behind it, held in the chuck
            const double end = std::min(b.z, barEnd) - 1.0;
            pts.push_back({b.z, rOut});
            pts.push_back({end, rOut});
            pts.push_back({end, 0.0});
            pts.push_back({a.z, 0.0});
        } else {
            pts.push_back({b.z, rOut});
            pts.push_back({a.z, rOut});
        }
        return pts;
    }
    return {};
}

}  // namespace

std::vector<std::vector<ZR>> turnedStockAfter(const Plan& plan, int last)
{
    if (!plan.mmJob.bar) return {};
    const BarStock& bar = *plan.mmJob.bar;
    const double R = bar.diameter / 2.0, b = bar.bore / 2.0;
    ClipperLib::Paths stock{path({{bar.face, b}, {bar.face, R}, {bar.face - bar.length, R}, {bar.face - bar.length, b}})};
    ClipperLib::Clipper removed;
    bool any = false;
    const int n = std::min(last + 1, static_cast<int>(plan.steps.size()));
    for (int k = 0; k < n; ++k) {
        const Step& s = plan.steps[static_cast<std::size_t>(k)];
        const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        if (!s.turn || !t) continue;
        const TurnPath& p = s.turn->path;
        const std::vector<ZR> shape = shapeOf(s, *t);
        ZR at = p.start;
        std::vector<ZR> contour;  // the compensated stretch, as programmed
        for (int m = 0; m < static_cast<int>(p.moves.size()); ++m) {
            const TurnMove& mv = p.moves[static_cast<std::size_t>(m)];
            const bool comp = p.comp != NoseCompensation::Off && m > p.compFrom && m < p.compTo;
            const auto pts = movePoints(at, mv);
            if (comp) {
                if (contour.empty()) contour.push_back(at);
                contour.insert(contour.end(), pts.begin() + 1, pts.end());
            } else if (mv.kind != TurnMove::Rapid) {
                for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                    std::vector<ZR> two;
                    for (const ZR q : shape) {
                        two.push_back(pts[i] + q);
                        two.push_back(pts[i + 1] + q);
                    }
                    removed.AddPath(path(turning::convexHull(two)), ClipperLib::ptSubject, true);
                    any = true;
                }
            }
            at = mv.end;
        }
        if (contour.size() >= 2) {
            // Compensated: within two nose radii of the contour, outside the part.
            ClipperLib::ClipperOffset band;
            ClipperLib::Path line;
            for (const ZR q : contour) line.push_back(ip(q));
            band.AddPath(line, ClipperLib::jtRound, ClipperLib::etOpenRound);
            ClipperLib::Paths swept;
            // The insert's body passes there too: at least a roughing pass's stair.
            band.Execute(swept, std::max(2.0 * t->cornerRadius, 3.0) * kClipperScale);
            ClipperLib::Clipper outside;
            outside.AddPaths(swept, ClipperLib::ptSubject, true);
            const auto part = partOf(plan, s.unit, R + 1.0, bar.face - bar.length);
            if (!part.empty()) outside.AddPath(path(part), ClipperLib::ptClip, true);
            ClipperLib::Paths cut;
            outside.Execute(ClipperLib::ctDifference, cut, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
            removed.AddPaths(cut, ClipperLib::ptSubject, true);
            any = true;
        }
    }
    if (any) {
        ClipperLib::Paths gone;
        removed.Execute(ClipperLib::ctUnion, gone, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        ClipperLib::Clipper c;
        c.AddPaths(stock, ClipperLib::ptSubject, true);
        c.AddPaths(gone, ClipperLib::ptClip, true);
        ClipperLib::Paths left;
        c.Execute(ClipperLib::ctDifference, left, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        stock = std::move(left);
    }
    std::vector<std::vector<ZR>> loops;
    for (const auto& q : stock) {
        std::vector<ZR> loop;
        for (const auto& v : q) {
            const Point2 p = fromClipper(v);
            loop.push_back({p.x, p.y});
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

double loopsArea(const std::vector<std::vector<ZR>>& loops)
{
    double a = 0.0;
    for (const auto& l : loops)
        for (std::size_t i = 0; i < l.size(); ++i) a += turning::cross(l[i], l[(i + 1) % l.size()]) / 2.0;
    return std::abs(a);
}

}  // namespace taiwa::sim
