// The stock surface from the height field, the stock block, the tool solid,
// the pocket outlines.
#include "viz/solids.h"

#include "sim/cutter_profile.h"
#include "viz/palette.h"

#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

namespace taiwa::viz {

namespace {

vtkSmartPointer<vtkPolyData> withNormals(vtkPolyData* pd, double featureAngle)
{
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputData(pd);
    normals->SetFeatureAngle(featureAngle);
    normals->SplittingOn();
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    normals->Update();
    return normals->GetOutput();
}

void addQuad(vtkCellArray* cells, vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
    const vtkIdType ids[4] = {a, b, c, d};
    cells->InsertNextCell(4, ids);
}

}  // namespace

vtkSmartPointer<vtkPolyData> heightFieldSurface(const sim::HeightField& f)
{
    const int nx = f.columns(), ny = f.rows();
    const Stock& s = f.stock();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetName("Colors");
    colours->SetNumberOfComponents(3);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    auto addPoint = [&](double x, double y, double z, Rgb c) {
        colours->InsertNextTuple3(c.r, c.g, c.b);
        return points->InsertNextPoint(x, y, z);
    };
    // Top: one vertex per cell centre, the outer ones moved onto the stock's edge.
    auto vx = [&](int i) { return i == 0 ? s.x : i == nx - 1 ? s.x + s.width : f.centre(i, 0).x; };
    auto vy = [&](int j) { return j == 0 ? s.y : j == ny - 1 ? s.y + s.length : f.centre(0, j).y; };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            addPoint(vx(i), vy(j), f.at(i, j), f.at(i, j) > -1e-4 ? palette::kStock : palette::kMachined);
    auto top = [nx](int i, int j) { return static_cast<vtkIdType>(j) * nx + i; };
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) addQuad(polys, top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1));

    // Side walls from the top's edge down to the bottom, normals outward.
    const double zb = f.bottom();
    std::vector<vtkIdType> front(nx), back(nx), left(ny), right(ny);
    for (int i = 0; i < nx; ++i) {
        front[i] = addPoint(vx(i), s.y, zb, palette::kStock);
        back[i] = addPoint(vx(i), s.y + s.length, zb, palette::kStock);
    }
    for (int j = 0; j < ny; ++j) {
        left[j] = addPoint(s.x, vy(j), zb, palette::kStock);
        right[j] = addPoint(s.x + s.width, vy(j), zb, palette::kStock);
    }
    for (int i = 0; i + 1 < nx; ++i) {
        addQuad(polys, front[i], front[i + 1], top(i + 1, 0), top(i, 0));
        addQuad(polys, back[i + 1], back[i], top(i, ny - 1), top(i + 1, ny - 1));
    }
    for (int j = 0; j + 1 < ny; ++j) {
        addQuad(polys, left[j + 1], left[j], top(0, j), top(0, j + 1));
        addQuad(polys, right[j], right[j + 1], top(nx - 1, j + 1), top(nx - 1, j));
    }
    addQuad(polys, front[0], back[0], back[nx - 1], front[nx - 1]);  // bottom, facing down

    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    pd->GetPointData()->SetScalars(colours);
    return withNormals(pd, 60.0);
}

vtkSmartPointer<vtkPolyData> stockBlock(const Stock& s)
{
    auto cube = vtkSmartPointer<vtkCubeSource>::New();
    cube->SetBounds(s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0);
    cube->Update();
    return cube->GetOutput();
}

vtkSmartPointer<vtkPolyData> toolSolid(const Tool& tool)
{
    constexpr int kSegments = 40;
    const auto outline = sim::CutterProfile(tool).outline();
    auto points = vtkSmartPointer<vtkPoints>::New();
    for (const auto& [r, h] : outline)
        for (int a = 0; a < kSegments; ++a) {
            const double t = 2.0 * std::numbers::pi * a / kSegments;
            points->InsertNextPoint(r * std::cos(t), r * std::sin(t), h);
        }
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    auto id = [](std::size_t k, int a) { return static_cast<vtkIdType>(k * kSegments + a % kSegments); };
    for (std::size_t k = 0; k + 1 < outline.size(); ++k)
        for (int a = 0; a < kSegments; ++a) {
            if (outline[k].first == 0.0) {  // a cap around the axis: triangles
                const vtkIdType tri[3] = {id(k, a), id(k + 1, a + 1), id(k + 1, a)};
                polys->InsertNextCell(3, tri);
            } else if (outline[k + 1].first == 0.0) {
                const vtkIdType tri[3] = {id(k, a), id(k, a + 1), id(k + 1, a)};
                polys->InsertNextCell(3, tri);
            } else {
                addQuad(polys, id(k, a), id(k, a + 1), id(k + 1, a + 1), id(k + 1, a));
            }
        }
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    return withNormals(pd, 40.0);
}

namespace {

// The rounded quad as a closed polyline at height z: each corner's arc
// around the corner moved inward by the radius, from the outward normal of
// the side before it to that of the side after it (counter-clockwise).
void addRoundedQuad(vtkPoints* points, vtkCellArray* lines, const Quad& q, double z)
{
    const double r = std::max(q.cornerRadius, 0.0);
    const auto sharp = counterClockwise(q.corners);
    const auto centres = r > 0 ? offsetInward(Quad{sharp, q.cornerRadius}, r).corners : sharp;
    std::vector<vtkIdType> ids;
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 in = sharp[i] - sharp[(i + 3) % 4], out = sharp[(i + 1) % 4] - sharp[i];
        const double a0 = std::atan2(-in.x, in.y), a1raw = std::atan2(-out.x, out.y);  // outward normals
        double sweep = a1raw - a0;
        while (sweep < 0) sweep += 2 * std::numbers::pi;
        const int n = r > 0 ? std::max(1, static_cast<int>(std::ceil(sweep / (5.0 * std::numbers::pi / 180.0)))) : 0;
        for (int k = 0; k <= n; ++k) {
            const double a = a0 + sweep * k / std::max(n, 1);
            ids.push_back(points->InsertNextPoint(centres[i].x + r * std::cos(a), centres[i].y + r * std::sin(a), z));
        }
    }
    ids.push_back(ids.front());
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
}

}  // namespace

vtkSmartPointer<vtkPolyData> pocketOutlines(const std::vector<Step>& steps)
{
    std::map<int, const Step*> last;  // unit -> its last wall step
    for (const Step& s : steps) {
        if (!s.outline || s.kind == StepKind::PilotHole || s.kind == StepKind::InclinedFaceFinishing) continue;
        const Step*& best = last[s.unit];
        if (!best || s.wallAllowance < best->wallAllowance - 1e-9 ||
            (s.wallAllowance <= best->wallAllowance + 1e-9 && s.cutDepth > best->cutDepth))
            best = &s;
    }
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& [unit, s] : last) {
        (void)unit;
        const Quad& top = *s->outline;
        addRoundedQuad(points, lines, top, 0.0);
        const double inset = s->wallTaper > 0 ? s->cutDepth * tanDeg(s->wallTaper) : 0.0;
        const Quad floor = inset > 0 ? offsetInward(top, inset) : top;
        addRoundedQuad(points, lines, floor, -s->cutDepth);
    }
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetLines(lines);
    return pd;
}

}  // namespace taiwa::viz
