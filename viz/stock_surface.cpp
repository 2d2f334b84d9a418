// The stock surface of a height field (the simulated stock, the
// verification's colour map): a vertex per cell centre, the outer ones on the
// stock's edges, side walls down to the bottom and the bottom, as few quads
// as show it exactly. A software renderer (Mesa's llvmpipe) pays about half a
// microsecond per triangle, so a surface of tens of thousands of slivers
// cost a frame more than all else in it. Quads between four vertices are
// merged where the merged quad is the same surface with the same colours:
//   - along a row, a run of quads each level along x (front and back edge
//     each at one height and in one colour) and alike: a pocket's floor row,
//     or a wall parallel to x, is one quad;
//   - such runs that are flat and alike in consecutive rows: one rectangle;
//   - along a column, the same for quads level along y (walls parallel to y);
//   - on the sides, a run of edge vertices at one height and colour.
// Every merged edge is a straight line through the vertices beside it at
// that height, so the finer quads beside it meet it without a gap. Each
// quad has four vertices of its own and is lit as one flat face on the
// processor (viz/surface_light.h).
#include "viz/solids.h"

#include "verify/deviation.h"
#include "viz/palette.h"
#include "viz/surface_light.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace taiwa::viz {

namespace {

// Builds the stock surface: each quad with four points of its own (so
// that viz/surface_light.h can light it as one flat face), in the colours
// of the corners it was given (kBaseColours, copied to the shown "Colors"
// until it is lit), and its outward normal (kQuadNormals).
class SurfaceBuilder {
public:
    SurfaceBuilder()
    {
        colours_->SetName("Colors");
        colours_->SetNumberOfComponents(3);
        base_->SetName(kBaseColours);
        base_->SetNumberOfComponents(3);
        normals_->SetName(kQuadNormals);
        normals_->SetNumberOfComponents(3);
    }
    // A corner quads are made of.
    int point(double x, double y, double z, Rgb c)
    {
        corners_.push_back(Corner{{x, y, z}, c});
        return static_cast<int>(corners_.size()) - 1;
    }
    // Counter-clockwise seen from outside; the normal from the diagonals.
    void quad(int a, int b, int c, int d)
    {
        const auto& pa = corners_[static_cast<std::size_t>(a)].p;
        const auto& pb = corners_[static_cast<std::size_t>(b)].p;
        const auto& pc = corners_[static_cast<std::size_t>(c)].p;
        const auto& pd = corners_[static_cast<std::size_t>(d)].p;
        const double u[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
        const double v[3] = {pd[0] - pb[0], pd[1] - pb[1], pd[2] - pb[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0)
            for (double& k : n) k /= len;
        normals_->InsertNextTuple(n);
        vtkIdType ids[4];
        int k = 0;
        for (int corner : {a, b, c, d}) {
            const Corner& q = corners_[static_cast<std::size_t>(corner)];
            ids[k++] = points_->InsertNextPoint(q.p.data());
            base_->InsertNextTuple3(q.c.r, q.c.g, q.c.b);
        }
        polys_->InsertNextCell(4, ids);
    }
    vtkSmartPointer<vtkPolyData> polyData()
    {
        colours_->DeepCopy(base_);
        colours_->SetName("Colors");
        auto pd = vtkSmartPointer<vtkPolyData>::New();
        pd->SetPoints(points_);
        pd->SetPolys(polys_);
        pd->GetPointData()->SetScalars(colours_);
        pd->GetPointData()->AddArray(base_);
        pd->GetCellData()->AddArray(normals_);
        return pd;
    }

private:
    struct Corner {
        std::array<double, 3> p;
        Rgb c;
    };
    std::vector<Corner> corners_;
    vtkNew<vtkPoints> points_;
    vtkNew<vtkUnsignedCharArray> colours_, base_;
    vtkNew<vtkFloatArray> normals_;
    vtkNew<vtkCellArray> polys_;
};

// The closed surface of a height field, each top vertex in the colour
// colourOf(i, j) gives its cell.
template <class ColourOf>
vtkSmartPointer<vtkPolyData> surfaceOf(const sim::HeightField& f, const ColourOf& colourOf)
{
    const int nx = f.columns(), ny = f.rows();
    const Stock& s = f.stock();
    const std::vector<float>& z = f.heights();
    // Each vertex's height and colour as one key: vertices alike have equal
    // keys (+ 0.0f: -0 is 0).
    std::vector<std::uint64_t> keys(static_cast<std::size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::size_t v = static_cast<std::size_t>(j) * nx + i;
            const Rgb c = colourOf(i, j);
            keys[v] = static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(z[v] + 0.0f)) << 32 |
                      static_cast<std::uint64_t>(c.r) << 16 | static_cast<std::uint64_t>(c.g) << 8 | c.b;
        }
    const auto Z = [&](int i, int j) { return z[static_cast<std::size_t>(j) * nx + i]; };
    const auto K = [&](int i, int j) { return keys[static_cast<std::size_t>(j) * nx + i]; };
    const auto C = [&](int i, int j) {
        const std::uint64_t k = K(i, j);
        return Rgb{static_cast<unsigned char>(k >> 16), static_cast<unsigned char>(k >> 8), static_cast<unsigned char>(k)};
    };
    SurfaceBuilder out;
    auto vx = [&](int i) { return i == 0 ? s.x : i == nx - 1 ? s.x + s.width : f.centre(i, 0).x; };
    auto vy = [&](int j) { return j == 0 ? s.y : j == ny - 1 ? s.y + s.length : f.centre(0, j).y; };
    std::vector<int> ids(static_cast<std::size_t>(nx) * ny, -1);
    auto top = [&](int i, int j) {
        int& id = ids[static_cast<std::size_t>(j) * nx + i];
        if (id < 0) id = out.point(vx(i), vy(j), Z(i, j), C(i, j));
        return id;
    };
    // The quad of vertices i0..i1 by j0..j1, counter-clockwise from above.
    const auto quad = [&](int i0, int i1, int j0, int j1) { out.quad(top(i0, j0), top(i1, j0), top(i1, j1), top(i0, j1)); };

    // Vertex (k, j) is like (i, j), and (k, j + 1) like (i, j + 1): quad k
    // continues the row run that quad i starts.
    const auto likeX = [&](int i, int k, int j) { return K(k, j) == K(i, j) && K(k, j + 1) == K(i, j + 1); };
    const auto likeY = [&](int i, int j, int k) { return K(i, k) == K(i, j) && K(i + 1, k) == K(i + 1, j); };
    const int qx = nx - 1, qy = ny - 1;  // quads per row and column
    std::vector<char> done(static_cast<std::size_t>(std::max(qx, 0)) * std::max(qy, 0), 0);
    // Flat row runs still growing downward: (i0, i1) -> first row, last row.
    struct Open {
        int j0, last;
    };
    std::map<std::pair<int, int>, Open> open;
    const auto close = [&](const std::pair<int, int>& key, const Open& o) { quad(key.first, key.second, o.j0, o.last + 1); };
    for (int j = 0; j < qy; ++j) {
        for (int i = 0; i < qx;) {
            if (!likeX(i, i + 1, j)) {  // not level along x: the column pass
                ++i;
                continue;
            }
            int k = i + 1;  // the run's quads are i..k-1, its vertices i..k
            while (k < qx && likeX(i, k + 1, j)) ++k;
            for (int q = i; q < k; ++q) done[static_cast<std::size_t>(j) * qx + q] = 1;
            const bool flat = K(i, j) == K(i, j + 1);
            const std::pair key{i, k};
            auto it = open.find(key);
            if (flat && it != open.end() && it->second.last == j - 1 && K(i, it->second.j0) == K(i, j)) {
                it->second.last = j;
            } else if (flat) {
                if (it != open.end()) close(key, it->second);
                open[key] = Open{j, j};
            } else {
                quad(i, k, j, j + 1);
            }
            i = k;
        }
        for (auto it = open.begin(); it != open.end();) {
            if (it->second.last == j) {
                ++it;
                continue;
            }
            close(it->first, it->second);
            it = open.erase(it);
        }
    }
    for (const auto& [key, o] : open) close(key, o);
    // What is left: runs down a column of quads level along y, or single quads.
    for (int i = 0; i < qx; ++i)
        for (int j = 0; j < qy;) {
            if (done[static_cast<std::size_t>(j) * qx + i]) {
                ++j;
                continue;
            }
            int k = j + 1;
            if (likeY(i, j, j + 1))
                while (k < qy && !done[static_cast<std::size_t>(k) * qx + i] && likeY(i, j, k + 1)) ++k;
            quad(i, i + 1, j, k);
            j = k;
        }

    // Side walls from the top's edge down to the bottom, normals outward. A
    // run of edge vertices at one height and in one colour is one quad: an
    // uncut side is one quad, not a sliver per cell (thousands of them cost
    // a software renderer as much as the whole top).
    const double zb = f.bottom();
    std::vector<int> front(nx, -1), back(nx, -1), left(ny, -1), right(ny, -1);
    const auto bottom = [&](std::vector<int>& side, int k, double x, double y) {
        if (side[static_cast<std::size_t>(k)] < 0) side[static_cast<std::size_t>(k)] = out.point(x, y, zb, palette::kStock);
        return side[static_cast<std::size_t>(k)];
    };
    // The side's n edge vertices, vertex k at cell (i, j) = at(k): each run
    // k0..k1 as wall(k0, k1).
    const auto runs = [&](int n, const auto& at, const auto& wall) {
        const auto same = [&](int a, int b) {
            const auto [ia, ja] = at(a);
            const auto [ib, jb] = at(b);
            return K(ia, ja) == K(ib, jb);
        };
        for (int k0 = 0; k0 + 1 < n;) {
            int k1 = k0 + 1;
            if (same(k0, k1))
                while (k1 + 1 < n && same(k0, k1 + 1)) ++k1;
            wall(k0, k1);
            k0 = k1;
        }
    };
    const auto alongX = [](int j) { return [j](int i) { return std::pair{i, j}; }; };
    const auto alongY = [](int i) { return [i](int j) { return std::pair{i, j}; }; };
    runs(nx, alongX(0), [&](int a, int b) {
        out.quad(bottom(front, a, vx(a), s.y), bottom(front, b, vx(b), s.y), top(b, 0), top(a, 0));
    });
    runs(nx, alongX(ny - 1), [&](int a, int b) {
        out.quad(bottom(back, b, vx(b), s.y + s.length), bottom(back, a, vx(a), s.y + s.length), top(a, ny - 1), top(b, ny - 1));
    });
    runs(ny, alongY(0), [&](int a, int b) {
        out.quad(bottom(left, b, s.x, vy(b)), bottom(left, a, s.x, vy(a)), top(0, a), top(0, b));
    });
    runs(ny, alongY(nx - 1), [&](int a, int b) {
        out.quad(bottom(right, a, s.x + s.width, vy(a)), bottom(right, b, s.x + s.width, vy(b)), top(nx - 1, b), top(nx - 1, a));
    });
    // The bottom, facing down.
    out.quad(bottom(front, 0, s.x, s.y), bottom(back, 0, s.x, s.y + s.length), bottom(back, nx - 1, s.x + s.width, s.y + s.length),
             bottom(front, nx - 1, s.x + s.width, s.y));
    return out.polyData();
}

Rgb bandColour(verify::DeviationBand b)
{
    using B = verify::DeviationBand;
    switch (b) {
    case B::Untouched: return palette::kStock;
    case B::Gouge: return palette::kGouge;
    case B::AtSize: return palette::kAtSize;
    case B::RestThin: return palette::kRestThin;
    case B::RestMedium: return palette::kRestMedium;
    case B::RestThick: return palette::kRestThick;
    }
    return palette::kStock;
}

}  // namespace

vtkSmartPointer<vtkPolyData> heightFieldSurface(const sim::HeightField& f, const sim::HeightField* before)
{
    if (before && !(before->columns() == f.columns() && before->rows() == f.rows())) before = nullptr;
    return surfaceOf(f, [&](int i, int j) {
        const double h = f.at(i, j);
        if (before && h < before->at(i, j) - 1e-4) return palette::kRemoved;  // cut by the step: lower than before it
        return h > -1e-4 ? palette::kStock : palette::kMachined;
    });
}

vtkSmartPointer<vtkPolyData> deviationSurface(const verify::DeviationMap& map)
{
    const int nx = map.stock.columns();
    return surfaceOf(map.stock, [&](int i, int j) { return bandColour(map.band[static_cast<std::size_t>(j) * nx + i]); });
}


}  // namespace taiwa::viz
