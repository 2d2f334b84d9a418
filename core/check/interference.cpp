// Interference check of input processing: the top outlines of two figures
// of one job must not overlap (touching is allowed). Rounded corners are
// flattened to 1 µm (model/geometry.h), outlines put on Clipper's integer
// grid (model/clipper_scale.h), and a pair whose common area exceeds a
// sliver tolerance is refused.
#include "check/messages.h"
#include "check/unit_checks.h"
#include "model/clipper_scale.h"

#include <algorithm>
#include <cmath>

namespace taiwa::check {

namespace {

constexpr double kChordTolerance = 1e-3;  // mm between an arc and its chords
// Rounding to the integer grid (model/clipper_scale.h) can make two touching
// edges overlap by half a grid cell along their length: allow that sliver (a
// whole cell wide), plus 1e-6 mm^2.
constexpr double kAreaTolerance = 1e-6;  // mm^2
constexpr double kSliverWidth = 1.0 / kClipperScale;  // mm

struct Figure {
    int unit;  // 0-based
    ClipperLib::Path path;
    double perimeter;
    double minX, maxX, minY, maxY;
};

Figure figure(const Quad& q, int unit)
{
    Figure f{unit, toClipper(flatten(q, kChordTolerance)), 0.0, q.corners[0].x, q.corners[0].x, q.corners[0].y,
             q.corners[0].y};
    for (std::size_t i = 0; i < 4; ++i) {
        f.perimeter += distance(q.corners[i], q.corners[(i + 1) % 4]);
        f.minX = std::min(f.minX, q.corners[i].x);
        f.maxX = std::max(f.maxX, q.corners[i].x);
        f.minY = std::min(f.minY, q.corners[i].y);
        f.maxY = std::max(f.maxY, q.corners[i].y);
    }
    return f;
}

double commonArea(const Figure& a, const Figure& b)
{
    ClipperLib::Clipper clipper;
    clipper.AddPath(a.path, ClipperLib::ptSubject, true);
    clipper.AddPath(b.path, ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0.0;
    for (const auto& p : out) area += clipperAreaMm2(p);
    return area;
}

}  // namespace

Diagnostics interferences(std::vector<UnitFigure> units, LengthUnit shownUnit)
{
    std::vector<Figure> figures;
    for (const auto& u : units) figures.push_back(figure(u.outline, u.unit));
    // Sweep along X: only figures whose boxes meet can overlap.
    std::sort(figures.begin(), figures.end(), [](const Figure& a, const Figure& b) { return a.minX < b.minX; });
    std::vector<std::pair<int, int>> pairs;  // (earlier unit, later unit), 0-based
    std::vector<double> areas;
    for (std::size_t i = 0; i < figures.size(); ++i) {
        const Figure& a = figures[i];
        for (std::size_t j = i + 1; j < figures.size() && figures[j].minX <= a.maxX; ++j) {
            const Figure& b = figures[j];
            if (b.minY > a.maxY || b.maxY < a.minY) continue;
            const double area = commonArea(a, b);
            const double tolerance = kAreaTolerance + kSliverWidth * std::min(a.perimeter, b.perimeter);
            if (area <= tolerance) continue;
            pairs.emplace_back(std::min(a.unit, b.unit), std::max(a.unit, b.unit));
            areas.push_back(area);
        }
    }
    std::vector<std::size_t> order(pairs.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return pairs[x] < pairs[y]; });
    Diagnostics out;
    for (const std::size_t k : order) {
        const auto [first, second] = pairs[k];
        const auto later = std::find_if(units.begin(), units.end(), [&](const UnitFigure& f) { return f.unit == second; });
        out.push_back({Severity::Error, second + 1, later->module, later->field,
                       msg::overlap(second + 1, first + 1, areas[k], shownUnit)});
    }
    return out;
}

}  // namespace taiwa::check
