// The one sweep of a cutter over the height field, shared by the material
// removal of the preview (sim/material_removal.cpp) and the verification
// (verify/milling_cut.cpp): a straight piece of path split into horizontal
// sweeps, and the cells within a distance of a horizontal segment.
#pragma once

#include "model/toolpath.h"
#include "sim/height_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace taiwa::sim {

// Splits the piece a -> b into horizontal sweeps no more than `zStep` apart
// in Z and calls level(from, to, z) for each, z being the higher end of its
// part (erring towards leaving material, never towards removing it), then
// level(b, b, b.z) for the end point. A piece without XY travel is one call
// at its lowest point.
template <class Level>
void forEachLevel(Point3 a, Point3 b, double zStep, Level&& level)
{
    const Point2 a2{a.x, a.y}, b2{b.x, b.y};
    if (distance(a2, b2) < 1e-9) {
        level(a2, a2, std::min(a.z, b.z));
        return;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(b.z - a.z) / zStep)));
    for (int k = 0; k < n; ++k) {
        const double t0 = static_cast<double>(k) / n, t1 = static_cast<double>(k + 1) / n;
        level(a2 + t0 * (b2 - a2), a2 + t1 * (b2 - a2), std::max(a.z + t0 * (b.z - a.z), a.z + t1 * (b.z - a.z)));
    }
    level(b2, b2, b.z);
}

// Where the last of a run of straight sweeps ended, and at what height:
// the next sweep that starts there at that height need not visit again the
// cells within the cutter's flat bottom of its start (forEachCellNear's
// skipAroundA). Cells are only ever lowered, so the result is the same.
class SweepChain {
public:
    // The radius around a to skip for a sweep from a at height z.
    double skip(Point2 a, double z, double flatRadius) const
    {
        return has_ && last_.z == z && last_.x == a.x && last_.y == a.y ? std::max(0.0, flatRadius) : 0.0;
    }
    void ended(Point2 b, double z)
    {
        last_ = Point3{b.x, b.y, z};
        has_ = true;
    }
    void broken() { has_ = false; }

private:
    bool has_ = false;  // (a flag, not std::optional: g++ 12 takes its value for unset)
    Point3 last_{};
};

// The runs of cells a sweep looks at: all of them. A caller that knows
// some cells cannot change (the milling verifier's tiles,
// verify/milling_verifier.h: a run of cells already at or below the tool's
// tip) passes its own, which calls cells(lo, hi) for
// the parts of [from, to] in row j still to visit.
struct EveryCell {
    template <class Cells>
    void operator()(int /*row*/, int from, int to, Cells&& cells) const
    {
        cells(from, to);
    }
};

// Calls visit(i, j, r2) for every cell of `f` in rows rowMin..rowMax whose
// centre lies within `reach` of the segment a -> b, r2 being the square of
// that distance (a flat end mill needs no root), except the cells whose
// centre lies within `skipAroundA` of a (none when 0): a caller whose last
// sweep at the same height ended at a has cut those with the cutter's flat
// bottom already, and a chain of short moves would otherwise visit a whole
// disc of cells per move.
template <class Visit, class Runs = EveryCell>
void forEachCellNear(const HeightField& f, Point2 a, Point2 b, double reach, int rowMin, int rowMax, Visit&& visit,
                     double skipAroundA = 0.0, Runs&& runs = Runs{})
{
    const double c = f.cellSize();
    const Stock& s = f.stock();
    const int i0 = std::max(0, static_cast<int>(std::floor((std::min(a.x, b.x) - reach - s.x) / c)));
    const int i1 = std::min(f.columns() - 1, static_cast<int>(std::floor((std::max(a.x, b.x) + reach - s.x) / c)));
    const int j0 = std::max(rowMin, static_cast<int>(std::floor((std::min(a.y, b.y) - reach - s.y) / c)));
    const int j1 = std::min(rowMax, static_cast<int>(std::floor((std::max(a.y, b.y) + reach - s.y) / c)));
    const Point2 d = b - a;
    const double len2 = dot(d, d);
    const double reach2 = reach * reach;
    const double len = std::sqrt(len2);
    const Point2 u = len > 0 ? (1.0 / len) * d : Point2{1.0, 0.0};
    for (int j = j0; j <= j1; ++j) {
        // The capsule cut by the row's line is one interval of X: the hull
        // of the two end discs' chords and the band's.
        const double y = f.centre(0, j).y;
        double lo = 1e300, hi = -1e300;
        for (const Point2 e : {a, b}) {
            const double dy = y - e.y;
            if (dy * dy > reach2) continue;
            const double w = std::sqrt(reach2 - dy * dy);
            lo = std::min(lo, e.x - w);
            hi = std::max(hi, e.x + w);
        }
        if (len > 0 && u.y != 0.0) {
            // |n . (p - a)| <= reach and 0 <= u . (p - a) <= len, n = (-u.y, u.x), p = (x, y).
            const double dy = y - a.y;
            double x0 = -1e300, x1 = 1e300;
            const auto clip = [&](double coef, double constant, double from, double to) {  // from <= coef x + constant <= to
                if (coef == 0.0) {
                    if (constant < from || constant > to) x0 = 1e300;
                    return;
                }
                double l = (from - constant) / coef, h = (to - constant) / coef;
                if (l > h) std::swap(l, h);
                x0 = std::max(x0, l);
                x1 = std::min(x1, h);
            };
            clip(-u.y, u.y * a.x + u.x * dy, -reach, reach);
            clip(u.x, -u.x * a.x + u.y * dy, 0.0, len);
            if (x0 <= x1) {
                lo = std::min(lo, x0);
                hi = std::max(hi, x1);
            }
        } else if (len > 0 && std::abs(y - a.y) <= reach) {  // along X: the band spans the segment
            lo = std::min(lo, std::min(a.x, b.x));
            hi = std::max(hi, std::max(a.x, b.x));
        }
        if (lo > hi) continue;
        const int from = std::max(i0, static_cast<int>(std::floor((lo - s.x) / c - 0.5)));
        const int to = std::min(i1, static_cast<int>(std::ceil((hi - s.x) / c - 0.5)));
        const double inverse = len2 > 0 ? 1.0 / len2 : 0.0;
        const double py = y - a.y;
        // The cells of this row inside the skipped disc: [skipFrom, skipTo],
        // their centres strictly inside it (by a nanometre, so that rounding
        // never skips a cell on its rim).
        int skipFrom = to + 1, skipTo = to;
        if (skipAroundA > 0.0) {
            const double inside = skipAroundA - 1e-6;
            if (py * py < inside * inside) {
                const double w = std::sqrt(inside * inside - py * py);
                skipFrom = std::max(from, static_cast<int>(std::ceil((a.x - w - s.x) / c - 0.5)));
                skipTo = std::min(to, static_cast<int>(std::floor((a.x + w - s.x) / c - 0.5)));
                if (skipFrom > skipTo) skipFrom = to + 1, skipTo = to;
            }
        }
        const auto cells = [&](int first, int last) {
            for (int i = first; i <= last; ++i) {
                if (i >= skipFrom && i <= skipTo) {
                    i = skipTo;
                    continue;
                }
                const double px = f.centre(i, j).x - a.x;
                const double t = std::clamp((px * d.x + py * d.y) * inverse, 0.0, 1.0);
                const double qx = px - t * d.x, qy = py - t * d.y;
                const double r2 = qx * qx + qy * qy;
                if (r2 <= reach2) visit(i, j, r2);
            }
        };
        runs(j, from, to, cells);
    }
}

// Calls visit(i, j, r2) for every cell of `f` in rows rowMin..rowMax whose
// centre lies within `reach` of the arc of radius `radius` around `c` from
// angle a0 [rad] over `sweep` (signed, |sweep| <= 2π), r2 being the square
// of that distance: exact, no chords. Each row looks only at the cells
// under the ring of width 2 reach around the circle (one or two runs), not
// at the arc's whole box.
template <class Visit, class Runs = EveryCell>
void forEachCellNearArc(const HeightField& f, Point2 c, double radius, double a0, double sweep, double reach, int rowMin,
                        int rowMax, Visit&& visit, Runs&& runs = Runs{})
{
    constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
    const bool full = std::abs(sweep) >= kTwoPi - 1e-12;
    // Counter-clockwise from direction `lo` to `hi` over `span`: a direction
    // is within when it lies left of lo and right of hi (span up to π), or
    // not strictly inside the rest of the turn (span over π).
    const double lo = sweep >= 0 ? a0 : a0 + sweep, span = std::abs(sweep);
    const Point2 uLo{std::cos(lo), std::sin(lo)}, uHi{std::cos(lo + span), std::sin(lo + span)};
    const auto withinDir = [&](Point2 v) {
        if (full) return true;
        if (span <= kTwoPi / 2) return cross(uLo, v) >= 0.0 && cross(v, uHi) >= 0.0;
        return !(cross(uHi, v) > 0.0 && cross(v, uLo) > 0.0);
    };
    const auto within = [&](double a) { return withinDir({std::cos(a), std::sin(a)}); };
    const Point2 p0 = c + radius * Point2{std::cos(a0), std::sin(a0)};
    const Point2 p1 = c + radius * Point2{std::cos(a0 + sweep), std::sin(a0 + sweep)};
    // The arc's box: its ends and the axis points it passes.
    double x0 = std::min(p0.x, p1.x), x1 = std::max(p0.x, p1.x), y0 = std::min(p0.y, p1.y), y1 = std::max(p0.y, p1.y);
    if (within(0.0)) x1 = c.x + radius;
    if (within(kTwoPi / 4)) y1 = c.y + radius;
    if (within(kTwoPi / 2)) x0 = c.x - radius;
    if (within(3 * kTwoPi / 4)) y0 = c.y - radius;
    const double cell = f.cellSize();
    const Stock& s = f.stock();
    const int i0 = std::max(0, static_cast<int>(std::floor((x0 - reach - s.x) / cell)));
    const int i1 = std::min(f.columns() - 1, static_cast<int>(std::floor((x1 + reach - s.x) / cell)));
    const int j0 = std::max(rowMin, static_cast<int>(std::floor((y0 - reach - s.y) / cell)));
    const int j1 = std::min(rowMax, static_cast<int>(std::floor((y1 + reach - s.y) / cell)));
    const double inner = std::max(0.0, radius - reach), outer = radius + reach;
    const double inner2 = inner * inner, outer2 = outer * outer, reach2 = reach * reach;
    // The cell columns whose centres may lie in [x0, x1] (a cell more each
    // side: the exact test below decides).
    const auto columnsOf = [&](double xa, double xb) {
        return std::pair{std::max(i0, static_cast<int>(std::floor((xa - s.x) / cell - 0.5))),
                         std::min(i1, static_cast<int>(std::ceil((xb - s.x) / cell - 0.5)))};
    };
    for (int j = j0; j <= j1; ++j) {
        const auto cells = [&](int first, int last) {
            for (int i = first; i <= last; ++i) {
                const Point2 p = f.centre(i, j);
                const Point2 v = p - c;
                const double d2 = dot(v, v);
                if (d2 > outer2 || d2 < inner2) continue;  // farther than the reach from the whole circle
                double r;
                if (d2 > 0.0 && withinDir(v)) {
                    r = std::abs(std::sqrt(d2) - radius);
                } else {
                    const Point2 e0 = p - p0, e1 = p - p1;
                    r = std::sqrt(std::min(dot(e0, e0), dot(e1, e1)));
                }
                if (r * r <= reach2) visit(i, j, r * r);
            }
        };
        const double dy = f.centre(0, j).y - c.y, dy2 = dy * dy;
        if (dy2 > outer2) continue;
        const double wOut = std::sqrt(outer2 - dy2);
        if (dy2 >= inner2) {  // the row crosses the ring once
            const auto [first, last] = columnsOf(c.x - wOut, c.x + wOut);
            if (first <= last) runs(j, first, last, cells);
            continue;
        }
        const double wIn = std::sqrt(inner2 - dy2);  // twice, around the hole
        const auto [lo0, hi0] = columnsOf(c.x - wOut, c.x - wIn);
        const auto [lo1, hi1] = columnsOf(c.x + wIn, c.x + wOut);
        if (lo0 <= hi0) runs(j, lo0, hi0, cells);
        const int from1 = lo0 <= hi0 ? std::max(lo1, hi0 + 1) : lo1;  // no cell twice
        if (from1 <= hi1) runs(j, from1, hi1, cells);
    }
}

}  // namespace taiwa::sim
