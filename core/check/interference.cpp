// Interference check of input processing: the top outlines of two figures
// of one job must not overlap (touching is allowed). Rounded corners are
// flattened to 1 µm (model/geometry.h), outlines put on Clipper's integer
// grid (model/clipper_scale.h), and a pair whose common area exceeds a
// sliver tolerance is refused.
#include "check/messages.h"
#include "check/unit_checks.h"
#include "model/clipper_scale.h"

#include <algorithm>
#include <array>
#include <limits>
#include <unordered_map>
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
    int unit = 0;  // 0-based
    Quad outline;
    double perimeter = 0.0;
    double minX = 0, maxX = 0, minY = 0, maxY = 0;
    std::array<Point2, 4> normals{};  // of the quad's sides (unit length, or zero)
    bool convex = false;
    // The flattened outline on Clipper's grid, made when a pair needs it
    // (most neighbours are told apart by their quads alone).
    mutable ClipperLib::Path path;
    const ClipperLib::Path& clipperPath() const
    {
        if (path.empty()) path = toClipper(flatten(outline, kChordTolerance));
        return path;
    }
};

Figure figure(const Quad& q, const std::vector<Point2>& polygon, int unit)
{
    Figure f;
    if (!polygon.empty()) {  // any outline (contour units): its polygon, no quad to shortcut with
        f.unit = unit;
        f.outline = q;
        f.path = toClipper(polygon);
        f.minX = f.maxX = polygon[0].x;
        f.minY = f.maxY = polygon[0].y;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            f.perimeter += distance(polygon[i], polygon[(i + 1) % polygon.size()]);
            f.minX = std::min(f.minX, polygon[i].x), f.maxX = std::max(f.maxX, polygon[i].x);
            f.minY = std::min(f.minY, polygon[i].y), f.maxY = std::max(f.maxY, polygon[i].y);
        }
        return f;
    }
    f.unit = unit;
    f.outline = q;
    f.perimeter = 0.0;
    f.minX = f.maxX = q.corners[0].x;
    f.minY = f.maxY = q.corners[0].y;
    for (std::size_t i = 0; i < 4; ++i) {
        f.perimeter += distance(q.corners[i], q.corners[(i + 1) % 4]);
        f.minX = std::min(f.minX, q.corners[i].x);
        f.maxX = std::max(f.maxX, q.corners[i].x);
        f.minY = std::min(f.minY, q.corners[i].y);
        f.maxY = std::max(f.maxY, q.corners[i].y);
        const Point2 side = q.corners[(i + 1) % 4] - q.corners[i];
        if (const double len = length(side); len > 0) f.normals[i] = {-side.y / len, side.x / len};
    }
    f.convex = isStrictlyConvex(q.corners) && q.cornerRadius >= 0;
    return f;
}

// Whether the common area of two outlines is surely within the sliver
// tolerance without asking Clipper. Two outlines that overlap by d along
// some direction have a common area of at most d times half the smaller
// perimeter (a line meets an outline in chords whose lengths add up to at
// most half its perimeter); the sides' normals are the directions tried.
// Convex outlines with rounded corners lie inside their quads, whose four
// corners then stand for them: on Clipper's grid each point moves by at
// most 0.71 cell along a direction, so quads overlapping by at most 0.25
// cell give grid outlines overlapping by less than 1.7 cells, whose common
// area is below the tolerance of one cell times the perimeter. Neighbours
// that touch side to side cost a few products instead of a boolean.
bool surelyApart(const Figure& a, const Figure& b)
{
    const bool quads = a.convex && b.convex;
    const auto span = [&](const Figure& f, Point2 n) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        if (quads) {
            for (const Point2 p : f.outline.corners) {
                const double v = kClipperScale * dot(n, p);
                lo = std::min(lo, v), hi = std::max(hi, v);
            }
        } else {
            for (const auto& p : f.clipperPath()) {
                const double v = n.x * static_cast<double>(p.X) + n.y * static_cast<double>(p.Y);
                lo = std::min(lo, v), hi = std::max(hi, v);
            }
        }
        return std::pair{lo, hi};
    };
    const double allowed = quads ? 0.25 : 1.0;  // grid cells
    for (const Figure* f : {&a, &b})
        for (const Point2 n : f->normals) {
            if (n.x == 0 && n.y == 0) continue;
            const auto [aLo, aHi] = span(a, n);
            const auto [bLo, bHi] = span(b, n);
            if (std::min(aHi, bHi) - std::max(aLo, bLo) <= allowed) return true;
        }
    return false;
}

double commonArea(const Figure& a, const Figure& b)
{
    ClipperLib::Clipper clipper;
    clipper.AddPath(a.clipperPath(), ClipperLib::ptSubject, true);
    clipper.AddPath(b.clipperPath(), ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0.0;
    for (const auto& p : out) area += clipperAreaMm2(p);
    return area;
}

}  // namespace

namespace {

// Figures by grid cell (the cell about the median figure's size): only
// figures in shared cells are compared, so n figures spread over the stock
// cost about n comparisons, not n².
class FigureGrid {
public:
    explicit FigureGrid(const std::vector<Figure>& figures) : figures_(figures)
    {
        if (figures.empty()) return;
        std::vector<double> sides;
        minX_ = figures[0].minX, minY_ = figures[0].minY;
        double maxX = figures[0].maxX, maxY = figures[0].maxY;
        for (const auto& f : figures) {
            sides.push_back(std::max(f.maxX - f.minX, f.maxY - f.minY));
            minX_ = std::min(minX_, f.minX), minY_ = std::min(minY_, f.minY);
            maxX = std::max(maxX, f.maxX), maxY = std::max(maxY, f.maxY);
        }
        std::nth_element(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2), sides.end());
        // At most 1024 cells a side, however small the median figure.
        cell_ = std::max({sides[sides.size() / 2], (maxX - minX_) / 1024, (maxY - minY_) / 1024, 1e-3});
        columns_ = static_cast<long>((maxX - minX_) / cell_) + 1;
    }
    // Earlier figures (by index) whose cells `f` shares, in index order.
    std::vector<int> candidates(const Figure& f) const
    {
        std::vector<int> out;
        forCells(f, [&](long key) {
            if (const auto it = cells_.find(key); it != cells_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }
    void insert(int index)
    {
        forCells(figures_[static_cast<std::size_t>(index)], [&](long key) { cells_[key].push_back(index); });
    }

private:
    template <class F>
    void forCells(const Figure& f, F visit) const
    {
        const auto at = [&](double v, double origin) { return static_cast<long>((v - origin) / cell_); };
        for (long y = at(f.minY, minY_); y <= at(f.maxY, minY_); ++y)
            for (long x = at(f.minX, minX_); x <= at(f.maxX, minX_); ++x) visit(y * columns_ + x);
    }
    const std::vector<Figure>& figures_;
    double minX_ = 0, minY_ = 0, cell_ = 1;
    long columns_ = 1;
    std::unordered_map<long, std::vector<int>> cells_;
};

}  // namespace

Diagnostics interferences(std::vector<UnitFigure> units, LengthUnit shownUnit)
{
    // Figures in unit order: each is compared with the earlier ones it may
    // touch, and the overlaps come out in the order of the later unit.
    std::sort(units.begin(), units.end(), [](const UnitFigure& a, const UnitFigure& b) { return a.unit < b.unit; });
    std::vector<Figure> figures;
    figures.reserve(units.size());
    for (const auto& u : units) figures.push_back(figure(u.outline, u.polygon, u.unit));
    FigureGrid grid(figures);
    Diagnostics out;
    for (std::size_t j = 0; j < figures.size() && out.size() < kMaxDiagnostics; ++j) {
        const Figure& b = figures[j];
        for (const int i : grid.candidates(b)) {
            const Figure& a = figures[static_cast<std::size_t>(i)];
            if (b.minX > a.maxX || b.maxX < a.minX || b.minY > a.maxY || b.maxY < a.minY) continue;
            if (surelyApart(a, b)) continue;  // apart, or touching
            const double area = commonArea(a, b);
            const double tolerance = kAreaTolerance + kSliverWidth * std::min(a.perimeter, b.perimeter);
            if (area <= tolerance) continue;
            out.push_back({Severity::Error, b.unit + 1, units[j].module, units[j].field,
                           msg::overlap(b.unit + 1, a.unit + 1, area, shownUnit)});
            if (out.size() == kMaxDiagnostics) break;
        }
        grid.insert(static_cast<int>(j));
    }
    // More than a list can show: the rest is not looked for (3,000 stacked
    // figures once took 171 s and 2.2 GB to list every pair).
    if (out.size() == kMaxDiagnostics)
        out.push_back({Severity::Error, std::nullopt, "", "", "further overlaps were not looked for: correct these first"});
    return out;
}

}  // namespace taiwa::check
