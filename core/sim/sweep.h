// The one sweep of a cutter over the height field, shared by the material
// removal of the preview (sim/material_removal.cpp) and the verification
// (verify/verify.cpp): a straight piece of path split into horizontal
// sweeps, and the cells within a distance of a horizontal segment.
#pragma once

#include "model/toolpath.h"
#include "sim/height_field.h"

#include <algorithm>
#include <cmath>

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

// Calls visit(i, j, r) for every cell of `f` in rows rowMin..rowMax whose
// centre lies within `reach` of the segment a -> b, r being that distance.
template <class Visit>
void forEachCellNear(const HeightField& f, Point2 a, Point2 b, double reach, int rowMin, int rowMax, Visit&& visit)
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
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const Point2 p = f.centre(i, j);
            const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
            const Point2 q = p - (a + t * d);
            const double r2 = dot(q, q);
            if (r2 <= reach2) visit(i, j, std::sqrt(r2));
        }
    }
}

}  // namespace taiwa::sim
