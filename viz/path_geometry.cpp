// Conversion of core tool paths into VTK lines.
#include "viz/path_geometry.h"

#include "sim/path_samples.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

namespace taiwa::viz {

namespace {
vtkSmartPointer<vtkPolyData> linesOn(vtkPoints* points, vtkCellArray* lines)
{
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetLines(lines);
    return pd;
}
}  // namespace

PathGeometry makePathGeometry(const ToolPath& path, double chordTolerance)
{
    const std::vector<sim::PathPiece> pieces = sim::flattenPath(path, chordTolerance);
    PathGeometry g;
    g.points = vtkSmartPointer<vtkPoints>::New();
    g.points->SetDataTypeToDouble();
    g.points->SetNumberOfPoints(static_cast<vtkIdType>(pieces.size() + 1));
    g.points->SetPoint(0, path.start.x, path.start.y, path.start.z);
    auto feeds = vtkSmartPointer<vtkCellArray>::New();
    auto rapids = vtkSmartPointer<vtkCellArray>::New();
    g.moveOfPiece.reserve(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const auto& p = pieces[k];
        if (k == 0) g.points->SetPoint(0, p.from.x, p.from.y, p.from.z);
        g.points->SetPoint(static_cast<vtkIdType>(k + 1), p.to.x, p.to.y, p.to.z);
        const vtkIdType ids[2] = {static_cast<vtkIdType>(k), static_cast<vtkIdType>(k + 1)};
        (p.rapid ? rapids : feeds)->InsertNextCell(2, ids);
        g.moveOfPiece.push_back(p.move);
    }
    g.feeds = linesOn(g.points, feeds);
    g.rapids = linesOn(g.points, rapids);
    return g;
}

vtkSmartPointer<vtkPolyData> movePieces(const PathGeometry& g, int move)
{
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t k = 0; k < g.moveOfPiece.size(); ++k) {
        if (g.moveOfPiece[k] != move) continue;
        const vtkIdType ids[2] = {static_cast<vtkIdType>(k), static_cast<vtkIdType>(k + 1)};
        lines->InsertNextCell(2, ids);
    }
    return linesOn(g.points, lines);
}

}  // namespace taiwa::viz
