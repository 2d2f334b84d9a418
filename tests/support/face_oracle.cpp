// Geometry oracle of module FACE: the faced part and the face, from their
// definitions (see face_oracle.h).
#include "support/face_oracle.h"

#include "modules/face/face.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::test {

double faceGouge(const FaceUnit& face, const Tool&, Point3 tip)
{
    if (tip.z >= 0.0) return -std::numeric_limits<double>::infinity();
    return -tip.z - face.depth;  // a flat-bottomed tool: its tip is its lowest point
}

double faceDepth(const FaceUnit& face) { return face.depth; }

double faceWallDistance(const FaceUnit&, Point3) { return -std::numeric_limits<double>::infinity(); }

double distanceToStock(const Stock& s, Point2 p)
{
    const double dx = std::max({s.x - p.x, 0.0, p.x - (s.x + s.width)});
    const double dy = std::max({s.y - p.y, 0.0, p.y - (s.y + s.length)});
    return std::hypot(dx, dy);
}

std::pair<Point2, Point2> faceBox(const Stock& s, double margin)
{
    return {{s.x - margin, s.y - margin}, {s.x + s.width + margin, s.y + s.length + margin}};
}

std::vector<Point2> faceGrid(const Stock& s, double margin, double spacing)
{
    const auto [lo, hi] = faceBox(s, margin);
    const int nx = static_cast<int>(std::ceil((hi.x - lo.x) / spacing)), ny = static_cast<int>(std::ceil((hi.y - lo.y) / spacing));
    std::vector<Point2> grid;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)  // the last row and column on the edges exactly
            grid.push_back({lo.x + (hi.x - lo.x) * i / nx, lo.y + (hi.y - lo.y) * j / ny});
    return grid;
}

double distanceToSegment(Point2 p, Point2 a, Point2 b)
{
    const Point2 ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * ab);
}

}  // namespace taiwa::test
