// The machining surface as triangles, tessellated once, and the drop-cutter
// that finds the tool-nose points on it (docs/surfaces.md): a ball or
// bull-nose end mill lowered along the tool axis (−Z) until it touches the
// first triangle. A uniform grid over XY indexes the triangles, so a drop
// looks only at those under the tool's disc, and of those only at the cells
// and triangles high enough to raise the contact found so far. No
// OpenCASCADE in the hot loop: surfaces from OpenCASCADE (surface_curves.h)
// are tessellated here once.
#pragma once

#include "model/toolpath.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace taiwa::surface {

struct RuledSurface;

struct TriangleMesh {
    std::vector<Point3> vertices;
    std::vector<std::array<int, 3>> triangles;  // indices into vertices
};

// A surface given as point-sequence paths (second abstract): paths[i][j],
// every path with the same number of points, neighbouring paths side by
// side; each quad of four neighbours becomes two triangles. No triangles
// for fewer than two paths or paths of different lengths.
TriangleMesh meshFromPaths(const std::vector<std::vector<Point3>>& paths);
// A ruled surface, each ruling divided into `alongRulings` pieces and each
// piece between rulings into `betweenRulings` (the bilinear patches' twist
// is followed to within their sag).
TriangleMesh meshRuled(const RuledSurface& s, int alongRulings, int betweenRulings);

// The tool's shape: a ball end mill has cornerRadius = diameter / 2, a
// bull-nose end mill 0 < cornerRadius < diameter / 2. The tool nose is its
// lowest point on the axis.
struct Cutter {
    double diameter = 10.0;
    double cornerRadius = 5.0;
    // How far above the nose the cutter's surface is at `d` from its axis
    // (d ≤ diameter / 2).
    double heightAt(double d) const;
};

// The triangles indexed by a uniform grid over XY (built once; queries do
// not change it). The cell is about the triangles' mean size.
class MeshIndex {
public:
    explicit MeshIndex(TriangleMesh mesh);
    const TriangleMesh& mesh() const { return mesh_; }
    double minX() const { return x0_; }
    double minY() const { return y0_; }
    double maxX() const { return x1_; }
    double maxY() const { return y1_; }
    double minZ() const { return z0_; }
    double maxZ() const { return z1_; }
    // Calls f(triangle index) once for each triangle whose XY box meets the
    // box [x − r, x + r] × [y − r, y + r]. `seen` is the caller's scratch.
    template <class F>
    void near(double x, double y, double r, std::vector<std::uint32_t>& seen, std::uint32_t& stamp, F&& f) const;
    // Calls f(cell, squared XY distance from (x, y) to the cell's box, the
    // highest top of the cell's triangles) for each non-empty cell meeting
    // the box [x − r, x + r] × [y − r, y + r]; cellTriangles(cell) lists the
    // triangles whose XY box meets the cell (a triangle may be in several).
    template <class F>
    void nearCells(double x, double y, double r, F&& f) const;
    // A caller's scratch made ready for a query that visits each triangle
    // once: sized to the triangles, and `stamp` one no triangle has yet
    // (a triangle is seen when seen[t] == stamp).
    void newQuery(std::vector<std::uint32_t>& seen, std::uint32_t& stamp) const
    {
        if (seen.size() != mesh_.triangles.size()) seen.assign(mesh_.triangles.size(), 0);
        if (++stamp == 0) {
            std::fill(seen.begin(), seen.end(), 0);
            stamp = 1;
        }
    }
    std::span<const int> cellTriangles(int cell) const
    {
        const auto c = static_cast<std::size_t>(cell);
        return {items_.data() + start_[c], static_cast<std::size_t>(start_[c + 1] - start_[c])};
    }

    // What the drop-cutter reads of a triangle, computed once: its unit
    // normal (nz ≥ 0; 0 for a degenerate one), its plane's n·p, its highest
    // Z and its XY box.
    struct Facet {
        double nx = 0, ny = 0, nz = 0, d = 0, zmax = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    };
    const Facet& facet(int t) const { return facets_[static_cast<std::size_t>(t)]; }

private:
    std::vector<Facet> facets_;
    TriangleMesh mesh_;
    double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0, z0_ = 0, z1_ = 0, cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<int> start_;  // cell c holds items_[start_[c] .. start_[c + 1])
    std::vector<int> items_;
    std::vector<double> cellTop_;  // the highest triangle top of each cell (−∞: empty)
};

// A drop-cutter over one indexed surface: the tool-nose height at (x, y)
// where the cutter, lowered along −Z, first touches a triangle (vertex, edge
// or face); nothing when no triangle lies under its disc. Not for sharing
// between threads (it keeps scratch space).
class DropCutter {
public:
    DropCutter(const MeshIndex& index, Cutter cutter);
    std::optional<double> noseZ(double x, double y);
    // With `on`, noseZ gives nothing where the tool axis is not over the
    // surface (surfaceZ has nothing there): the cutter never hangs over the
    // surface's edge, where its nose would go below the edge by up to its
    // corner radius (docs/surfaces.md, the sample's 2.68 mm below its edge).
    void keepAxisOverSurface(bool on) { axisOver_ = on; }
    // The surface's own height at (x, y) (a point dropped, the highest
    // triangle over it), nothing outside the surface.
    std::optional<double> surfaceZ(double x, double y);
    const Cutter& cutter() const { return cutter_; }
    const MeshIndex& index() const { return *index_; }

private:
    const MeshIndex* index_;
    Cutter cutter_;
    bool axisOver_ = false;
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
    std::vector<std::pair<double, int>> cells_;  // (the most a cell's triangles could raise the nose to, cell)
};

template <class F>
void MeshIndex::near(double x, double y, double r, std::vector<std::uint32_t>& seen, std::uint32_t& stamp,
                     F&& f) const
{
    if (start_.empty() || x + r < x0_ || x - r > x1_ || y + r < y0_ || y - r > y1_) return;
    newQuery(seen, stamp);
    const auto clampi = [](int v, int hi) { return v < 0 ? 0 : v > hi ? hi : v; };
    const int i0 = clampi(static_cast<int>((x - r - x0_) / cell_), nx_ - 1);
    const int i1 = clampi(static_cast<int>((x + r - x0_) / cell_), nx_ - 1);
    const int j0 = clampi(static_cast<int>((y - r - y0_) / cell_), ny_ - 1);
    const int j1 = clampi(static_cast<int>((y + r - y0_) / cell_), ny_ - 1);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const int c = j * nx_ + i;
            for (int k = start_[static_cast<std::size_t>(c)]; k < start_[static_cast<std::size_t>(c) + 1]; ++k) {
                const int t = items_[static_cast<std::size_t>(k)];
                if (seen[static_cast<std::size_t>(t)] == stamp) continue;
                seen[static_cast<std::size_t>(t)] = stamp;
                f(t);
            }
        }
}

template <class F>
void MeshIndex::nearCells(double x, double y, double r, F&& f) const
{
    if (start_.empty() || x + r < x0_ || x - r > x1_ || y + r < y0_ || y - r > y1_) return;
    const auto clampi = [](int v, int hi) { return v < 0 ? 0 : v > hi ? hi : v; };
    const int i0 = clampi(static_cast<int>((x - r - x0_) / cell_), nx_ - 1);
    const int i1 = clampi(static_cast<int>((x + r - x0_) / cell_), nx_ - 1);
    const int j0 = clampi(static_cast<int>((y - r - y0_) / cell_), ny_ - 1);
    const int j1 = clampi(static_cast<int>((y + r - y0_) / cell_), ny_ - 1);
    for (int j = j0; j <= j1; ++j) {
        const double cy0 = y0_ + j * cell_, dy = std::max({cy0 - y, 0.0, y - (cy0 + cell_)});
        for (int i = i0; i <= i1; ++i) {
            const int c = j * nx_ + i;
            if (start_[static_cast<std::size_t>(c)] == start_[static_cast<std::size_t>(c) + 1]) continue;
            const double cx0 = x0_ + i * cell_, dx = std::max({cx0 - x, 0.0, x - (cx0 + cell_)});
            f(c, dx * dx + dy * dy, cellTop_[static_cast<std::size_t>(c)]);
        }
    }
}

}  // namespace taiwa::surface
