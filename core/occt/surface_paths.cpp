// Finishing, roughing, boundary and combining paths over a tessellated
// surface (surface_paths.h), all from the drop-cutter of surface_mesh.h.
#include "occt/surface_paths.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace taiwa::surface {

namespace {

std::vector<double> samples(double a, double b, double step)
{
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / step - 1e-9)));
    std::vector<double> xs;
    xs.reserve(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k <= n; ++k) xs.push_back(k == n ? b : a + (b - a) * k / n);
    return xs;
}

using Row = std::vector<std::optional<double>>;

Row dropRow(DropCutter& drop, const std::vector<double>& xs, double y)
{
    Row row;
    row.reserve(xs.size());
    for (double x : xs) row.push_back(drop.noseZ(x, y));
    return row;
}

// The row as paths: runs of present points, reversed when `reverse`.
std::vector<std::vector<Point3>> piecesOf(const Row& row, const std::vector<double>& xs, double y, bool reverse)
{
    std::vector<std::vector<Point3>> out;
    std::vector<Point3> cur;
    const std::size_t n = row.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = reverse ? n - 1 - i : i;
        if (row[k]) {
            cur.push_back({xs[k], y, *row[k]});
        } else if (!cur.empty()) {
            out.push_back(std::move(cur));
            cur.clear();
        }
    }
    if (!cur.empty()) out.push_back(std::move(cur));
    return out;
}

// The largest distance between the corner-circle centres of two rows at the
// same X (the rows' Y apart by dy); 0 when they share no sample.
double rowDistance(const Row& a, const Row& b, double dy)
{
    double worst = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k] && b[k]) worst = std::max(worst, std::hypot(dy, *b[k] - *a[k]));
    return worst;
}

}  // namespace

std::vector<std::vector<Point3>> dropLine(DropCutter& drop, double y, double x0, double x1, double step, bool reverse)
{
    const std::vector<double> xs = samples(x0, x1, step);
    return piecesOf(dropRow(drop, xs, y), xs, y, reverse);
}

double scallopSpacing(const Cutter& cutter, double height, double concaveRadius)
{
    const double r = cutter.cornerRadius;
    const double h = std::clamp(height, 0.0, r);
    const double flat = 2 * std::sqrt(h * (2 * r - h));
    if (std::isinf(concaveRadius)) return flat;
    const double rho = concaveRadius;
    if (rho <= r) return 0.0;
    // The cusp's depth grows with ℓ: bisection up to the flat spacing.
    const auto depth = [&](double l) {
        const double half = std::asin(std::min(1.0, l / (2 * (rho - r))));
        return rho - (rho - r) * std::cos(half) - std::sqrt(std::max(0.0, r * r - l * l / 4));
    };
    double lo = 0.0, hi = std::min(flat, 2 * (rho - r));
    if (depth(hi) <= h) return hi;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (depth(mid) <= h ? lo : hi) = mid;
    }
    return lo;
}

FinishingPaths finishingPaths(DropCutter& drop, const Area& area, double step, double height, double concaveRadius)
{
    FinishingPaths out;
    const std::vector<double> xs = samples(area.x0, area.x1, step);
    const double spacing = scallopSpacing(drop.cutter(), height, concaveRadius);
    if (!(spacing > 0)) return out;
    double y = area.y0;
    Row row = dropRow(drop, xs, y);
    bool reverse = false;
    double lastPick = spacing;
    for (;;) {
        for (auto& p : piecesOf(row, xs, y, reverse)) out.paths.push_back(std::move(p));
        out.ys.push_back(y);
        reverse = !reverse;
        if (y >= area.y1) break;
        // From the last pick-feed grown a little (slopes change slowly),
        // shrunk until the centres are close enough.
        double s = std::min({spacing, area.y1 - y, lastPick * 1.25});
        Row next;
        for (int tries = 0; tries < 60; ++tries) {
            next = dropRow(drop, xs, y + s);
            const double d = rowDistance(row, next, s);
            if (d <= spacing * (1 + 1e-9)) break;
            s *= 0.999 * spacing / d;
        }
        y = s >= area.y1 - y ? area.y1 : y + s;
        lastPick = s;
        row = std::move(next);
    }
    return out;
}

FinishingPaths parallelPaths(DropCutter& drop, const Area& area, double step, double pickFeed)
{
    FinishingPaths out;
    const std::vector<double> xs = samples(area.x0, area.x1, step);
    const std::vector<double> ys = samples(area.y0, area.y1, pickFeed);
    bool reverse = false;
    for (double y : ys) {
        for (auto& p : piecesOf(dropRow(drop, xs, y), xs, y, reverse)) out.paths.push_back(std::move(p));
        out.ys.push_back(y);
        reverse = !reverse;
    }
    return out;
}

std::vector<RoughingPass> zLevelRoughing(const MeshIndex& surface, const Cutter& cutter, const Area& area,
                                         const ZLevelOptions& o)
{
    std::vector<RoughingPass> out;
    const double a = std::max(0.0, o.allowance);
    DropCutter grown(surface, Cutter{cutter.diameter + 2 * a, cutter.cornerRadius + a});
    grown.keepAxisOverSurface(o.axisOverSurface);
    const std::vector<double> xs = samples(area.x0, area.x1, o.step);
    const std::vector<double> ys = samples(area.y0, area.y1, o.stepOver);
    std::vector<Row> rows;
    double bottom = o.top;
    for (double y : ys) {
        Row row = dropRow(grown, xs, y);
        for (auto& z : row)
            if (z) {
                *z += a;  // the real cutter's nose: the grown one's centre is a higher
                bottom = std::min(bottom, *z);
            }
        rows.push_back(std::move(row));
    }
    std::vector<double> levels;
    for (int k = 1; o.depth > 0 && o.top - k * o.depth > bottom + 1e-9; ++k) levels.push_back(o.top - k * o.depth);
    if (bottom < o.top - 1e-9) levels.push_back(bottom);
    double above = o.top;
    bool reverse = false;
    for (double level : levels) {
        for (std::size_t j = 0; j < ys.size(); ++j) {
            const Row& row = rows[j];
            RoughingPass pass{level, {}};
            const std::size_t n = row.size();
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t k = reverse ? n - 1 - i : i;
                if (row[k] && *row[k] < above - 1e-9) {
                    pass.points.push_back({xs[k], ys[j], std::max(level, *row[k])});
                } else if (!pass.points.empty()) {
                    out.push_back(std::move(pass));
                    pass = RoughingPass{level, {}};
                }
            }
            if (!pass.points.empty()) out.push_back(std::move(pass));
            reverse = !reverse;
        }
        above = level;
    }
    return out;
}

void refineMoves(DropCutter& drop, std::vector<Point3>& path, double tolerance, double floorZ, double raise)
{
    if (path.size() < 2) return;
    std::vector<Point3> out{path.front()};
    const auto between = [&](auto& self, Point3 a, Point3 b, int depth) -> void {
        if (depth < 4) {
            const Point3 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)};
            if (const std::optional<double> z = drop.noseZ(m.x, m.y)) {
                const double at = std::max(floorZ, *z + raise);
                if (at > m.z + tolerance) {
                    self(self, a, {m.x, m.y, at}, depth + 1);
                    self(self, {m.x, m.y, at}, b, depth + 1);
                    return;
                }
            }
        }
        out.push_back(b);
    };
    for (std::size_t i = 1; i < path.size(); ++i) between(between, path[i - 1], path[i], 0);
    path = std::move(out);
}

StoppedPath stopAtBoundary(const std::vector<Point3>& path, const MeshIndex& boundary)
{
    StoppedPath out;
    std::vector<std::uint32_t> seen;
    std::uint32_t stamp = 0;
    const TriangleMesh& m = boundary.mesh();
    for (std::size_t i = 0; i < path.size(); ++i) {
        out.points.push_back(path[i]);
        if (i + 1 == path.size()) break;
        const Point3 p = path[i], q = path[i + 1];
        const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
        double tBest = 2.0;
        boundary.near(0.5 * (p.x + q.x), 0.5 * (p.y + q.y), 0.5 * std::hypot(dx, dy) + 1e-9, seen, stamp, [&](int t) {
            const auto& tri = m.triangles[static_cast<std::size_t>(t)];
            const Point3& a = m.vertices[static_cast<std::size_t>(tri[0])];
            const Point3& b = m.vertices[static_cast<std::size_t>(tri[1])];
            const Point3& c = m.vertices[static_cast<std::size_t>(tri[2])];
            // Möller–Trumbore, the segment p + t·(q − p), 0 ≤ t ≤ 1.
            const double e1x = b.x - a.x, e1y = b.y - a.y, e1z = b.z - a.z;
            const double e2x = c.x - a.x, e2y = c.y - a.y, e2z = c.z - a.z;
            const double hx = dy * e2z - dz * e2y, hy = dz * e2x - dx * e2z, hz = dx * e2y - dy * e2x;
            const double det = e1x * hx + e1y * hy + e1z * hz;
            if (std::abs(det) < 1e-14) return;
            const double f = 1.0 / det;
            const double sx = p.x - a.x, sy = p.y - a.y, sz = p.z - a.z;
            const double u = f * (sx * hx + sy * hy + sz * hz);
            const double eps = 1e-12;
            if (u < -eps || u > 1 + eps) return;
            const double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
            const double v = f * (dx * qx + dy * qy + dz * qz);
            if (v < -eps || u + v > 1 + eps) return;
            const double tt = f * (e2x * qx + e2y * qy + e2z * qz);
            if (tt >= 0 && tt <= 1) tBest = std::min(tBest, tt);
        });
        if (tBest <= 1.0) {
            if (tBest > 0) out.points.push_back({p.x + tBest * dx, p.y + tBest * dy, p.z + tBest * dz});
            out.stopped = true;
            break;
        }
    }
    return out;
}

ToolPath linkPaths(const std::vector<std::vector<Point3>>& paths, double safeZ, double clearance, double materialTop)
{
    ToolPath out;
    for (const auto& path : paths)
        if (!path.empty()) {
            out.start = {path.front().x, path.front().y, safeZ};
            break;
        }
    for (const auto& path : paths) {
        if (path.empty()) continue;
        const Point3 first = path.front();
        out.moves.push_back({MoveKind::Rapid, {first.x, first.y, safeZ}});
        out.moves.push_back({MoveKind::Rapid, {first.x, first.y, std::min(safeZ, std::max(first.z, materialTop) + clearance)}});
        out.moves.push_back({MoveKind::Feed, first, {}, FeedKind::Plunge});
        for (std::size_t i = 1; i < path.size(); ++i) out.moves.push_back({MoveKind::Feed, path[i]});
        out.moves.push_back({MoveKind::Rapid, {path.back().x, path.back().y, safeZ}});
    }
    return out;
}

std::vector<std::vector<Point3>> combineSurfaces(const MeshIndex& first,
                                                 const std::vector<std::vector<Point3>>& secondPaths, KeepSide keep)
{
    DropCutter drop(first, Cutter{});
    std::vector<std::vector<Point3>> out;
    for (const auto& path : secondPaths) {
        std::vector<Point3> kept;
        kept.reserve(path.size());
        for (const Point3& q : path) {
            const std::optional<double> z = drop.surfaceZ(q.x, q.y);
            const bool onKeptSide = !z || (keep == KeepSide::Above ? q.z >= *z : q.z <= *z);
            kept.push_back(onKeptSide ? q : Point3{q.x, q.y, *z});
        }
        out.push_back(std::move(kept));
    }
    return out;
}

}  // namespace taiwa::surface
