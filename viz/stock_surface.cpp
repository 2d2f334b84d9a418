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
// processor (viz/surface_light.h). The top is made in bands of rows on
// threads of their own (plate.taiwa, 480,000 cells: 6 ms on one core).
#include "viz/solids.h"

#include "verify/deviation.h"
#include "viz/palette.h"
#include "viz/surface_light.h"

#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <future>
#include <map>
#include <utility>
#include <vector>

namespace taiwa::viz {

namespace {

// A part of the stock surface: quads with four points of their own (so
// that viz/surface_light.h can light each as one flat face), in their
// corners' colours, with their outward normals.
struct SurfacePart {
    std::vector<float> points;          // x, y, z per point
    std::vector<unsigned char> colours;  // r, g, b per point
    std::vector<float> normals;         // x, y, z per quad

    struct Corner {
        double x, y, z;
        Rgb c;
    };
    // Counter-clockwise seen from outside; the normal from the diagonals.
    void quad(const Corner& a, const Corner& b, const Corner& c, const Corner& d)
    {
        const double u[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
        const double v[3] = {d.x - b.x, d.y - b.y, d.z - b.z};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double k : n) normals.push_back(static_cast<float>(len > 0 ? k / len : k));
        for (const Corner* q : {&a, &b, &c, &d}) {
            points.insert(points.end(), {static_cast<float>(q->x), static_cast<float>(q->y), static_cast<float>(q->z)});
            colours.insert(colours.end(), {q->c.r, q->c.g, q->c.b});
        }
    }
};

// The parts joined into one surface: the quads' points and base colours
// (kBaseColours, copied to the shown "Colors" until it is lit) and
// normals (kQuadNormals).
vtkSmartPointer<vtkPolyData> joined(const std::vector<SurfacePart>& parts)
{
    std::size_t nPoints = 0;
    for (const SurfacePart& p : parts) nPoints += p.points.size() / 3;
    const auto quads = static_cast<vtkIdType>(nPoints / 4);
    auto xyz = vtkSmartPointer<vtkFloatArray>::New();
    xyz->SetNumberOfComponents(3);
    xyz->SetNumberOfTuples(static_cast<vtkIdType>(nPoints));
    auto base = vtkSmartPointer<vtkUnsignedCharArray>::New();
    base->SetName(kBaseColours);
    base->SetNumberOfComponents(3);
    base->SetNumberOfTuples(static_cast<vtkIdType>(nPoints));
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName(kQuadNormals);
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(quads);
    float* to = xyz->GetPointer(0);
    unsigned char* colourTo = base->GetPointer(0);
    float* normalTo = normals->GetPointer(0);
    for (const SurfacePart& p : parts) {
        to = std::copy(p.points.begin(), p.points.end(), to);
        colourTo = std::copy(p.colours.begin(), p.colours.end(), colourTo);
        normalTo = std::copy(p.normals.begin(), p.normals.end(), normalTo);
    }
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfTuples(quads + 1);
    for (vtkIdType q = 0; q <= quads; ++q) offsets->SetValue(q, 4 * q);
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfTuples(4 * quads);
    for (vtkIdType k = 0; k < 4 * quads; ++k) connectivity->SetValue(k, k);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->SetData(offsets, connectivity);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(xyz);
    auto shown = vtkSmartPointer<vtkUnsignedCharArray>::New();
    shown->DeepCopy(base);
    shown->SetName("Colors");
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    pd->GetPointData()->SetScalars(shown);
    pd->GetPointData()->AddArray(base);
    pd->GetCellData()->AddArray(normals);
    return pd;
}

// Runs f(0) .. f(n - 1), each on a thread of its own but the first.
template <class F>
void inParallel(int n, const F& f)
{
    std::vector<std::future<void>> running;
    for (int k = 1; k < n; ++k) running.push_back(std::async(std::launch::async, f, k));
    f(0);
    for (auto& r : running) r.get();
}

// A height field's vertices for its surface: each one's height and colour
// as one key (vertices alike have equal keys), its corner on the top, and
// the runs of alike vertices the quads of the top and the walls are merged
// along.
struct Vertices {
    const sim::HeightField& f;
    const std::vector<std::uint64_t>& keys;
    int nx, ny, qx;  // vertices per row and column, quads per row
    const Stock& s = f.stock();
    const std::vector<float>& z = f.heights();

    float Z(int i, int j) const { return z[static_cast<std::size_t>(j) * nx + i]; }
    std::uint64_t K(int i, int j) const { return keys[static_cast<std::size_t>(j) * nx + i]; }
    Rgb C(int i, int j) const
    {
        const std::uint64_t k = K(i, j);
        return Rgb{static_cast<unsigned char>(k >> 16), static_cast<unsigned char>(k >> 8), static_cast<unsigned char>(k)};
    }
    double vx(int i) const { return i == 0 ? s.x : i == nx - 1 ? s.x + s.width : f.centre(i, 0).x; }
    double vy(int j) const { return j == 0 ? s.y : j == ny - 1 ? s.y + s.length : f.centre(0, j).y; }
    SurfacePart::Corner top(int i, int j) const { return SurfacePart::Corner{vx(i), vy(j), Z(i, j), C(i, j)}; }
    // Vertex (k, j) is like (i, j), and (k, j + 1) like (i, j + 1): quad k
    // continues the row run that quad i starts.
    bool likeX(int i, int k, int j) const { return K(k, j) == K(i, j) && K(k, j + 1) == K(i, j + 1); }
    bool likeY(int i, int j, int k) const { return K(i, k) == K(i, j) && K(i + 1, k) == K(i + 1, j); }

    // The top's quad rows j0..j1-1 into `out`.
    void topBand(int j0, int j1, SurfacePart& out) const
    {
        // The quad of vertices i0..i1 by ja..jb, counter-clockwise from above.
        const auto quad = [&](int i0, int i1, int ja, int jb) { out.quad(top(i0, ja), top(i1, ja), top(i1, jb), top(i0, jb)); };
        std::vector<char> done(static_cast<std::size_t>(std::max(qx, 0)) * std::max(j1 - j0, 0), 0);
        const auto isDone = [&](int i, int j) -> char& { return done[static_cast<std::size_t>(j - j0) * qx + i]; };
        // Flat row runs still growing downward: (i0, i1) -> first row, last row.
        struct Open {
            int j0, last;
        };
        std::map<std::pair<int, int>, Open> open;
        const auto close = [&](const std::pair<int, int>& key, const Open& o) { quad(key.first, key.second, o.j0, o.last + 1); };
        for (int j = j0; j < j1; ++j) {
            for (int i = 0; i < qx;) {
                if (!likeX(i, i + 1, j)) {  // not level along x: the column pass
                    ++i;
                    continue;
                }
                int k = i + 1;  // the run's quads are i..k-1, its vertices i..k
                while (k < qx && likeX(i, k + 1, j)) ++k;
                for (int q = i; q < k; ++q) isDone(q, j) = 1;
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
            for (int j = j0; j < j1;) {
                if (isDone(i, j)) {
                    ++j;
                    continue;
                }
                int k = j + 1;
                if (likeY(i, j, j + 1))
                    while (k < j1 && !isDone(i, k) && likeY(i, j, k + 1)) ++k;
                quad(i, i + 1, j, k);
                j = k;
            }
    }

    // Side walls from the top's edge down to the bottom, normals outward. A
    // run of edge vertices at one height and in one colour is one quad: an
    // uncut side is one quad, not a sliver per cell (thousands of them cost
    // a software renderer as much as the whole top).
    void sides(SurfacePart& out) const
    {
        const double zb = f.bottom();
        const auto low = [&](double x, double y) { return SurfacePart::Corner{x, y, zb, palette::kStock}; };
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
        const double xEnd = s.x + s.width, yEnd = s.y + s.length;
        runs(nx, alongX(0), [&](int a, int b) { out.quad(low(vx(a), s.y), low(vx(b), s.y), top(b, 0), top(a, 0)); });
        runs(nx, alongX(ny - 1), [&](int a, int b) { out.quad(low(vx(b), yEnd), low(vx(a), yEnd), top(a, ny - 1), top(b, ny - 1)); });
        runs(ny, alongY(0), [&](int a, int b) { out.quad(low(s.x, vy(b)), low(s.x, vy(a)), top(0, a), top(0, b)); });
        runs(ny, alongY(nx - 1), [&](int a, int b) { out.quad(low(xEnd, vy(a)), low(xEnd, vy(b)), top(nx - 1, b), top(nx - 1, a)); });
        // The bottom, facing down.
        out.quad(low(s.x, s.y), low(s.x, yEnd), low(xEnd, yEnd), low(xEnd, s.y));
    }
};

// The closed surface of a height field, each top vertex in the colour
// colourOf(i, j) gives its cell. The top is made in kSurfaceBands bands of
// rows at once (a quad merged within its band only).
template <class ColourOf>
vtkSmartPointer<vtkPolyData> surfaceOf(const sim::HeightField& f, const ColourOf& colourOf)
{
    const int nx = f.columns(), ny = f.rows();
    const std::vector<float>& z = f.heights();
    const int qx = nx - 1, qy = ny - 1;  // quads per row and column
    const int bands = qy >= kSurfaceBandRows * kSurfaceBands ? kSurfaceBands : 1;
    // Each vertex's height and colour as one key: vertices alike have equal
    // keys (+ 0.0f: -0 is 0).
    std::vector<std::uint64_t> keys(static_cast<std::size_t>(nx) * ny);
    inParallel(bands, [&](int band) {
        for (int j = ny * band / bands; j < ny * (band + 1) / bands; ++j)
            for (int i = 0; i < nx; ++i) {
                const std::size_t v = static_cast<std::size_t>(j) * nx + i;
                const Rgb c = colourOf(i, j);
                keys[v] = static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(z[v] + 0.0f)) << 32 |
                          static_cast<std::uint64_t>(c.r) << 16 | static_cast<std::uint64_t>(c.g) << 8 | c.b;
            }
    });
    const Vertices vertices{f, keys, nx, ny, qx};
    std::vector<SurfacePart> parts(static_cast<std::size_t>(bands) + 1);
    inParallel(bands, [&](int band) {
        vertices.topBand(qy * band / bands, qy * (band + 1) / bands, parts[static_cast<std::size_t>(band)]);
    });
    vertices.sides(parts.back());
    return joined(parts);
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
