// Sweeping a cutter profile over the height field.
#include "sim/material_removal.h"

#include "sim/cutter_profile.h"
#include "sim/path_samples.h"

#include <algorithm>
#include <cmath>

namespace taiwa::sim {

namespace {

constexpr double kZStep = 0.02;  // largest Z change within one swept piece [mm]

// Lowers the cells under the tool moved horizontally at tip height z from a
// to b: each cell to z + height(distance of its centre to the piece).
void sweepLevel(HeightField& f, const CutterProfile& cutter, Point2 a, Point2 b, double z)
{
    if (z >= 0.0) return;  // the tip above the top never reaches material
    const double reach = cutter.reach();
    const double c = f.cellSize();
    const Stock& s = f.stock();
    const int i0 = std::max(0, static_cast<int>(std::floor((std::min(a.x, b.x) - reach - s.x) / c)));
    const int i1 = std::min(f.columns() - 1, static_cast<int>(std::floor((std::max(a.x, b.x) + reach - s.x) / c)));
    const int j0 = std::max(0, static_cast<int>(std::floor((std::min(a.y, b.y) - reach - s.y) / c)));
    const int j1 = std::min(f.rows() - 1, static_cast<int>(std::floor((std::max(a.y, b.y) + reach - s.y) / c)));
    const Point2 d = b - a;
    const double len2 = dot(d, d);
    const double reach2 = reach * reach;
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const Point2 p = f.centre(i, j);
            const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
            const Point2 q = p - (a + t * d);
            const double r2 = dot(q, q);
            if (r2 > reach2) continue;
            f.lower(i, j, z + cutter.height(std::sqrt(r2)));
        }
    }
}

void sweepPiece(HeightField& f, const CutterProfile& cutter, Point3 a, Point3 b)
{
    if (std::min(a.z, b.z) >= 0.0) return;
    const Point2 a2{a.x, a.y}, b2{b.x, b.y};
    if (distance(a2, b2) < 1e-9) {  // straight up or down: the lowest point cuts all
        sweepLevel(f, cutter, a2, a2, std::min(a.z, b.z));
        return;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(b.z - a.z) / kZStep)));
    for (int k = 0; k < n; ++k) {
        const double t0 = static_cast<double>(k) / n, t1 = static_cast<double>(k + 1) / n;
        const Point2 p0 = a2 + t0 * (b2 - a2), p1 = a2 + t1 * (b2 - a2);
        sweepLevel(f, cutter, p0, p1, std::max(a.z + t0 * (b.z - a.z), a.z + t1 * (b.z - a.z)));
    }
    sweepLevel(f, cutter, b2, b2, b.z);
}

}  // namespace

void cut(HeightField& field, const ToolPath& path, const Tool& tool)
{
    const CutterProfile cutter(tool);
    const double tolerance = std::min(0.01, field.cellSize() / 10.0);
    for (const PathPiece& piece : flattenPath(path, tolerance)) sweepPiece(field, cutter, piece.from, piece.to);
}

}  // namespace taiwa::sim
