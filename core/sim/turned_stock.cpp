// The bar's half-section after turning steps (turned_stock.h).
#include "sim/turned_stock.h"

#include "model/turned_geometry.h"
#include "model/turn_path.h"
#include "sim/turned_clipper.h"
#include "sim/turned_shapes.h"

#include <algorithm>
#include <cmath>

namespace taiwa::sim {

using turning::ZR;

std::vector<std::vector<ZR>> turnedStockAfter(const Plan& plan, int last)
{
    if (!plan.mmJob.bar) return {};
    const BarStock& bar = *plan.mmJob.bar;
    const double R = bar.diameter / 2.0, b = bar.bore / 2.0;
    ClipperLib::Paths stock{clipperPolygon({{bar.face, b}, {bar.face, R}, {bar.face - bar.length, R}, {bar.face - bar.length, b}})};
    ClipperLib::Clipper removed;
    bool any = false;
    const int n = std::min(last + 1, static_cast<int>(plan.steps.size()));
    for (int k = 0; k < n; ++k) {
        const Step& s = plan.steps[static_cast<std::size_t>(k)];
        const Tool* t = s.tool ? plan.tool(s.tool->toolId) : nullptr;
        if (!turnOf(s) || !t) continue;
        const TurnPath& p = turnOf(s)->path;
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
                    removed.AddPath(clipperPolygon(turning::convexHull(two)), ClipperLib::ptSubject, true);
                    any = true;
                }
            }
            at = mv.end;
        }
        if (contour.size() >= 2) {
            // Compensated: within two nose radii of the contour, outside the part.
            ClipperLib::ClipperOffset band;
            ClipperLib::Path line;
            for (const ZR q : contour) line.push_back(clipperPoint(q));
            band.AddPath(line, ClipperLib::jtRound, ClipperLib::etOpenRound);
            ClipperLib::Paths swept;
            // The insert's body passes there too: at least a roughing pass's stair.
            band.Execute(swept, std::max(2.0 * t->cornerRadius, 3.0) * kClipperScale);
            ClipperLib::Clipper outside;
            outside.AddPaths(swept, ClipperLib::ptSubject, true);
            const auto part = partOf(plan, s.unit, R + 1.0, bar.face - bar.length);
            if (!part.empty()) outside.AddPath(clipperPolygon(part), ClipperLib::ptClip, true);
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
            loop.push_back(zrOf(v));
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
