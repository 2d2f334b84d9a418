// The programmed point's path of a turning step's moves, for the lathe
// verification (verify_turning.cpp) to sweep its tool's outline along:
// arcs as chords, and along the nose-compensated stretch the path the
// control makes of it (each element offset by the nose radius, round about
// outside corners, trimmed at inside ones).
#include "verify/verify_turning_traces.h"

#include "model/turned_geometry.h"
#include "sim/turned_shapes.h"

#include <algorithm>
#include <cmath>

namespace taiwa::verify {

using turning::ZR;

namespace {

// The compensated stretch: the entry (from `at`), the contour and the
// exit. Each element offset exactly (a line shifted, an arc concentric),
// joined round about the vertex at an outside corner and trimmed where
// the two offsets cross at an inside one, then flattened.
void compensated(const TurnStep& ts, double r, double tol, ZR at, std::vector<std::vector<ZR>>& out)
{
    const TurnPath& p = ts.path;
    const ZR tip = ts.tipFromCentre;
    const int side = p.comp == NoseCompensation::Left ? 1 : -1;  // G41: the nose left of the contour
    std::vector<turning::Segment> contour, off;
    std::vector<int> owner;  // the move of each element
    ZR from = at;
    for (int m = p.compFrom; m < p.compTo; ++m) {
        const TurnMove& mv = p.moves[static_cast<std::size_t>(m)];
        if (turning::dist(from, mv.end) > 1e-9) {
            const bool arc = mv.kind == TurnMove::ArcCW || mv.kind == TurnMove::ArcCCW;
            contour.push_back(arc ? turning::arcSegment(from, mv.end, mv.centre, mv.kind == TurnMove::ArcCCW)
                                  : turning::lineSegment(from, mv.end));
            owner.push_back(m);
        }
        from = mv.end;
    }
    const std::size_t n = contour.size();
    if (n == 0) return;
    const auto normal = [&](ZR t) { return static_cast<double>(side) * turning::leftNormal(t); };
    for (const turning::Segment& e : contour) {
        const auto o = turning::offset(e, r, side);
        // An arc tighter than the nose (no plan has one): its chord's offset.
        off.push_back(o ? *o
                        : turning::lineSegment(e.a + r * normal(turning::tangentAtStart(e)),
                                               e.b + r * normal(turning::tangentAtEnd(e))));
    }
    std::vector<std::vector<ZR>> corner(n);  // round about the outside corner before element i
    for (std::size_t i = 1; i < n; ++i) {
        const ZR t1 = turning::tangentAtEnd(contour[i - 1]), t2 = turning::tangentAtStart(contour[i]);
        const double turn = static_cast<double>(side) * turning::cross(t1, t2);
        if (turn < -1e-9) {
            const ZR a = normal(t1), b = normal(t2);
            const double angle = std::atan2(turning::cross(a, b), turning::dot(a, b));
            const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tol / std::max(r, tol)));
            const int k = std::max(1, static_cast<int>(std::ceil(std::abs(angle) / std::max(step, 1e-6))));
            for (int j = 1; j < k; ++j) {
                const double t = angle * j / k, c = std::cos(t), s = std::sin(t);
                corner[i].push_back(contour[i].a + r * ZR{c * a.z - s * a.r, s * a.z + c * a.r});
            }
        } else if (turn > 1e-9) {
            const auto x = turning::nearest(
                turning::intersections(turning::curveOf(off[i - 1]), turning::curveOf(off[i])), contour[i].a);
            if (x && turning::contains(off[i - 1], *x) && turning::contains(off[i], *x)) {
                off[i - 1] = turning::piece(off[i - 1], off[i - 1].a, *x);
                off[i] = turning::piece(off[i], *x, off[i].b);
            }
        }
    }
    if (!off[0].arc) off[0] = turning::lineSegment(at - tip, off[0].b);  // the entry starts uncompensated
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<ZR>& t = out[static_cast<std::size_t>(owner[i])];
        if (t.empty() && i > 0) t.push_back(off[i - 1].b + tip);
        for (const ZR q : corner[i]) t.push_back(q + tip);
        for (const ZR q : turning::flatten({off[i]}, tol)) t.push_back(q + tip);
        t.push_back(off[i].b + tip);
    }
    // The exit: compensation cancelled on the way off the part.
    out[static_cast<std::size_t>(p.compTo)] = {off[n - 1].b + tip, p.moves[static_cast<std::size_t>(p.compTo)].end};
}

}  // namespace

// The programmed point's path of every move of a step, arcs as chords;
// along the compensated stretch the point where the tool would be
// programmed without compensation for its nose to be where the
// control puts it (the nose centre offset by its radius from the
// contour, round about outside corners, at the offsets' crossing inside).
std::vector<std::vector<ZR>> traces(const TurnStep& ts, double nose, double tol)
{
    const TurnPath& p = ts.path;
    std::vector<std::vector<ZR>> out(p.moves.size());
    ZR at = p.start;
    const bool comp = p.comp != NoseCompensation::Off && p.compFrom >= 0 && p.compTo > p.compFrom &&
                      p.compTo < static_cast<int>(p.moves.size());
    for (int m = 0; m < static_cast<int>(p.moves.size()); ++m) {
        const TurnMove& mv = p.moves[static_cast<std::size_t>(m)];
        if (comp && m == p.compFrom) compensated(ts, nose, tol, at, out);
        if (!comp || m < p.compFrom || m > p.compTo)
            out[static_cast<std::size_t>(m)] = sim::movePoints(at, mv, tol);
        at = mv.end;
    }
    return out;
}

}  // namespace taiwa::verify
