// Conversion of core tool paths into VTK lines.
#include "viz/path_geometry.h"

#include "sim/path_samples.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

#include <functional>

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

namespace {

// Appends the path's pieces: its points after those already in `points`,
// one line cell a piece, and the move of each piece.
void appendPath(const ToolPath& path, double chordTolerance, vtkPoints* points, vtkCellArray* feeds,
                vtkCellArray* rapids, std::vector<int>& moveOfPiece)
{
    const std::vector<sim::PathPiece> pieces = sim::flattenPath(path, chordTolerance);
    const vtkIdType base = points->GetNumberOfPoints();
    points->InsertNextPoint(pieces.empty() ? path.start.x : pieces[0].from.x,
                            pieces.empty() ? path.start.y : pieces[0].from.y,
                            pieces.empty() ? path.start.z : pieces[0].from.z);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const auto& p = pieces[k];
        points->InsertNextPoint(p.to.x, p.to.y, p.to.z);
        const vtkIdType ids[2] = {base + static_cast<vtkIdType>(k), base + static_cast<vtkIdType>(k + 1)};
        (p.rapid ? rapids : feeds)->InsertNextCell(2, ids);
        moveOfPiece.push_back(p.move);
    }
}

}  // namespace

PathGeometry makePathGeometry(const ToolPath& path, double chordTolerance)
{
    PathGeometry g;
    g.points = vtkSmartPointer<vtkPoints>::New();
    g.points->SetDataTypeToDouble();
    auto feeds = vtkSmartPointer<vtkCellArray>::New();
    auto rapids = vtkSmartPointer<vtkCellArray>::New();
    appendPath(path, chordTolerance, g.points, feeds, rapids, g.moveOfPiece);
    g.feeds = linesOn(g.points, feeds);
    g.rapids = linesOn(g.points, rapids);
    return g;
}

MergedPaths makeMergedPaths(const std::vector<const ToolPath*>& paths, double chordTolerance)
{
    MergedPaths m;
    m.points = vtkSmartPointer<vtkPoints>::New();
    m.points->SetDataTypeToDouble();
    auto feeds = vtkSmartPointer<vtkCellArray>::New();
    auto rapids = vtkSmartPointer<vtkCellArray>::New();
    for (const ToolPath* path : paths) {
        const vtkIdType first = m.points->GetNumberOfPoints();
        m.first.push_back(first);
        if (path) {
            appendPath(*path, chordTolerance, m.points, feeds, rapids, m.moveOfPiece);
            m.moveOfPiece.push_back(-1);  // the step's last point starts no piece
        }
        m.count.push_back(m.points->GetNumberOfPoints() - first);
    }
    m.feeds = linesOn(m.points, feeds);
    m.rapids = linesOn(m.points, rapids);
    return m;
}

std::size_t pathKey(const ToolPath& p)
{
    std::size_t h = std::hash<std::size_t>()(p.moves.size());
    const auto mix = [&h](double v) { h ^= std::hash<double>()(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
    mix(p.start.x);
    mix(p.start.y);
    mix(p.start.z);
    if (!p.moves.empty()) {
        for (const Move* m : {&p.moves.front(), &p.moves[p.moves.size() / 2], &p.moves.back()}) {
            mix(m->end.x);
            mix(m->end.y);
            mix(m->end.z);
        }
    }
    return h;
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
