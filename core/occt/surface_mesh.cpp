// Tessellation, the XY grid index and the drop-cutter (surface_mesh.h). The
// drop of a ball or bull-nose cutter onto one triangle is the highest of its
// face contact (closed form: the torus' ring point nearest the plane), its
// vertices' and its three edges' (a ball's in closed form; a bull-nose's
// height along an edge is concave, so a golden-section search finds its
// top), the edges skipped when a bound shows they cannot beat the best
// height found on the faces and vertices.
#include "occt/surface_mesh.h"

#include "occt/surface_curves.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::surface {

namespace {

constexpr double kNone = -std::numeric_limits<double>::infinity();

// Is (px, py) inside the XY projection of triangle a, b, c (edges included)?
bool insideXY(double px, double py, const Point3& a, const Point3& b, const Point3& c)
{
    const double d1 = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
    const double d2 = (c.x - b.x) * (py - b.y) - (c.y - b.y) * (px - b.x);
    const double d3 = (a.x - c.x) * (py - c.y) - (a.y - c.y) * (px - c.x);
    const double eps = 1e-12;
    const bool neg = d1 < -eps || d2 < -eps || d3 < -eps;
    const bool pos = d1 > eps || d2 > eps || d3 > eps;
    return !(neg && pos);
}

// The cutter's nose height touching the segment p–q (its part within the
// disc) at (x, y), raising `best` to it.
void noseOnEdge(const Cutter& cutter, double x, double y, const Point3& p, const Point3& q, double& best)
{
    const double rmax = cutter.diameter / 2;
    const double ex = q.x - p.x, ey = q.y - p.y, ez = q.z - p.z;
    const double fx = p.x - x, fy = p.y - y;
    const double a = ex * ex + ey * ey;
    const double b = 2 * (ex * fx + ey * fy);
    const double c = fx * fx + fy * fy;
    if (a < 1e-18) {  // a vertical edge
        const double d = std::sqrt(c);
        if (d > rmax) return;
        best = std::max(best, std::max(p.z, q.z) - cutter.heightAt(d));
        return;
    }
    const double disc = b * b - 4 * a * (c - rmax * rmax);
    if (disc < 0) return;
    const double sq = std::sqrt(disc);
    double s0 = std::max(0.0, (-b - sq) / (2 * a)), s1 = std::min(1.0, (-b + sq) / (2 * a));
    if (s0 > s1) return;
    const double sm = std::clamp(-b / (2 * a), s0, s1);
    const double dmin = std::sqrt(std::max(0.0, a * sm * sm + b * sm + c));
    const double zTop = std::max(p.z + s0 * ez, p.z + s1 * ez);
    if (zTop - cutter.heightAt(dmin) <= best) return;
    const auto g = [&](double s) {
        const double d = std::sqrt(std::max(0.0, a * s * s + b * s + c));
        return p.z + s * ez - cutter.heightAt(std::min(d, rmax));
    };
    // Golden section on the concave g.
    constexpr double k = 0.6180339887498949;
    double lo = s0, hi = s1;
    double m1 = hi - k * (hi - lo), m2 = lo + k * (hi - lo);
    double g1 = g(m1), g2 = g(m2);
    for (int i = 0; i < 32 && hi - lo > 1e-10; ++i) {  // 0.618³² ≈ 2e-7 of the edge
        if (g1 < g2) {
            lo = m1, m1 = m2, g1 = g2;
            m2 = lo + k * (hi - lo), g2 = g(m2);
        } else {
            hi = m2, m2 = m1, g2 = g1;
            m1 = hi - k * (hi - lo), g1 = g(m1);
        }
    }
    best = std::max({best, g1, g2, g(s0), g(s1)});
}

// A ball's edge contact in closed form: in the vertical plane of the
// edge the ball is a circle of radius √(r² − d²) (d the axis' distance
// from the edge's line in XY) resting on a line of slope m; `best` raised to it.
void ballOnEdge(double r, double x, double y, const Point3& p, const Point3& q, double& best)
{
    const double ex = q.x - p.x, ey = q.y - p.y;
    const double len = std::sqrt(ex * ex + ey * ey);
    if (len < 1e-12) return;  // vertical: its top vertex decides
    const double tx = ex / len, ty = ey / len;
    const double along = (x - p.x) * tx + (y - p.y) * ty;
    const double across = (x - p.x) * ty - (y - p.y) * tx;
    if (std::abs(across) >= r) return;
    const double rc = std::sqrt(r * r - across * across);
    const double slope = (q.z - p.z) / len;
    const double root = std::sqrt(1 + slope * slope);
    const double contact = along + rc * slope / root;
    if (contact < 0 || contact > len) return;
    best = std::max(best, p.z + slope * along + rc * root - r);
}

}  // namespace

TriangleMesh meshFromPaths(const std::vector<std::vector<Point3>>& paths)
{
    TriangleMesh m;
    if (paths.size() < 2) return m;
    const std::size_t n = paths.front().size();
    for (const auto& p : paths)
        if (p.size() != n) return m;
    for (const auto& p : paths) m.vertices.insert(m.vertices.end(), p.begin(), p.end());
    const int cols = static_cast<int>(n);
    for (int i = 0; i + 1 < static_cast<int>(paths.size()); ++i)
        for (int j = 0; j + 1 < cols; ++j) {
            const int a = i * cols + j, b = a + 1, c = a + cols + 1, d = a + cols;
            m.triangles.push_back({a, b, c});
            m.triangles.push_back({a, c, d});
        }
    return m;
}

TriangleMesh meshRuled(const RuledSurface& s, int alongRulings, int betweenRulings)
{
    return meshFromPaths(pathsOfRuled(s, alongRulings, betweenRulings));
}

double Cutter::heightAt(double d) const
{
    const double r = cornerRadius;
    const double flat = diameter / 2 - r;
    if (d <= flat) return 0.0;
    const double t = std::min(d - flat, r);
    return r - std::sqrt(std::max(0.0, r * r - t * t));
}

MeshIndex::MeshIndex(TriangleMesh mesh) : mesh_(std::move(mesh))
{
    if (mesh_.triangles.empty()) return;
    facets_.reserve(mesh_.triangles.size());
    for (const auto& t : mesh_.triangles) {
        const Point3& a = mesh_.vertices[static_cast<std::size_t>(t[0])];
        const Point3& b = mesh_.vertices[static_cast<std::size_t>(t[1])];
        const Point3& c = mesh_.vertices[static_cast<std::size_t>(t[2])];
        Facet f;
        double nx = (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
        double ny = (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
        double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (len > 0) {
            nx /= len, ny /= len, nz /= len;
            if (nz < 0) nx = -nx, ny = -ny, nz = -nz;
            f.nx = nx, f.ny = ny, f.nz = nz, f.d = nx * a.x + ny * a.y + nz * a.z;
        }
        f.zmax = std::max({a.z, b.z, c.z});
        f.x0 = std::min({a.x, b.x, c.x}), f.x1 = std::max({a.x, b.x, c.x});
        f.y0 = std::min({a.y, b.y, c.y}), f.y1 = std::max({a.y, b.y, c.y});
        facets_.push_back(f);
    }
    x0_ = y0_ = z0_ = std::numeric_limits<double>::infinity();
    x1_ = y1_ = z1_ = -std::numeric_limits<double>::infinity();
    for (const Point3& p : mesh_.vertices) {
        x0_ = std::min(x0_, p.x), x1_ = std::max(x1_, p.x);
        y0_ = std::min(y0_, p.y), y1_ = std::max(y1_, p.y);
        z0_ = std::min(z0_, p.z), z1_ = std::max(z1_, p.z);
    }
    // A cell of about twice the triangles' mean XY extent, at most 4 M cells.
    double extent = 0.0;
    for (const auto& t : mesh_.triangles) {
        const Point3 &a = mesh_.vertices[static_cast<std::size_t>(t[0])],
                     &b = mesh_.vertices[static_cast<std::size_t>(t[1])],
                     &c = mesh_.vertices[static_cast<std::size_t>(t[2])];
        extent += std::max({a.x, b.x, c.x}) - std::min({a.x, b.x, c.x}) + std::max({a.y, b.y, c.y}) -
                  std::min({a.y, b.y, c.y});
    }
    cell_ = std::max(1e-3, extent / static_cast<double>(mesh_.triangles.size()));
    const double w = std::max(x1_ - x0_, 1e-9), h = std::max(y1_ - y0_, 1e-9);
    while ((w / cell_ + 1) * (h / cell_ + 1) > 4e6) cell_ *= 1.5;
    nx_ = static_cast<int>(w / cell_) + 1;
    ny_ = static_cast<int>(h / cell_) + 1;
    std::vector<int> count(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
    const auto cellsOf = [&](const std::array<int, 3>& t, auto&& f) {
        const Point3 &a = mesh_.vertices[static_cast<std::size_t>(t[0])],
                     &b = mesh_.vertices[static_cast<std::size_t>(t[1])],
                     &c = mesh_.vertices[static_cast<std::size_t>(t[2])];
        const int i0 = std::clamp(static_cast<int>((std::min({a.x, b.x, c.x}) - x0_) / cell_), 0, nx_ - 1);
        const int i1 = std::clamp(static_cast<int>((std::max({a.x, b.x, c.x}) - x0_) / cell_), 0, nx_ - 1);
        const int j0 = std::clamp(static_cast<int>((std::min({a.y, b.y, c.y}) - y0_) / cell_), 0, ny_ - 1);
        const int j1 = std::clamp(static_cast<int>((std::max({a.y, b.y, c.y}) - y0_) / cell_), 0, ny_ - 1);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) f(j * nx_ + i);
    };
    for (const auto& t : mesh_.triangles) cellsOf(t, [&](int c) { ++count[static_cast<std::size_t>(c) + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    start_ = count;
    items_.resize(static_cast<std::size_t>(count.back()));
    std::vector<int> fill(count.begin(), count.end() - 1);
    cellTop_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), kNone);
    for (int k = 0; k < static_cast<int>(mesh_.triangles.size()); ++k)
        cellsOf(mesh_.triangles[static_cast<std::size_t>(k)], [&](int c) {
            items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(c)]++)] = k;
            double& top = cellTop_[static_cast<std::size_t>(c)];
            top = std::max(top, facets_[static_cast<std::size_t>(k)].zmax);
        });
}

DropCutter::DropCutter(const MeshIndex& index, Cutter cutter) : index_(&index), cutter_(cutter) {}

std::optional<double> DropCutter::noseZ(double x, double y)
{
    if (axisOver_ && !surfaceZ(x, y)) return std::nullopt;
    const TriangleMesh& m = index_->mesh();
    const double rmax = cutter_.diameter / 2;
    const double r = cutter_.cornerRadius;
    const double flat = rmax - r;
    double best = kNone;

    const bool ball = flat < 1e-12;
    const auto edge = [&](const Point3& p, const Point3& q) { noseOnEdge(cutter_, x, y, p, q, best); };
    const auto ballEdge = [&](const Point3& p, const Point3& q) { ballOnEdge(r, x, y, p, q, best); };
    const auto vertex = [&](const Point3& v) {
        const double d2 = (v.x - x) * (v.x - x) + (v.y - y) * (v.y - y);
        if (d2 > rmax * rmax || v.z <= best) return;
        best = std::max(best, v.z - cutter_.heightAt(std::sqrt(d2)));
    };

    const auto evaluate = [&](int t) {
        const MeshIndex::Facet& f = index_->facet(t);
        const auto& tri = m.triangles[static_cast<std::size_t>(t)];
        const Point3& a = m.vertices[static_cast<std::size_t>(tri[0])];
        const Point3& b = m.vertices[static_cast<std::size_t>(tri[1])];
        const Point3& c = m.vertices[static_cast<std::size_t>(tri[2])];
        // Face: the plane's contact, when it falls inside the triangle.
        if (f.nz > 1e-9) {
            const double nxy = std::sqrt(f.nx * f.nx + f.ny * f.ny);
            const double ux = nxy > 1e-12 ? f.nx / nxy : 0.0, uy = nxy > 1e-12 ? f.ny / nxy : 0.0;
            const double px = x - flat * ux - r * f.nx, py = y - flat * uy - r * f.ny;
            if (insideXY(px, py, a, b, c))
                best = std::max(best, (f.d + r - f.nx * (x - flat * ux) - f.ny * (y - flat * uy)) / f.nz - r);
        }
        vertex(a);
        vertex(b);
        vertex(c);
        if (ball) {
            ballEdge(a, b);
            ballEdge(b, c);
            ballEdge(c, a);
        } else {
            edge(a, b);
            edge(b, c);
            edge(c, a);
        }
    };

    // The most a triangle's contact could put the nose at: no point of it
    // is higher than its top, nor nearer the axis than its box, where the
    // cutter is already heightAt(that distance) above its nose; a cell's
    // the same of its triangles' highest top and its own box. A cell or
    // triangle whose bound the best contact so far reaches cannot raise it.
    // The cell with the highest bound first (most often the answer is in
    // it or near it), then the rest in any order (a sort costs more than it
    // saves): on a smooth surface a few triangles near the axis decide among
    // the hundreds under the disc. The answer is the same maximum as taking
    // every triangle.
    const auto bound = [&](double top, double d2) { return top - cutter_.heightAt(std::sqrt(d2)); };
    cells_.clear();
    index_->nearCells(x, y, rmax, [&](int cell, double d2, double top) {
        if (d2 <= rmax * rmax) cells_.push_back({bound(top, d2), cell});
    });
    const auto first = std::max_element(cells_.begin(), cells_.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
    if (first != cells_.end()) std::iter_swap(cells_.begin(), first);
    index_->newQuery(seen_, stamp_);
    for (const auto& [cellBound, cell] : cells_)
        for (const int t : index_->cellTriangles(cell)) {
            if (cellBound <= best) break;
            if (seen_[static_cast<std::size_t>(t)] == stamp_) continue;
            seen_[static_cast<std::size_t>(t)] = stamp_;
            const MeshIndex::Facet& f = index_->facet(t);
            if (f.zmax <= best) continue;
            const double dx = std::max({f.x0 - x, 0.0, x - f.x1}), dy = std::max({f.y0 - y, 0.0, y - f.y1});
            const double d2 = dx * dx + dy * dy;
            if (d2 > rmax * rmax || bound(f.zmax, d2) <= best) continue;
            evaluate(t);
        }
    if (best == kNone) return std::nullopt;
    return best;
}

std::optional<double> DropCutter::surfaceZ(double x, double y)
{
    const TriangleMesh& m = index_->mesh();
    double best = kNone;
    index_->near(x, y, 0.0, seen_, stamp_, [&](int t) {
        const auto& tri = m.triangles[static_cast<std::size_t>(t)];
        const Point3& a = m.vertices[static_cast<std::size_t>(tri[0])];
        const Point3& b = m.vertices[static_cast<std::size_t>(tri[1])];
        const Point3& c = m.vertices[static_cast<std::size_t>(tri[2])];
        const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (std::abs(det) < 1e-18) return;
        const double l1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
        const double l2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
        const double eps = 1e-12;
        if (l1 < -eps || l2 < -eps || l1 + l2 > 1 + eps) return;
        best = std::max(best, a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z));
    });
    if (best == kNone) return std::nullopt;
    return best;
}

}  // namespace taiwa::surface
