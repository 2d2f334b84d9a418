// Decimation of line geometry for the paths drawn while the camera moves:
// one pass over the points of each run (a strip test, Reumann-Witkam with
// forward progress), linear in the number of points. VTK's own
// vtkStripper + vtkDecimatePolylineFilter did the same for a
// million-segment path in 0.9 s (a priority queue over every point); this
// takes a few tens of milliseconds (bench_viz_rotate's BM_BuildLod).
#include "viz/path_lod.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPoints.h>

#include <array>
#include <cmath>
#include <vector>

namespace taiwa::viz {

namespace {

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Thins one run of point ids into `out` (its first point is already there
// unless `first`): points are dropped while they stay within `tol` of the
// line from the last kept point along the run's direction (taken from the
// first point at least `tol` away) and do not go back along it by more
// than `tol`; the point before the first that leaves is kept and starts
// the next strip.
void thinRun(vtkPoints* points, const std::vector<vtkIdType>& run, double tol, std::vector<vtkIdType>& out)
{
    out.push_back(run.front());
    if (run.size() < 3 || tol <= 0) {
        out.insert(out.end(), run.begin() + 1, run.end());
        return;
    }
    Vec anchor{}, dir{};
    points->GetPoint(run.front(), anchor.data());
    bool haveDir = false;
    double tmax = 0;
    std::size_t last = 0;  // index in run of the last point passed (the next to keep)
    for (std::size_t i = 1; i + 1 < run.size(); ++i) {
        Vec p{};
        points->GetPoint(run[i], p.data());
        const Vec v{p[0] - anchor[0], p[1] - anchor[1], p[2] - anchor[2]};
        if (!haveDir) {
            const double len = std::sqrt(dot(v, v));
            if (len >= tol) {
                dir = {v[0] / len, v[1] / len, v[2] / len};
                haveDir = true;
                tmax = len;
            }
            last = i;
            continue;
        }
        const double t = dot(v, dir);
        const Vec perp{v[0] - t * dir[0], v[1] - t * dir[1], v[2] - t * dir[2]};
        if (dot(perp, perp) <= tol * tol && t >= tmax - tol) {
            tmax = std::max(tmax, t);
            last = i;
            continue;
        }
        // p leaves the strip: the last point inside is kept and anchors the next.
        out.push_back(run[last]);
        points->GetPoint(run[last], anchor.data());
        haveDir = false;
        --i;  // p again, against the new anchor (the anchor is before it: progress is made)
    }
    out.push_back(run.back());
}

}  // namespace

std::size_t lineSegmentCount(vtkPolyData* lines)
{
    if (!lines || !lines->GetLines()) return 0;
    vtkCellArray* cells = lines->GetLines();
    const vtkIdType ids = cells->GetNumberOfConnectivityIds(), n = cells->GetNumberOfCells();
    return ids > n ? static_cast<std::size_t>(ids - n) : 0;
}

vtkSmartPointer<vtkPolyData> decimateLines(vtkPolyData* lines, double tolerance)
{
    auto outPoints = vtkSmartPointer<vtkPoints>::New();
    auto outLines = vtkSmartPointer<vtkCellArray>::New();
    auto result = vtkSmartPointer<vtkPolyData>::New();
    result->SetPoints(outPoints);
    result->SetLines(outLines);
    if (!lines || !lines->GetPoints() || !lines->GetLines()) return result;
    vtkPoints* points = lines->GetPoints();
    outPoints->SetDataType(points->GetDataType());  // kept points exactly as they were

    std::vector<vtkIdType> run, kept;
    std::vector<vtkIdType> newId(static_cast<std::size_t>(points->GetNumberOfPoints()), -1);
    const auto flush = [&] {
        if (run.size() >= 2) {
            kept.clear();
            thinRun(points, run, tolerance, kept);
            outLines->InsertNextCell(static_cast<int>(kept.size()));
            for (vtkIdType id : kept) {
                vtkIdType& to = newId[static_cast<std::size_t>(id)];
                if (to < 0) to = outPoints->InsertNextPoint(points->GetPoint(id));
                outLines->InsertCellPoint(to);
            }
        }
        run.clear();
    };
    auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
        vtkIdType n = 0;
        const vtkIdType* ids = nullptr;
        it->GetCurrentCell(n, ids);
        if (n < 2) continue;
        if (run.empty() || run.back() != ids[0]) {
            flush();
            run.push_back(ids[0]);
        }
        run.insert(run.end(), ids + 1, ids + n);
    }
    flush();
    return result;
}

vtkSmartPointer<vtkPolyData> decimateLinesWithin(vtkPolyData* lines, double tolerance, std::size_t maxSegments)
{
    vtkSmartPointer<vtkPolyData> result = decimateLines(lines, tolerance);
    for (int k = 0; k < 10 && lineSegmentCount(result) > maxSegments && tolerance > 0; ++k) {
        tolerance *= 2;
        result = decimateLines(lines, tolerance);
    }
    return result;
}

}  // namespace taiwa::viz
