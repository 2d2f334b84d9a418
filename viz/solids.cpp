// The stock block, the tool solid, the pocket outlines, a lathe job's
// surfaces of revolution, the section face and the labelled axes (the stock
// surface and the colour map: viz/stock_surface.cpp).
#include "viz/solids.h"

#include "model/turned_geometry.h"
#include "sim/cutter_profile.h"
#include "turning/turn_tools.h"
#include "verify/deviation.h"
#include "viz/palette.h"

#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCubeSource.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
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

vtkSmartPointer<vtkPolyData> sectionCap(const sim::HeightField& f, const SectionPlane& plane, std::size_t maxSamples)
{
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    const double nl = std::hypot(plane.normal.x, plane.normal.y, plane.normal.z);
    if (!(nl > 0.0) || f.columns() <= 0) return pd;
    const double n[3] = {plane.normal.x / nl, plane.normal.y / nl, plane.normal.z / nl};
    // u across the plane, level where it can be; v = n x u.
    double u[3] = {-n[1], n[0], 0.0};
    double ul = std::hypot(u[0], u[1]);
    if (ul < 1e-9) {  // a level plane: u along X
        u[0] = 1.0;
        u[1] = 0.0;
        ul = 1.0;
    }
    for (double& c : u) c /= ul;
    const double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    const Stock& s = f.stock();
    const double o[3] = {plane.origin.x, plane.origin.y, plane.origin.z};
    // The stock's box seen in the plane's (a, b) coordinates.
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (const double x : {s.x, s.x + s.width})
        for (const double y : {s.y, s.y + s.length})
            for (const double z : {-s.height, 0.0}) {
                const double d[3] = {x - o[0], y - o[1], z - o[2]};
                const double a = d[0] * u[0] + d[1] * u[1] + d[2] * u[2], b = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
                a0 = std::min(a0, a);
                a1 = std::max(a1, a);
                b0 = std::min(b0, b);
                b1 = std::max(b1, b);
            }
    const double step =
        std::max(f.cellSize(), std::sqrt((a1 - a0) * (b1 - b0) / static_cast<double>(std::max<std::size_t>(maxSamples, 1))));
    const int na = std::max(1, static_cast<int>(std::ceil((a1 - a0) / step)));
    const int nb = std::max(1, static_cast<int>(std::ceil((b1 - b0) / step)));
    // A sample is in the material when it lies over the stock, above its
    // bottom and not above the stock's top there.
    const auto inside = [&](double a, double b) {
        const double x = o[0] + a * u[0] + b * v[0], y = o[1] + a * u[1] + b * v[1], z = o[2] + a * u[2] + b * v[2];
        return f.contains(x, y) && z >= f.bottom() - 1e-9 && z <= f.atPoint(x, y) + 1e-9;
    };
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    const auto at = [&](double a, double b) {
        return points->InsertNextPoint(o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]);
    };
    // Each row's runs of samples in the material, one quad a run.
    for (int jb = 0; jb < nb; ++jb) {
        const double b = b0 + (jb + 0.5) * step;
        int start = -1;
        for (int ia = 0; ia <= na; ++ia) {
            const bool in = ia < na && inside(a0 + (ia + 0.5) * step, b);
            if (in && start < 0) start = ia;
            if (in || start < 0) continue;
            const double aFrom = a0 + start * step, aTo = a0 + ia * step, bFrom = b - step / 2, bTo = b + step / 2;
            addQuad(polys, at(aFrom, bFrom), at(aTo, bFrom), at(aTo, bTo), at(aFrom, bTo));
            start = -1;
        }
    }
    pd->SetPoints(points);
    pd->SetPolys(polys);
    return pd;
}

vtkSmartPointer<vtkAxesActor> labelledAxes(double length, int fontSize, const char* x, const char* y, const char* z)
{
    auto axes = vtkSmartPointer<vtkAxesActor>::New();
    axes->SetTotalLength(length, length, length);
    axes->SetShaftTypeToLine();
    axes->SetXAxisLabelText(x);
    axes->SetYAxisLabelText(y);
    axes->SetZAxisLabelText(z);
    for (vtkCaptionActor2D* c : {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(), axes->GetZAxisCaptionActor2D()}) {
        c->GetTextActor()->SetTextScaleModeToNone();
        c->GetCaptionTextProperty()->SetFontSize(fontSize);
        c->GetCaptionTextProperty()->ShadowOff();
    }
    return axes;
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

// The rounded quad as a closed polyline at height z, its corner arcs
// within 10 µm (model/geometry.h's flatten).
void addRoundedQuad(vtkPoints* points, vtkCellArray* lines, const std::vector<Point2>& outline, double z)
{
    std::vector<vtkIdType> ids;
    for (const Point2 p : outline) ids.push_back(points->InsertNextPoint(p.x, p.y, z));
    ids.push_back(ids.front());
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
}

}  // namespace

vtkSmartPointer<vtkPolyData> pocketOutlines(const std::vector<Step>& steps, OutlineCache* cache)
{
    std::map<int, const Step*> last;  // unit -> its last wall step
    for (const Step& s : steps) {
        const MillingGeometry& g = millingOf(s);
        if (!g.outline || s.kind == StepKind::PilotHole || s.kind == StepKind::InclinedFaceFinishing) continue;
        const Step*& best = last[s.unit];
        if (!best || g.wallAllowance < millingOf(*best).wallAllowance - 1e-9 ||
            (g.wallAllowance <= millingOf(*best).wallAllowance + 1e-9 && g.cutDepth > millingOf(*best).cutDepth))
            best = &s;
    }
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    OutlineCache made;
    for (const auto& [unit, s] : last) {
        const MillingGeometry& g = millingOf(*s);
        const Quad& top = *g.outline;
        OutlineCache::Entry* e = nullptr;
        if (cache)
            if (auto it = cache->units.find(unit);
                it != cache->units.end() && it->second.top == top && it->second.depth == g.cutDepth && it->second.taper == g.wallTaper)
                e = &(made.units[unit] = std::move(it->second));
        if (!e) {
            e = &made.units[unit];
            e->top = top;
            e->depth = g.cutDepth;
            e->taper = g.wallTaper;
            e->topPoints = flatten(top, 0.01);
            const double inset = g.wallTaper > 0 ? g.cutDepth * tanDeg(g.wallTaper) : 0.0;
            e->floorPoints = inset > 0 ? flatten(offsetInward(top, inset), 0.01) : e->topPoints;
        }
        addRoundedQuad(points, lines, e->topPoints, 0.0);
        addRoundedQuad(points, lines, e->floorPoints, -g.cutDepth);
    }
    if (cache) *cache = std::move(made);
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetLines(lines);
    return pd;
}

vtkSmartPointer<vtkPolyData> revolvedChain(const std::vector<turning::Segment>& chain, bool half)
{
    // The chain as points in (z, r), arcs every 3°.
    std::vector<std::pair<double, double>> profile;
    for (const auto& s : chain) {
        const int n = s.arc ? std::max(2, static_cast<int>(std::ceil(turning::sweep(s) / (3.0 * std::numbers::pi / 180.0)))) : 1;
        const double len = turning::length(s);
        for (int i = profile.empty() ? 0 : 1; i <= n; ++i) {
            const turning::ZR p = turning::pointAt(s, len * i / n);
            profile.emplace_back(p.z, p.r);
        }
    }
    // A full turn in kTurn columns (the last joining the first), or a half
    // turn from -90° to 90° in kTurn / 2 + 1 columns.
    constexpr int kTurn = 72;
    const int columns = half ? kTurn / 2 + 1 : kTurn;
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& [z, r] : profile)
        for (int k = 0; k < columns; ++k) {
            const double a = half ? std::numbers::pi * (static_cast<double>(k) / (columns - 1) - 0.5) : 2.0 * std::numbers::pi * k / kTurn;
            points->InsertNextPoint(z, r * std::cos(a), r * std::sin(a));
        }
    for (std::size_t i = 0; i + 1 < profile.size(); ++i)
        for (int k = 0; k < (half ? columns - 1 : kTurn); ++k) {
            const auto at = [&](std::size_t row, int col) { return static_cast<vtkIdType>(row * columns + (col % columns)); };
            addQuad(cells, at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1));
        }
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(cells);
    return withNormals(pd, 30.0);
}

std::vector<turning::ZR> latheToolOutline(const Tool& tool, const TurnStep& step)
{
    using turning::ZR;
    const bool inside = step.side == turning::ProfileSide::Inner;
    if (const auto g = turning::insertGeometry(tool)) {
        std::vector<ZR> outline = turning::insertShape(*g);
        for (ZR& p : outline) p = p - step.tipFromCentre;  // about the programmed point
        return outline;
    }
    if (tool.turning.width > 0) {
        const double reach = tool.turning.maxDepth > 0 ? tool.turning.maxDepth : 4.0 * tool.turning.width;
        return turning::bladeShape(tool.turning.width, reach, inside);
    }
    if (tool.type == ToolType::Drill || tool.type == ToolType::CentreDrill) {
        // Its half above the axis: the point, then the body back along +Z.
        const double r = tool.radius();
        const double point = r / std::tan(tool.pointAngle / 2.0 * std::numbers::pi / 180.0);
        const double body = tool.fluteLength > 0 ? tool.fluteLength : 4.0 * tool.diameter;
        return {{0.0, 0.0}, {point, r}, {point + body, r}, {point + body, 0.0}};
    }
    return {};
}

vtkSmartPointer<vtkPolyData> sectionFace(const std::vector<turning::ZR>& outline, double y)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->InsertNextCell(static_cast<int>(outline.size()));
    for (const auto& p : outline) polys->InsertCellPoint(points->InsertNextPoint(p.z, y, p.r));
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    return pd;
}

}  // namespace taiwa::viz
